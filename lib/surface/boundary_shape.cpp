#include "boundary_shape.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>

#include "boundary.hpp"
#include "error.hpp"
#include "number_text.hpp"

namespace dbs {

namespace {

constexpr double kPi = 3.14159265358979323846;

// Below this (in units of the boundary's size) two points of the projection are one point,
// and parts of the loop closer than this along it are neighbours, not a crossing: the
// corner tolerance.
constexpr double kSamePoint = Boundary::kCornerTolerance;

std::string number(double x) { return significant_text(x, 6); }

std::string point_text(const Vec3& p) { return "(" + number(p.x()) + ", " + number(p.y()) + ", " + number(p.z()) + ")"; }

std::string side_text(int s) { return std::string("side '") + side_name(static_cast<Side>(s)) + "'"; }

// ---- a side folding back -----------------------------------------------------------------

// The point at arc length `at` of the polyline `p` with cumulative lengths `c` (clamped).
Vec3 point_at(const std::vector<Vec3>& p, const std::vector<double>& c, double at) {
  if (at <= 0.0) return p.front();
  if (at >= c.back()) return p.back();
  const std::size_t k = static_cast<std::size_t>(std::upper_bound(c.begin(), c.end(), at) - c.begin());  // c[k-1] <= at < c[k]
  const double len = c[k] - c[k - 1];
  const double t = len > 0.0 ? (at - c[k - 1]) / len : 0.0;
  return p[k - 1] + t * (p[k] - p[k - 1]);
}

// A side folds back where its direction over the stretch before a point and over the
// stretch after it (each kFoldWindow of the side's length, or the whole segment where that
// is longer) turn by more than kFoldAngleDegrees. Of the points where it does, the one where
// the side itself turns most (its two segments) is named: the tip of the fold.
void check_side_fold(int s, const std::vector<Vec3>& p, double size, const Vec3& origin) {
  std::vector<double> c(p.size(), 0.0);
  for (std::size_t k = 1; k < p.size(); ++k) c[k] = c[k - 1] + (p[k] - p[k - 1]).norm();
  const double window = kFoldWindow * c.back();
  const double fold_cos = std::cos(kFoldAngleDegrees * kPi / 180.0);
  auto cos_turn = [](const Vec3& in, const Vec3& out) {
    const double lengths = in.norm() * out.norm();
    return lengths > 0.0 ? in.dot(out) / lengths : 1.0;
  };
  double tip_turn = 2.0, tip_stretch_turn = 1.0;
  std::size_t tip = 0;
  for (std::size_t k = 1; k + 1 < p.size(); ++k) {
    const Vec3 in = p[k] - point_at(p, c, std::min(c[k - 1], c[k] - window));
    const Vec3 out = point_at(p, c, std::max(c[k + 1], c[k] + window)) - p[k];
    const double stretch_turn = cos_turn(in, out);
    if (!(stretch_turn < fold_cos)) continue;
    const double own_turn = cos_turn(p[k] - p[k - 1], p[k + 1] - p[k]);
    if (own_turn < tip_turn) {
      tip_turn = own_turn;
      tip_stretch_turn = stretch_turn;
      tip = k;
    }
  }
  if (tip != 0) {
    const double degrees = std::acos(std::max(-1.0, tip_stretch_turn)) * 180.0 / kPi;
    fail(ErrorCode::Degenerate, "boundary " + side_text(s) + " folds back on itself at its point " + std::to_string(tip) + " " +
                                    point_text(origin + p[tip] * size) + ": its direction turns by " + number(degrees) + " degrees (more than " +
                                    number(kFoldAngleDegrees) + "), so it runs back over itself");
  }
}

// ---- the loop crossing itself ------------------------------------------------------------

// The four sides as one closed loop (bottom, right, top backwards, left backwards), without
// repeated points. Segment k runs from point k to point k+1 (mod the count).
struct Loop {
  std::vector<Vec3> points;  // in units of the boundary's size, from corner (0,0)
  std::vector<int> side;     // per segment: the side it runs along
  std::vector<std::size_t> first;  // per segment: the lower index of its ends in that side's own points
  std::vector<double> arc;   // per point: arc length along the loop from its start
  double length = 0.0;
};

Loop make_loop(const std::array<std::vector<Vec3>, 4>& sides) {
  Loop loop;
  auto add = [&](const Vec3& p, int s, std::size_t first) {
    if (!loop.points.empty() && loop.points.back() == p) return;
    if (!loop.points.empty()) {
      loop.side.push_back(s);
      loop.first.push_back(first);
    }
    loop.points.push_back(p);
  };
  const std::vector<Vec3>&bottom = sides[0], &right = sides[1], &top = sides[2], &left = sides[3];
  for (std::size_t i = 0; i < bottom.size(); ++i) add(bottom[i], 0, i == 0 ? 0 : i - 1);
  for (std::size_t i = 1; i < right.size(); ++i) add(right[i], 1, i - 1);
  for (std::size_t i = top.size() - 1; i-- > 0;) add(top[i], 2, i);
  for (std::size_t i = left.size() - 1; i-- > 0;) add(left[i], 3, i);
  // The last point added is left's first, the loop's start: it closes the loop.
  if (loop.points.size() > 1 && loop.points.back() == loop.points.front()) {
    loop.points.pop_back();
  } else {
    loop.side.push_back(3);
    loop.first.push_back(0);
  }
  const std::size_t n = loop.points.size();
  loop.arc.resize(n);
  for (std::size_t k = 0; k < n; ++k) {
    loop.arc[k] = loop.length;
    loop.length += (loop.points[(k + 1) % n] - loop.points[k]).norm();
  }
  return loop;
}

// The loop's best-fit plane: the principal axes of its points spread evenly along its length.
struct Plane {
  Vec3 origin, e1, e2, normal;
};

Plane best_fit_plane(const Loop& loop) {
  const std::size_t n = loop.points.size();
  Vec3 mean = Vec3::Zero();
  for (std::size_t k = 0; k < n; ++k) {
    const Vec3 &a = loop.points[k], &b = loop.points[(k + 1) % n];
    mean += (b - a).norm() * 0.5 * (a + b);
  }
  mean /= loop.length;
  Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
  for (std::size_t k = 0; k < n; ++k) {
    const Vec3 a = loop.points[k] - mean, b = loop.points[(k + 1) % n] - mean;
    const Vec3 m = 0.5 * (a + b), d = b - a;
    // The second moment of a segment with uniform density: its midpoint's plus d d^T / 12.
    cov += d.norm() * (m * m.transpose() + d * d.transpose() / 12.0);
  }
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen(cov);
  return {mean, eigen.eigenvectors().col(2), eigen.eigenvectors().col(1), eigen.eigenvectors().col(0)};
}

Vec2 cross_section(const Plane& plane, const Vec3& p) { return {(p - plane.origin).dot(plane.e1), (p - plane.origin).dot(plane.e2)}; }

double cross2(const Vec2& a, const Vec2& b) { return a.x() * b.y() - a.y() * b.x(); }

// Where segment i (at fraction t) and segment j (at s) cross in the projection, and how far
// apart they are there in 3D.
struct Meeting {
  double t = 0.0, s = 0.0, gap = 0.0;
  bool found = false;
};

// The angle of direction d, in (-pi, pi].
double angle_of(const Vec2& d) { return std::atan2(d.y(), d.x()); }

// Whether angle x lies strictly inside the counter-clockwise turn from a to b, away from
// both ends.
bool strictly_between(double a, double b, double x) {
  constexpr double kMargin = 1e-9;
  const auto ccw = [](double from, double to) {
    double d = to - from;
    while (d < 0.0) d += 2.0 * kPi;
    while (d >= 2.0 * kPi) d -= 2.0 * kPi;
    return d;
  };
  const double span = ccw(a, b), at = ccw(a, x);
  return at > kMargin && at < span - kMargin;
}

// Two strands of the projected loop meeting at x, strand A from a to a' and strand B from b
// to b' through it: B crosses A when b and b' lie on either side of the path a -> x -> a'
// (strictly: strands that touch, run along each other or only meet there do not cross).
bool strands_cross(const Vec2& x, const Vec2& a, const Vec2& a2, const Vec2& b, const Vec2& b2) {
  const Vec2 da = a - x, da2 = a2 - x, db = b - x, db2 = b2 - x;
  if (da.norm() <= kSamePoint || da2.norm() <= kSamePoint || db.norm() <= kSamePoint || db2.norm() <= kSamePoint) return false;
  const double ta = angle_of(da), ta2 = angle_of(da2), tb = angle_of(db), tb2 = angle_of(db2);
  const bool b_in = strictly_between(ta, ta2, tb), b2_in = strictly_between(ta, ta2, tb2);
  const bool b_out = strictly_between(ta2, ta, tb), b2_out = strictly_between(ta2, ta, tb2);
  return (b_in && b2_out) || (b_out && b2_in);
}

// The projected loop (q) beside the 3D one.
struct Projected {
  const Loop& loop;
  const std::vector<Vec2>& q;
  std::size_t next(std::size_t k) const { return (k + 1) % q.size(); }
  std::size_t prev(std::size_t k) const { return (k + q.size() - 1) % q.size(); }
};

// Where segments i and j cross in the projection, if they do: a proper crossing (each
// segment's ends strictly on either side of the other's line), or a meeting at an end of
// one of them (an end of a segment on the other, or two ends at one point) where the loop's
// strands through that point cross. Of several, the one closest in 3D.
Meeting meet(const Projected& pr, std::size_t i, std::size_t j) {
  const std::vector<Vec2>& q = pr.q;
  const std::vector<Vec3>& P = pr.loop.points;
  const std::size_t i1 = pr.next(i), j1 = pr.next(j);
  Meeting best;
  auto consider = [&](double t, double s) {
    const double gap = ((P[i] + t * (P[i1] - P[i])) - (P[j] + s * (P[j1] - P[j]))).norm();
    if (!best.found || gap < best.gap) best = {t, s, gap, true};
  };
  const Vec2 dp = q[i1] - q[i], dq = q[j1] - q[j];
  const double lp = dp.norm(), lq = dq.norm();
  if (lp > kSamePoint && lq > kSamePoint) {
    const double a0 = cross2(dq, q[i] - q[j]) / lq, a1 = cross2(dq, q[i1] - q[j]) / lq;
    const double b0 = cross2(dp, q[j] - q[i]) / lp, b1 = cross2(dp, q[j1] - q[i]) / lp;
    const bool p_across = (a0 > kSamePoint && a1 < -kSamePoint) || (a0 < -kSamePoint && a1 > kSamePoint);
    const bool q_across = (b0 > kSamePoint && b1 < -kSamePoint) || (b0 < -kSamePoint && b1 > kSamePoint);
    if (p_across && q_across) consider(a0 / (a0 - a1), b0 / (b0 - b1));
  }
  // Loop point v (an end of one segment) on segment (s0, s1) of the other, at fraction f:
  // the strand through v against the other's strand through the meeting point (the
  // segment itself, or the strand through its end when v meets that end).
  auto vertex_on = [&](std::size_t v, std::size_t s0, std::size_t s1, double& f) {
    const Vec2 d = q[s1] - q[s0];
    const double l = d.norm();
    f = l > 0.0 ? std::clamp((q[v] - q[s0]).dot(d) / (l * l), 0.0, 1.0) : 0.0;
    if ((q[s0] + f * d - q[v]).norm() > kSamePoint) return false;
    const Vec2 &a = q[pr.prev(v)], &a2 = q[pr.next(v)];
    if (f * l <= kSamePoint) return strands_cross(q[v], a, a2, q[pr.prev(s0)], q[s1]);
    if ((1.0 - f) * l <= kSamePoint) return strands_cross(q[v], a, a2, q[s0], q[pr.next(s1)]);
    return strands_cross(q[v], a, a2, q[s0], q[s1]);
  };
  double f;
  if (vertex_on(i, j, j1, f)) consider(0.0, f);
  if (vertex_on(i1, j, j1, f)) consider(1.0, f);
  if (vertex_on(j, i, i1, f)) consider(f, 0.0);
  if (vertex_on(j1, i, i1, f)) consider(f, 1.0);
  return best;
}

struct Crossing {
  std::size_t i = 0, j = 0;  // segments, i < j
  Meeting meeting;
  bool found = false;
};

// Segments are gathered in a grid of cells over the projection (about one segment per
// cell), and only pairs sharing a cell are compared, each pair once (in the first cell
// both cover).
Crossing first_crossing(const Loop& loop, const Plane& plane) {
  const std::size_t n = loop.points.size();
  std::vector<Vec2> q(n);
  Vec2 lo = Vec2::Constant(INFINITY), hi = Vec2::Constant(-INFINITY);
  for (std::size_t k = 0; k < n; ++k) {
    q[k] = cross_section(plane, loop.points[k]);
    lo = lo.cwiseMin(q[k]);
    hi = hi.cwiseMax(q[k]);
  }
  lo -= Vec2::Constant(2 * kSamePoint);
  hi += Vec2::Constant(2 * kSamePoint);
  const Vec2 extent = hi - lo;
  const double cell = std::sqrt(extent.x() * extent.y() / static_cast<double>(n));
  const std::size_t max_cells = 4 * n;
  const auto cells_along = [&](double width) { return static_cast<std::size_t>(std::clamp(std::ceil(width / cell), 1.0, static_cast<double>(max_cells))); };
  std::size_t nx = cells_along(extent.x()), ny = cells_along(extent.y());
  while (nx * ny > max_cells) (nx > ny ? nx : ny) = std::max<std::size_t>(1, (nx > ny ? nx : ny) / 2);
  auto cell_of = [&](const Vec2& p, std::size_t& cx, std::size_t& cy) {
    cx = std::min(nx - 1, static_cast<std::size_t>(std::max(0.0, (p.x() - lo.x()) / extent.x() * static_cast<double>(nx))));
    cy = std::min(ny - 1, static_cast<std::size_t>(std::max(0.0, (p.y() - lo.y()) / extent.y() * static_cast<double>(ny))));
  };
  struct Range {
    std::size_t x0, y0, x1, y1;
  };
  std::vector<Range> range(n);
  std::vector<std::size_t> start(nx * ny + 1, 0);
  for (std::size_t k = 0; k < n; ++k) {
    const Vec2 &a = q[k], &b = q[(k + 1) % n];
    Range& r = range[k];
    cell_of(a.cwiseMin(b) - Vec2::Constant(kSamePoint), r.x0, r.y0);
    cell_of(a.cwiseMax(b) + Vec2::Constant(kSamePoint), r.x1, r.y1);
    for (std::size_t y = r.y0; y <= r.y1; ++y)
      for (std::size_t x = r.x0; x <= r.x1; ++x) ++start[y * nx + x + 1];
  }
  for (std::size_t c = 0; c < nx * ny; ++c) start[c + 1] += start[c];
  std::vector<std::uint32_t> members(start.back());
  std::vector<std::size_t> fill(start.begin(), start.end() - 1);
  for (std::size_t k = 0; k < n; ++k)
    for (std::size_t y = range[k].y0; y <= range[k].y1; ++y)
      for (std::size_t x = range[k].x0; x <= range[k].x1; ++x) members[fill[y * nx + x]++] = static_cast<std::uint32_t>(k);

  const Projected projected{loop, q};
  Crossing first;
  const double max_gap = kCrossingGap;
  for (std::size_t y = 0; y < ny; ++y)
    for (std::size_t x = 0; x < nx; ++x)
      for (std::size_t a = start[y * nx + x]; a < start[y * nx + x + 1]; ++a)
        for (std::size_t b = a + 1; b < start[y * nx + x + 1]; ++b) {
          std::size_t i = members[a], j = members[b];
          if (i > j) std::swap(i, j);
          if (j == i + 1 || (i == 0 && j == n - 1)) continue;  // neighbours share a point
          if (std::max(range[i].x0, range[j].x0) != x || std::max(range[i].y0, range[j].y0) != y) continue;  // met in an earlier cell
          if (first.found && (i > first.i || (i == first.i && j > first.j))) continue;
          const Meeting m = meet(projected, i, j);
          if (!m.found || m.gap > max_gap) continue;
          // Strands this close along the loop close a small curl of it (as an outline found
          // from a scan may have near a corner), not two parts of the boundary crossing.
          const double at_i = loop.arc[i] + m.t * (loop.points[(i + 1) % n] - loop.points[i]).norm();
          const double at_j = loop.arc[j] + m.s * (loop.points[(j + 1) % n] - loop.points[j]).norm();
          const double along = std::min(at_j - at_i, loop.length - (at_j - at_i));
          if (along <= kCurlLength * loop.length) continue;
          first = {i, j, m, true};
        }
  return first;
}

std::string segment_text(const Loop& loop, std::size_t k) {
  return side_text(loop.side[k]) + " (between its points " + std::to_string(loop.first[k]) + " and " + std::to_string(loop.first[k] + 1) + ")";
}

void check_loop_crossing(const std::array<std::vector<Vec3>, 4>& sides, double size, const Vec3& origin) {
  const Loop loop = make_loop(sides);
  if (loop.points.size() < 3) return;
  const Plane plane = best_fit_plane(loop);
  const Crossing c = first_crossing(loop, plane);
  if (!c.found) return;
  const std::size_t n = loop.points.size();
  const Vec3 at = loop.points[c.i] + c.meeting.t * (loop.points[(c.i + 1) % n] - loop.points[c.i]);
  const Vec2 in_plane = Vec2((at - loop.points[0]).dot(plane.e1), (at - loop.points[0]).dot(plane.e2)) * size;
  const int si = loop.side[c.i], sj = loop.side[c.j];
  std::string what = si == sj ? side_text(si) + " crosses itself: " + segment_text(loop, c.i) + " meets " + segment_text(loop, c.j)
                              : segment_text(loop, c.i) + " crosses " + segment_text(loop, c.j);
  std::string hint;
  if (si != sj && (si + 2) % 4 == sj) hint = "; a side runs across the patch into the opposite one, or two corners are given in the wrong order (a bow-tie)";
  fail(ErrorCode::Degenerate, "boundary crosses itself: " + what + " at " + point_text(origin + at * size) + ", (" + number(in_plane.x()) + ", " +
                                  number(in_plane.y()) + ") in the boundary's best-fit plane (from corner (u=0,v=0), normal " +
                                  point_text(plane.normal) + "), " + number(c.meeting.gap * size) + " apart" + hint);
}

}  // namespace

void check_boundary_shape(const std::array<Polyline, 4>& sides, double size) {
  // In units of the boundary's size from its first corner, so that products of lengths
  // neither overflow nor underflow at any supported magnitude.
  const Vec3 origin = sides[0].front();
  std::array<std::vector<Vec3>, 4> scaled;
  for (int s = 0; s < 4; ++s) {
    scaled[s].reserve(sides[s].size());
    for (const Vec3& p : sides[s].points()) scaled[s].push_back((p - origin) / size);
  }
  for (int s = 0; s < 4; ++s) check_side_fold(s, scaled[s], size, origin);
  check_loop_crossing(scaled, size, origin);
}

}  // namespace dbs
