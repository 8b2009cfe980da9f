#include "outline_corners.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "error.hpp"

namespace dbs {

namespace {

/// Arc length from loop point 0 to each point (the closing edge not included).
std::vector<double> arc_lengths(const std::vector<Vec3>& p) {
  std::vector<double> at(p.size(), 0.0);
  for (std::size_t i = 1; i < p.size(); ++i) at[i] = at[i - 1] + (p[i] - p[i - 1]).norm();
  return at;
}

/// Cyclic distance along the loop between arc lengths a and b.
double cyclic(double a, double b, double perimeter) {
  const double d = std::abs(a - b);
  return std::min(d, perimeter - d);
}

/// The loop point about `length` along the loop from point i (backwards when negative).
std::size_t walk(const std::vector<Vec3>& p, std::size_t i, double length) {
  const std::size_t m = p.size();
  double s = 0.0;
  std::size_t j = i;
  for (std::size_t step = 0; step + 1 < m && s < std::abs(length); ++step) {
    const std::size_t next = length > 0 ? (j + 1) % m : (j + m - 1) % m;
    s += (p[next] - p[j]).norm();
    j = next;
  }
  return j;
}

std::vector<double> turning(const OutlineLoop& loop) {
  const std::vector<Vec3>& p = loop.points;
  const std::size_t m = p.size();
  const double window = kCornerWindow * loop.perimeter;
  std::vector<double> t(m, 0.0);
  double total = 0.0;
  for (std::size_t i = 0; i < m; ++i) {
    const Vec3& n = loop.normals[i];
    Vec3 before = p[i] - p[walk(p, i, -window)], after = p[walk(p, i, window)] - p[i];
    before -= before.dot(n) * n;
    after -= after.dot(n) * n;
    t[i] = std::atan2(before.cross(after).dot(n), before.dot(after));
    total += t[i];
  }
  if (total < 0.0)
    for (double& x : t) x = -x;
  return t;
}

/// The loop points nearest to the corners of the minimum-area rectangle around the loop in
/// the plane of its two principal axes.
std::array<std::size_t, 4> rectangle_corners(const std::vector<Vec3>& p) {
  const PlaneFrame frame = principal_plane(p);
  std::vector<Vec2> q;
  for (const Vec3& x : p) q.push_back(frame.project(x));
  // Convex hull (monotone chain), then the rectangle of each hull edge's direction.
  std::vector<std::size_t> order(q.size());
  for (std::size_t i = 0; i < q.size(); ++i) order[i] = i;
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return q[a].x() < q[b].x() || (q[a].x() == q[b].x() && (q[a].y() < q[b].y() || (q[a].y() == q[b].y() && a < b))); });
  auto cross = [&](const Vec2& o, const Vec2& a, const Vec2& b) { return (a - o).x() * (b - o).y() - (a - o).y() * (b - o).x(); };
  std::vector<Vec2> hull;
  for (int pass = 0; pass < 2; ++pass) {
    const std::size_t start = hull.size();
    for (std::size_t k = 0; k < order.size(); ++k) {
      const Vec2& x = q[order[pass == 0 ? k : order.size() - 1 - k]];
      while (hull.size() >= start + 2 && cross(hull[hull.size() - 2], hull.back(), x) <= 0.0) hull.pop_back();
      hull.push_back(x);
    }
    hull.pop_back();
  }
  double best_area = std::numeric_limits<double>::infinity();
  std::array<Vec2, 4> best{};
  for (std::size_t k = 0; k < hull.size(); ++k) {
    Vec2 u = hull[(k + 1) % hull.size()] - hull[k];
    if (!(u.norm() > 0.0)) continue;
    u.normalize();
    const Vec2 v(-u.y(), u.x());
    double lo_u = std::numeric_limits<double>::infinity(), hi_u = -lo_u, lo_v = lo_u, hi_v = -lo_u;
    for (const Vec2& x : hull) {
      lo_u = std::min(lo_u, x.dot(u));
      hi_u = std::max(hi_u, x.dot(u));
      lo_v = std::min(lo_v, x.dot(v));
      hi_v = std::max(hi_v, x.dot(v));
    }
    const double area = (hi_u - lo_u) * (hi_v - lo_v);
    if (area < best_area) {
      best_area = area;
      best = {lo_u * u + lo_v * v, hi_u * u + lo_v * v, hi_u * u + hi_v * v, lo_u * u + hi_v * v};
    }
  }
  std::array<std::size_t, 4> corners{};
  for (int c = 0; c < 4; ++c) {
    double nearest = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < q.size(); ++i) {
      const double d = (q[i] - best[static_cast<std::size_t>(c)]).squaredNorm();
      if (d < nearest) {
        nearest = d;
        corners[static_cast<std::size_t>(c)] = i;
      }
    }
  }
  return corners;
}

}  // namespace

std::array<std::size_t, 4> outline_corners(const OutlineLoop& loop) {
  const std::vector<Vec3>& p = loop.points;
  const std::size_t m = p.size();
  if (m < kMinLoopPoints || loop.normals.size() != m)
    fail(ErrorCode::Degenerate, "outline corners: the loop has " + std::to_string(m) + " points; at least " + std::to_string(kMinLoopPoints) + " are needed");
  const std::vector<double> t = turning(loop), at = arc_lengths(p);
  const double separation = kCornerSeparation * loop.perimeter;
  std::vector<std::size_t> order(m);
  for (std::size_t i = 0; i < m; ++i) order[i] = i;
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return t[a] > t[b] || (t[a] == t[b] && a < b); });
  std::vector<std::size_t> chosen;
  for (std::size_t i : order) {
    if (chosen.size() == 4) break;
    if (std::all_of(chosen.begin(), chosen.end(), [&](std::size_t c) { return cyclic(at[c], at[i], loop.perimeter) >= separation; })) chosen.push_back(i);
  }
  std::array<std::size_t, 4> corners{};
  if (chosen.size() == 4 && t[chosen[3]] >= kRoundTurning) {
    std::copy(chosen.begin(), chosen.end(), corners.begin());
  } else {
    corners = rectangle_corners(p);
  }
  std::sort(corners.begin(), corners.end());
  for (int c = 1; c < 4; ++c)
    if (corners[static_cast<std::size_t>(c)] == corners[static_cast<std::size_t>(c - 1)]) fail(ErrorCode::Degenerate, "outline corners: the outline has no four distinct corners");
  return corners;
}

}  // namespace dbs
