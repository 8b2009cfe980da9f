// An immutable set of 3D points with its bounding box.
#pragma once
#include <cstddef>
#include <vector>

#include "geometry.hpp"

namespace dbs {

/// Most points of a cloud (the cloud index numbers them with 32 bits).
constexpr std::size_t kMaxCloudPoints = 4294967295u;

class PointCloud {
 public:
  /// Takes the points; throws Error(Empty) for none, Error(OutOfRange) for more than
  /// kMaxCloudPoints, and Error(NonFinite) naming the first non-finite point's index.
  explicit PointCloud(std::vector<Vec3> points);

  const std::vector<Vec3>& points() const { return points_; }
  std::size_t size() const { return points_.size(); }
  const Box3& bounds() const { return bounds_; }

 private:
  std::vector<Vec3> points_;
  Box3 bounds_;
};

}  // namespace dbs
