#include "point_cloud.hpp"

#include <string>

#include "error.hpp"

namespace dbs {

PointCloud::PointCloud(std::vector<Vec3> points) : points_(std::move(points)) {
  if (points_.empty()) fail(ErrorCode::Empty, "point cloud has no points");
  // The cloud index numbers points with 32 bits; refused here, at the input check, rather
  // than in the middle of a run.
  if (points_.size() > kMaxCloudPoints) fail(ErrorCode::OutOfRange, "point cloud has " + std::to_string(points_.size()) + " points, more than the " + std::to_string(kMaxCloudPoints) + " libdbs can index");
  for (std::size_t i = 0; i < points_.size(); ++i) {
    if (!is_finite(points_[i])) fail(ErrorCode::NonFinite, "point " + std::to_string(i) + " has a non-finite coordinate");
    bounds_.extend(points_[i]);
  }
}

}  // namespace dbs
