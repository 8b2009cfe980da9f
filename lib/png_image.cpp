#include "png_image.hpp"

#include <png.h>

#include <cstdio>
#include <cstring>
#include <string>
#include <utility>

#include "error.hpp"

namespace dbs {

RgbImage::RgbImage(int width, int height, Rgb fill) : width_(width), height_(height) {
  if (width < 1 || height < 1) fail(ErrorCode::InvalidArgument, "image size " + std::to_string(width) + " x " + std::to_string(height) + " is empty");
  bytes_.resize(static_cast<std::size_t>(width) * height * 3);
  for (std::size_t i = 0; i < bytes_.size(); i += 3) std::memcpy(&bytes_[i], fill.data(), 3);
}

RgbImage RgbImage::from_bytes(int width, int height, std::vector<std::uint8_t> bytes) {
  RgbImage image(width, height);
  if (bytes.size() != image.bytes_.size()) fail(ErrorCode::InvalidArgument, "image of " + std::to_string(width) + " x " + std::to_string(height) + " pixels given " + std::to_string(bytes.size()) + " bytes");
  image.bytes_ = std::move(bytes);
  return image;
}

Rgb RgbImage::at(int x, int y) const {
  const std::uint8_t* p = &bytes_[(static_cast<std::size_t>(y) * width_ + x) * 3];
  return {p[0], p[1], p[2]};
}

void RgbImage::set(int x, int y, Rgb colour) { std::memcpy(&bytes_[(static_cast<std::size_t>(y) * width_ + x) * 3], colour.data(), 3); }

void RgbImage::plot(int x, int y, Rgb colour) {
  if (x >= 0 && y >= 0 && x < width_ && y < height_) set(x, y, colour);
}

void write_png(const std::string& path, const RgbImage& image) {
  png_image png;
  std::memset(&png, 0, sizeof png);
  png.version = PNG_IMAGE_VERSION;
  png.width = static_cast<png_uint_32>(image.width());
  png.height = static_cast<png_uint_32>(image.height());
  png.format = PNG_FORMAT_RGB;
  if (!png_image_write_to_file(&png, path.c_str(), 0, image.bytes().data(), 0, nullptr)) {
    std::string message = png.message;
    png_image_free(&png);
    fail(ErrorCode::Io, "cannot write PNG file '" + path + "': " + message);
  }
}

RgbImage read_png(const std::string& path) {
  if (std::FILE* probe = std::fopen(path.c_str(), "rb")) {
    std::fclose(probe);
  } else {
    fail(ErrorCode::Io, "cannot open PNG file '" + path + "'");
  }
  png_image png;
  std::memset(&png, 0, sizeof png);
  png.version = PNG_IMAGE_VERSION;
  if (!png_image_begin_read_from_file(&png, path.c_str())) {
    std::string message = png.message;
    png_image_free(&png);
    fail(ErrorCode::Parse, "'" + path + "' is not a readable PNG: " + message);
  }
  png.format = PNG_FORMAT_RGB;
  std::vector<std::uint8_t> bytes(PNG_IMAGE_SIZE(png));
  png_color white{255, 255, 255};
  if (!png_image_finish_read(&png, &white, bytes.data(), 0, nullptr)) {
    std::string message = png.message;
    png_image_free(&png);
    fail(ErrorCode::Parse, "'" + path + "' is not a readable PNG: " + message);
  }
  return RgbImage::from_bytes(static_cast<int>(png.width), static_cast<int>(png.height), std::move(bytes));
}

}  // namespace dbs
