// An 8-bit RGB picture in memory (its PNG encoding is report/png_file).
#pragma once
#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace dbs {

using Rgb = std::array<std::uint8_t, 3>;

class RgbImage {
 public:
  /// width, height >= 1, every pixel `fill`.
  RgbImage(int width, int height, Rgb fill = {255, 255, 255});
  /// Takes rows top to bottom, 3 bytes per pixel (width * height * 3 bytes).
  static RgbImage from_bytes(int width, int height, std::vector<std::uint8_t> bytes);

  int width() const { return width_; }
  int height() const { return height_; }
  /// Pixel (x, y), y = 0 the top row. Coordinates must lie inside the image.
  Rgb at(int x, int y) const;
  void set(int x, int y, Rgb colour);
  /// Sets the pixel when (x, y) lies inside the image, ignores it otherwise.
  void plot(int x, int y, Rgb colour);
  /// Rows top to bottom, 3 bytes per pixel.
  const std::vector<std::uint8_t>& bytes() const { return bytes_; }

 private:
  int width_, height_;
  std::vector<std::uint8_t> bytes_;
};

}  // namespace dbs
