#include "png_file.hpp"

#include <png.h>

#include <cstdio>
#include <cstring>
#include <string>
#include <utility>
#include <vector>

#include "error.hpp"

namespace dbs {

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
