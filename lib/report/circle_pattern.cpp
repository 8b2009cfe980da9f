#include "circle_pattern.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "error.hpp"
#include "number_text.hpp"

namespace dbs {
namespace {

constexpr double kDiskRadius = 0.3;  // in periods

}  // namespace

CirclePattern::CirclePattern(double scale_u, double scale_v, int across) : scale_u_(scale_u), scale_v_(scale_v) {
  if (!(scale_u > 0.0) || !(scale_v > 0.0) || !std::isfinite(scale_u) || !std::isfinite(scale_v)) fail(ErrorCode::InvalidArgument, "circle pattern: domain scales " + significant_text(scale_u, 6) + ", " + significant_text(scale_v, 6) + " must be positive and finite");
  if (across < 1) fail(ErrorCode::OutOfRange, "circle pattern: " + std::to_string(across) + " disks across (at least 1)");
  period_ = std::max(scale_u, scale_v) / across;
}

bool CirclePattern::black(double u, double v) const {
  double x = u * scale_u_ / period_, y = v * scale_v_ / period_;
  double dx = x - std::floor(x) - 0.5, dy = y - std::floor(y) - 0.5;
  return dx * dx + dy * dy < kDiskRadius * kDiskRadius;
}

void CirclePattern::disk_centre(int i, int j, double& out_u, double& out_v) const {
  out_u = (i + 0.5) * period_ / scale_u_;
  out_v = (j + 0.5) * period_ / scale_v_;
}

RgbImage CirclePattern::texture(int long_side) const {
  if (long_side < 1) fail(ErrorCode::OutOfRange, "circle pattern: texture size " + std::to_string(long_side) + " (at least 1)");
  double longest = std::max(scale_u_, scale_v_);
  int width = std::max(1, static_cast<int>(std::lround(long_side * scale_u_ / longest)));
  int height = std::max(1, static_cast<int>(std::lround(long_side * scale_v_ / longest)));
  RgbImage image(width, height);
  for (int y = 0; y < height; ++y) {
    double v = 1.0 - (y + 0.5) / height;
    for (int x = 0; x < width; ++x) {
      if (black((x + 0.5) / width, v)) image.set(x, y, {0, 0, 0});
    }
  }
  return image;
}

}  // namespace dbs
