#include "suspicious_triangles.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "error.hpp"
#include "parallel.hpp"

namespace dbs {

std::vector<double> local_spacing(const CloudIndex& index, int threads) {
  const std::vector<Vec3>& points = index.points();
  std::vector<double> spacing(points.size(), 0.0);
  // Ask for a few more neighbours than needed: the query point itself and duplicates of it
  // come back at distance zero and do not count.
  const std::size_t ask = std::min(kSpacingNeighbour + 4, index.size());
  parallel_for(points.size(), resolve_threads(threads), [&](std::size_t i) {
    std::vector<std::size_t> idx;
    std::vector<double> d2;
    index.knn(points[i], ask, idx, d2);
    std::size_t counted = 0;
    for (double d : d2) {
      if (d <= 0.0) continue;
      spacing[i] = std::sqrt(d);
      if (++counted == kSpacingNeighbour) break;
    }
  });
  return spacing;
}

std::vector<std::size_t> find_suspicious_triangles(const std::vector<Vec3>& points, const std::vector<Triangle>& triangles, const std::vector<double>& spacing, double factor) {
  if (spacing.size() != points.size()) fail(ErrorCode::InvalidArgument, "find_suspicious_triangles: " + std::to_string(spacing.size()) + " spacings for " + std::to_string(points.size()) + " points");
  std::vector<std::size_t> suspicious;
  for (std::size_t t = 0; t < triangles.size(); ++t) {
    const Triangle& tri = triangles[t];
    for (int k = 0; k < 3; ++k) {
      if (tri[k] < 0 || static_cast<std::size_t>(tri[k]) >= points.size()) fail(ErrorCode::OutOfRange, "triangle " + std::to_string(t) + " has vertex index " + std::to_string(tri[k]) + " outside the " + std::to_string(points.size()) + " points");
    }
    for (int k = 0; k < 3; ++k) {
      std::int32_t a = tri[k], b = tri[(k + 1) % 3];
      double limit = factor * std::max(spacing[a], spacing[b]);
      if ((points[a] - points[b]).norm() > limit) {
        suspicious.push_back(t);
        break;
      }
    }
  }
  return suspicious;
}

}  // namespace dbs
