// Basic geometric types shared by the core.
#pragma once
#include <Eigen/Core>
#include <cmath>
#include <limits>
#include <vector>

namespace dbs {

using Vec3 = Eigen::Vector3d;
using Vec2 = Eigen::Vector2d;

/// Axis-aligned bounding box; empty until a point is added.
struct Box3 {
  Vec3 min = Vec3::Constant(std::numeric_limits<double>::infinity());
  Vec3 max = Vec3::Constant(-std::numeric_limits<double>::infinity());

  void extend(const Vec3& p) {
    min = min.cwiseMin(p);
    max = max.cwiseMax(p);
  }
  bool empty() const { return !(min.x() <= max.x()); }
  double diagonal() const { return empty() ? 0.0 : (max - min).norm(); }
};

inline Box3 bounds_of(const std::vector<Vec3>& pts) {
  Box3 b;
  for (const Vec3& p : pts) b.extend(p);
  return b;
}

inline bool is_finite(const Vec3& p) { return std::isfinite(p.x()) && std::isfinite(p.y()) && std::isfinite(p.z()); }

/// Rectangle [u0,u1] x [v0,v1] of the global parameter domain.
struct Rect {
  double u0 = 0, v0 = 0, u1 = 1, v1 = 1;
  /// Global parameters of the local (s,t) in [0,1]^2.
  Vec2 to_global(double s, double t) const { return {u0 + s * (u1 - u0), v0 + t * (v1 - v0)}; }
  /// Local parameters of the global (u,v).
  Vec2 to_local(double u, double v) const { return {(u - u0) / (u1 - u0), (v - v0) / (v1 - v0)}; }
  bool contains(double u, double v) const { return u >= u0 && u <= u1 && v >= v0 && v <= v1; }
};

}  // namespace dbs
