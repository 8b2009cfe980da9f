#include "rgb_image.hpp"

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

}  // namespace dbs
