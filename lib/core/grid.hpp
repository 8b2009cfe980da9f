// A grid of 3D points p(i,j), i along u (0..nu-1), j along v (0..nv-1), stored u fastest.
#pragma once
#include <vector>

#include "geometry.hpp"

namespace dbs {

struct Grid {
  int nu = 0;
  int nv = 0;
  std::vector<Vec3> points;  // index j*nu + i

  Grid() = default;
  Grid(int nu_, int nv_) : nu(nu_), nv(nv_), points(static_cast<std::size_t>(nu_) * nv_, Vec3::Zero()) {}
  Vec3& operator()(int i, int j) { return points[static_cast<std::size_t>(j) * nu + i]; }
  const Vec3& operator()(int i, int j) const { return points[static_cast<std::size_t>(j) * nu + i]; }
  /// Parameter of grid column i (uniform): i / (nu-1).
  double u(int i) const { return static_cast<double>(i) / (nu - 1); }
  double v(int j) const { return static_cast<double>(j) / (nv - 1); }
};

}  // namespace dbs
