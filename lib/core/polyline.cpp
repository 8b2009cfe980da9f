#include "polyline.hpp"

#include <algorithm>
#include <limits>
#include <string>

#include "error.hpp"

namespace dbs {

namespace {

// Splits closer than this (in arc-length fraction) to an existing vertex reuse that vertex
// instead of creating a segment a few ulps long.
constexpr double kVertexSnap = 1e-14;

double clamp_unit(double s) { return s > 0.0 ? (s < 1.0 ? s : 1.0) : 0.0; }

// Normalized arc-length parameter of vertex i: cumulative[i] / length, computed the same
// way everywhere so that at(vertex parameter) finds that vertex exactly. It is exactly 0
// at the first vertex and exactly 1 at the last.
double vertex_param(const std::vector<double>& cumulative, std::size_t i) { return cumulative[i] / cumulative.back(); }

// Where s in [0,1] falls: segment i, [param(i), param(i+1)) (the last segment for s = 1),
// and the fraction t along it. Found by arc length (a multiplication); only near a vertex
// is it settled against the exact vertex parameters, so that a vertex parameter gives
// t = 0 on that vertex's segment.
struct Location {
  std::size_t segment;
  double t;
};

/// The first index whose cumulative length exceeds x (std::upper_bound over `cumulative`):
/// a few steps from the first vertex past x's bucket, or a binary search where vertices
/// crowd into one bucket.
std::size_t first_above(const std::vector<double>& cumulative, const Polyline::Lookup& lookup, double x) {
  constexpr int kMaxSteps = 8;
  const std::vector<std::size_t>& bucket_first = lookup.bucket_first;
  const std::size_t n = cumulative.size(), buckets = bucket_first.size() - 1;
  const double position = x * lookup.buckets_per_length;
  std::size_t i = bucket_first[position > 0.0 ? std::min(buckets - 1, static_cast<std::size_t>(position)) : 0];
  for (int step = 0; step < kMaxSteps; ++step) {
    if (i > 0 && cumulative[i - 1] > x) --i;
    else if (i < n && cumulative[i] <= x) ++i;
    else return i;
  }
  return static_cast<std::size_t>(std::upper_bound(cumulative.begin(), cumulative.end(), x) - cumulative.begin());
}

Location locate(const std::vector<double>& cumulative, const Polyline::Lookup& lookup, double s) {
  const std::size_t last = cumulative.size() - 2;
  const double total = cumulative.back(), x = s * total;
  std::size_t i = first_above(cumulative, lookup, x);
  i = std::min(i == 0 ? 0 : i - 1, last);
  const double near = 8 * std::numeric_limits<double>::epsilon() * total;
  if (x - cumulative[i] <= near || cumulative[i + 1] - x <= near) {
    while (i > 0 && vertex_param(cumulative, i) > s) --i;
    while (i < last && vertex_param(cumulative, i + 1) <= s) ++i;
    const double s0 = vertex_param(cumulative, i), s1 = vertex_param(cumulative, i + 1);
    return {i, s1 > s0 ? (s - s0) / (s1 - s0) : 0.0};
  }
  // A division, not a multiplication by a stored inverse: the rounding of t is part of
  // what every surface evaluation returns.
  const double len = cumulative[i + 1] - cumulative[i];
  return {i, len > 0.0 ? (x - cumulative[i]) / len : 0.0};
}

// The point at s in [0,1], located at loc: the stored point at both ends and at a vertex.
Vec3 point_at(const std::vector<Vec3>& points, double s, const Location& loc) {
  if (s == 0.0) return points.front();
  if (s == 1.0) return points.back();
  if (loc.t == 0.0) return points[loc.segment];
  // (1-t)a + tb (not a + t(b-a)): exactly b at t = 1.
  return (1.0 - loc.t) * points[loc.segment] + loc.t * points[loc.segment + 1];
}

}  // namespace

Polyline::Polyline(std::vector<Vec3> points) : points_(std::move(points)) {
  if (points_.size() < 2)
    fail(ErrorCode::InvalidArgument, "polyline has " + std::to_string(points_.size()) + " point(s); at least 2 are needed");
  cumulative_.resize(points_.size());
  cumulative_[0] = 0.0;
  for (std::size_t i = 1; i < points_.size(); ++i) {
    if (!is_finite(points_[i]) || !is_finite(points_[i - 1]))
      fail(ErrorCode::NonFinite, "polyline point " + std::to_string(is_finite(points_[i]) ? i - 1 : i) + " has a non-finite coordinate");
    cumulative_[i] = cumulative_[i - 1] + (points_[i] - points_[i - 1]).norm();
  }
  const double total = cumulative_.back();
  if (!(total > 0.0)) fail(ErrorCode::Degenerate, "polyline has zero length (all its points coincide)");
  if (!std::isfinite(total)) fail(ErrorCode::NonFinite, "polyline length overflows");
  const std::size_t buckets = points_.size() - 1;
  lookup_.buckets_per_length = static_cast<double>(buckets) / total;
  lookup_.bucket_first.resize(buckets + 1);
  std::size_t vertex = 0;
  for (std::size_t b = 0; b <= buckets; ++b) {
    const double x = total * (static_cast<double>(b) / static_cast<double>(buckets));
    while (vertex < cumulative_.size() && cumulative_[vertex] <= x) ++vertex;
    lookup_.bucket_first[b] = vertex;
  }
  // Each segment's d/ds, as at(s, d_ds) returns it: the segment's own where it has a length,
  // else (repeated points) that of the last segment before it with a direction (the first
  // segment with one for repeated points at the start, which no s locates).
  derivative_.resize(points_.size() - 1);
  std::size_t directed = 0;
  while (cumulative_[directed + 1] == cumulative_[directed]) ++directed;
  for (std::size_t k = 0; k + 1 < points_.size(); ++k) {
    if (cumulative_[k + 1] != cumulative_[k]) directed = k;
    derivative_[k] = (points_[directed + 1] - points_[directed]) * (total / (cumulative_[directed + 1] - cumulative_[directed]));
  }
}

Vec3 Polyline::at(double s) const {
  s = clamp_unit(s);
  return point_at(points_, s, locate(cumulative_, lookup_, s));
}

Vec3 Polyline::tangent(double s) const {
  Vec3 d_ds;
  at(s, d_ds);
  return d_ds / length();
}

Vec3 Polyline::at(double s, Vec3& d_ds) const {
  s = clamp_unit(s);
  const Location loc = locate(cumulative_, lookup_, s);
  // locate returns a segment of non-zero length, except for s = 1 when the polyline ends
  // on repeated points, whose derivative is that of the last segment with a direction.
  d_ds = derivative_[loc.segment];
  return point_at(points_, s, loc);
}

std::pair<Polyline, Polyline> Polyline::split(double s) const {
  if (!(s > 0.0 && s < 1.0)) fail(ErrorCode::InvalidArgument, "polyline split at s=" + std::to_string(s) + ", outside (0,1)");
  std::vector<Vec3> first, second;
  const std::size_t i = locate(cumulative_, lookup_, s).segment;
  std::size_t vertex = points_.size();  // the existing vertex at s, if any
  if (i > 0 && s - vertex_param(cumulative_, i) <= kVertexSnap) vertex = i;
  else if (i + 2 < points_.size() && vertex_param(cumulative_, i + 1) - s <= kVertexSnap) vertex = i + 1;
  if (vertex < points_.size()) {
    first.assign(points_.begin(), points_.begin() + vertex + 1);
    second.assign(points_.begin() + vertex, points_.end());
  } else {
    const Vec3 p = at(s);
    first.assign(points_.begin(), points_.begin() + i + 1);
    first.push_back(p);
    second.push_back(p);
    second.insert(second.end(), points_.begin() + i + 1, points_.end());
  }
  return {Polyline(std::move(first)), Polyline(std::move(second))};
}

Vec3 Polyline::nearest(const Vec3& q, double* out_s) const {
  double best_d2 = std::numeric_limits<double>::infinity();
  double best_s = 0.0;
  for (std::size_t i = 0; i + 1 < points_.size(); ++i) {
    const Vec3& a = points_[i];
    const Vec3& b = points_[i + 1];
    const Vec3 ab = b - a;
    const double len2 = ab.squaredNorm();
    double t = len2 > 0.0 ? (q - a).dot(ab) / len2 : 0.0;
    t = clamp_unit(t);
    const double d2 = (q - ((1.0 - t) * a + t * b)).squaredNorm();
    if (d2 < best_d2) {
      best_d2 = d2;
      const double s0 = vertex_param(cumulative_, i), s1 = vertex_param(cumulative_, i + 1);
      best_s = t == 1.0 ? s1 : s0 + t * (s1 - s0);
    }
  }
  if (out_s) *out_s = best_s;
  // The point is at(s) itself, so that callers holding s get the very same point.
  return at(best_s);
}

Polyline Polyline::with_ends(const Vec3& first, const Vec3& last) const {
  std::vector<Vec3> pts = points_;
  pts.front() = first;
  pts.back() = last;
  return Polyline(std::move(pts));
}

}  // namespace dbs
