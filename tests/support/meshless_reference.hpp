// A meshless reference parameterization for the fold-free work (issue 10): Floater-Reimers
// style, the yardstick the recursive method's folds are compared with.
//
// The cloud points nearest to the boundary sides are fixed at the arc-length position of their
// closest boundary point on the square's sides; every other point is the convex combination of
// its k nearest neighbours in 3D with inverse-distance weights; one sparse solve (Eigen SparseLU)
// gives all (u,v). Needs Eigen (std-only callers use fold_shapes.hpp alone).
#pragma once

#include <cstddef>
#include <vector>

#include "fold_shapes.hpp"

namespace dbs_folds {

struct MeshlessReference {
  std::vector<double> uv;       // 2 per point
  std::vector<char> fixed;      // 1 for the points fixed on the boundary
  std::size_t fixed_count = 0;
  double seconds = 0.0;         // wall-clock time of the whole computation
};

/// `xyz` 3 per point; the sides 3 doubles per polyline point, oriented as in dbs.h (bottom and
/// top in increasing u, left and right in increasing v). Throws std::runtime_error when the
/// system is singular (a neighbourhood cluster with no path to the boundary) and
/// std::invalid_argument for fewer than k + 1 points or a side with fewer than 2 points.
MeshlessReference meshless_reference(const std::vector<double>& xyz, const std::vector<double>& bottom, const std::vector<double>& right,
                                     const std::vector<double>& top, const std::vector<double>& left, int k = 12);

/// The same on a shape's (possibly noisy) points and boundary.
MeshlessReference meshless_reference(const FoldShape& shape, int k = 12);

}  // namespace dbs_folds
