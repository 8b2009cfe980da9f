// Analytic surfaces with known parameterizations, sampled into clouds and boundaries for
// the core tests. Header-only; deterministic (fixed-seed std::mt19937_64).
#pragma once
#include <cmath>
#include <functional>
#include <random>
#include <vector>

#include <Eigen/Geometry>

#include "boundary.hpp"
#include "geometry.hpp"
#include "point_cloud.hpp"

namespace dbs_test {

using dbs::Vec3;
using Surface = std::function<Vec3(double, double)>;

/// Polyline of n points along the surface's side from (a0,b0) to (a1,b1) in its parameters.
inline std::vector<Vec3> side_of(const Surface& s, double a0, double b0, double a1, double b1, int n) {
  std::vector<Vec3> pts;
  for (int i = 0; i < n; ++i) {
    const double t = static_cast<double>(i) / (n - 1);
    pts.push_back(s(a0 + t * (a1 - a0), b0 + t * (b1 - b0)));
  }
  return pts;
}

/// The boundary of s over [0,1]^2, each side sampled with n points.
inline dbs::Boundary boundary_of(const Surface& s, int n) {
  return dbs::Boundary(side_of(s, 0, 0, 1, 0, n), side_of(s, 1, 0, 1, 1, n), side_of(s, 0, 1, 1, 1, n), side_of(s, 0, 0, 0, 1, n));
}

/// `count` random points of s over [0,1]^2; out_ab receives their parameters if not null.
inline std::vector<Vec3> random_points(const Surface& s, std::size_t count, unsigned seed, std::vector<dbs::Vec2>* out_ab = nullptr) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<Vec3> pts;
  for (std::size_t i = 0; i < count; ++i) {
    const double a = unit(rng), b = unit(rng);
    pts.push_back(s(a, b));
    if (out_ab) out_ab->emplace_back(a, b);
  }
  return pts;
}

inline Surface height_field() {
  return [](double x, double y) { return Vec3(x, y, 0.2 * std::sin(M_PI * x) * std::sin(M_PI * y)); };
}

/// The height field with a narrow bump near (0.75, 0.7) that one patch cannot follow.
inline Surface bumpy_field() {
  return [](double x, double y) {
    const double r2 = (x - 0.75) * (x - 0.75) + (y - 0.7) * (y - 0.7);
    return Vec3(x, y, 0.2 * std::sin(M_PI * x) * std::sin(M_PI * y) + 0.12 * std::exp(-r2 / 0.006));
  };
}

/// The bumpy field plus ripples of wavelength 0.25 that an 11 x 11 grid cannot follow, so the
/// root must subdivide everywhere.
inline Surface rippled_bumpy_field() {
  return [](double x, double y) { return Vec3(bumpy_field()(x, y) + Vec3(0, 0, 0.03 * std::sin(8 * M_PI * x) * std::sin(8 * M_PI * y))); };
}

/// bumpy_field with ripples of 6 periods a side (amplitude 0.03): beyond what one patch's
/// largest grid reaches even fitted to its points (rippled_bumpy_field's 4 periods are reached
/// by the fit to the target, fit_to_target.hpp), so the quadtree is needed.
inline Surface sharply_rippled_field() {
  return [](double x, double y) { return Vec3(bumpy_field()(x, y) + Vec3(0, 0, 0.03 * std::sin(12 * M_PI * x) * std::sin(12 * M_PI * y))); };
}

/// A rigid motion followed by a uniform scale.
inline Vec3 move_and_scale(const Vec3& p, double scale) {
  const Eigen::Matrix3d r = (Eigen::AngleAxisd(0.7, Vec3(1, 2, 3).normalized())).toRotationMatrix();
  return scale * (r * p + Vec3(5.0, -3.0, 2.0));
}

}  // namespace dbs_test
