#include "boundary.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cstdio>
#include <string>

#include "boundary_shape.hpp"
#include "coons_patch.hpp"
#include "error.hpp"
#include "number_text.hpp"

namespace dbs {

namespace {

constexpr Side kSides[4] = {Side::Bottom, Side::Right, Side::Top, Side::Left};

// 6 significant digits, without the exponent's leading zero: 1e-6, not 1e-06.
std::string format_number(double x) {
  return significant_text(x, 6);
}

std::string format_point(const Vec3& p) {
  return "(" + format_number(p.x()) + ", " + format_number(p.y()) + ", " + format_number(p.z()) + ")";
}

std::string side_label(Side s) { return std::string("boundary side '") + side_name(s) + "'"; }

// A corner where two sides meet: which end of which side.
struct CornerEnds {
  int u, v;
  Side a;
  bool a_at_end;
  Side b;
  bool b_at_end;
};

// bottom[0]=left[0], bottom[end]=right[0], top[0]=left[end], top[end]=right[end].
constexpr CornerEnds kCorners[4] = {
    {0, 0, Side::Bottom, false, Side::Left, false},
    {1, 0, Side::Bottom, true, Side::Right, false},
    {0, 1, Side::Top, false, Side::Left, true},
    {1, 1, Side::Top, true, Side::Right, true},
};

std::string corner_label(const CornerEnds& c) {
  return "corner (u=" + std::to_string(c.u) + ",v=" + std::to_string(c.v) + ")";
}

std::string end_label(Side s, bool at_end) { return std::string(side_name(s)) + (at_end ? " ends at " : " starts at "); }

void check_side_points(Side s, const std::vector<Vec3>& pts) {
  if (pts.size() < 2)
    fail(ErrorCode::InvalidArgument, side_label(s) + " has " + std::to_string(pts.size()) + " point(s); at least 2 are needed");
  for (std::size_t i = 0; i < pts.size(); ++i)
    if (!is_finite(pts[i])) fail(ErrorCode::NonFinite, side_label(s) + ", point " + std::to_string(i) + " has a non-finite coordinate");
}

double polyline_length(const std::vector<Vec3>& pts) {
  double len = 0.0;
  for (std::size_t i = 1; i < pts.size(); ++i) len += (pts[i] - pts[i - 1]).norm();
  return len;
}

// A side shorter than the corner tolerance joins two corners that are the same point.
void check_side_length(Side s, double length, double size, double tol) {
  if (length == 0.0) fail(ErrorCode::Degenerate, side_label(s) + " has zero length (all its points coincide)");
  if (length <= tol)
    fail(ErrorCode::Degenerate, side_label(s) + " has length " + format_number(length) + ", below the corner tolerance " +
                                    format_number(tol) + " (" + format_number(tol / size) + " of the boundary size " +
                                    format_number(size) + ")");
}

// The end of side `s` (its first point, or its last when `at_end`), with the sides given as
// they are except those flagged in `reversed` (bit s), which are read backwards, and the
// sides renamed by `as` (as[s]: the side given in place of s).
const Vec3& end_of(const std::array<std::vector<Vec3>, 4>& pts, Side s, bool at_end, unsigned reversed, const std::array<int, 4>& as) {
  const int given = as[static_cast<int>(s)];
  const bool back = at_end != (((reversed >> given) & 1u) != 0);
  return back ? pts[given].back() : pts[given].front();
}

// Whether every corner meets within `tol` with the sides read as end_of reads them.
bool corners_meet(const std::array<std::vector<Vec3>, 4>& pts, double tol, unsigned reversed, const std::array<int, 4>& as) {
  for (const CornerEnds& c : kCorners)
    if ((end_of(pts, c.a, c.a_at_end, reversed, as) - end_of(pts, c.b, c.b_at_end, reversed, as)).norm() > tol) return false;
  return true;
}

// The fix for corners that miss, when an evident one makes them all meet: a side or two
// running backwards, left and right or bottom and top swapped. "" when none does.
std::string corner_fix(const std::array<std::vector<Vec3>, 4>& pts, double tol) {
  const std::array<int, 4> given{{0, 1, 2, 3}};
  // One side backwards: its start meets where its end should, and the other way round.
  for (Side s : kSides) {
    if (!corners_meet(pts, tol, 1u << static_cast<int>(s), given)) continue;
    const bool row = s == Side::Bottom || s == Side::Top;
    const char* start_meets = row ? (s == Side::Bottom ? "right's start" : "right's end") : (s == Side::Left ? "top's start" : "top's end");
    const char* end_meets = row ? (s == Side::Bottom ? "left's start" : "left's end") : (s == Side::Left ? "bottom's start" : "bottom's end");
    return std::string("; ") + side_name(s) + " runs backwards (its start meets " + start_meets + ", its end meets " + end_meets + "): reverse it";
  }
  const std::array<int, 4> lr{{0, 3, 2, 1}}, bt{{2, 1, 0, 3}};
  if (corners_meet(pts, tol, 0u, lr)) return "; left and right are swapped";
  if (corners_meet(pts, tol, 0u, bt)) return "; bottom and top are swapped";
  // Two sides backwards (a side pair traced the other way round).
  for (int a = 0; a < 4; ++a)
    for (int b = a + 1; b < 4; ++b)
      if (corners_meet(pts, tol, (1u << a) | (1u << b), given))
        return std::string("; ") + side_name(kSides[a]) + " and " + side_name(kSides[b]) + " run backwards: reverse them";
  return "";
}

double checked_size(const Box3& box) {
  const double size = box.diagonal();
  if (!std::isfinite(size)) fail(ErrorCode::OutOfRange, "boundary coordinates are too large (its size overflows)");
  if (size == 0.0) fail(ErrorCode::Degenerate, "boundary has zero size: all its points coincide");
  return size;
}

// Unsigned area of the boundary's Coons patch, from a sampled triangulation. A boundary
// whose sides are collinear, or fold back onto each other, spans (almost) none.
double coons_area(const Boundary& boundary, double size) {
  constexpr int n = 8;
  const CoonsPatch coons(boundary);
  // In units of the boundary's size, so that the cross products of a boundary 1e-100 across
  // do not underflow (nor of one 1e100 across overflow); the area is scaled back at the end.
  const Vec3 origin = boundary.corner(0, 0);
  std::vector<Vec3> samples;
  samples.reserve((n + 1) * (n + 1));
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) samples.push_back((coons.eval(static_cast<double>(i) / n, static_cast<double>(j) / n) - origin) / size);
  double area = 0.0;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const Vec3& p00 = samples[j * (n + 1) + i];
      const Vec3& p10 = samples[j * (n + 1) + i + 1];
      const Vec3& p01 = samples[(j + 1) * (n + 1) + i];
      const Vec3& p11 = samples[(j + 1) * (n + 1) + i + 1];
      area += 0.5 * ((p10 - p00).cross(p11 - p00).norm() + (p11 - p00).cross(p01 - p00).norm());
    }
  return area;  // in units of size^2
}

// The spanned area is compared with size^2: its mean width (area / size) must exceed the
// corner tolerance, below which points of the boundary count as the same point.
void check_area(const Boundary& boundary, double size) {
  const double share = coons_area(boundary, size);  // of size^2
  if (!(share > Boundary::kCornerTolerance))
    fail(ErrorCode::Degenerate, "boundary spans (almost) no area: its Coons patch has area " + format_number(share * size * size) + ", below " +
                                    format_number(Boundary::kCornerTolerance) + " of the boundary size squared (" +
                                    format_number(size * size) + "); are its sides collinear or folded onto each other?");
}

}  // namespace

const char* side_name(Side side) {
  switch (side) {
    case Side::Bottom: return "bottom";
    case Side::Right: return "right";
    case Side::Top: return "top";
    case Side::Left: return "left";
  }
  return "unknown";
}

Boundary::Boundary(std::vector<Vec3> bottom, std::vector<Vec3> right, std::vector<Vec3> top, std::vector<Vec3> left, CornerTolerance tolerance) {
  std::array<std::vector<Vec3>, 4> pts = {std::move(bottom), std::move(right), std::move(top), std::move(left)};
  Box3 box;
  for (Side s : kSides) {
    check_side_points(s, pts[static_cast<int>(s)]);
    for (const Vec3& p : pts[static_cast<int>(s)]) box.extend(p);
  }
  const double size = checked_size(box);
  if (!std::isfinite(tolerance.value) || tolerance.value < 0.0)
    fail(ErrorCode::OutOfRange, "the corner tolerance " + format_number(tolerance.value) + " is not a finite value >= 0");
  const double tol = tolerance.relative ? tolerance.value * size : tolerance.value;
  if (tol > kMaxCornerTolerance * size)
    fail(ErrorCode::OutOfRange, "the corner tolerance " + format_number(tol) + " is above " + format_number(kMaxCornerTolerance) + " of the boundary size " + format_number(size));
  const std::string tolerance_text = tolerance.relative ? format_number(tolerance.value) + " of the boundary size " + format_number(size)
                                                        : format_number(tol) + ", the boundary size " + format_number(size);

  for (const CornerEnds& c : kCorners) {
    Vec3& a = c.a_at_end ? pts[static_cast<int>(c.a)].back() : pts[static_cast<int>(c.a)].front();
    Vec3& b = c.b_at_end ? pts[static_cast<int>(c.b)].back() : pts[static_cast<int>(c.b)].front();
    const double miss = (a - b).norm();
    if (miss > tol)
      fail(ErrorCode::Degenerate, corner_label(c) + ": " + end_label(c.a, c.a_at_end) + format_point(a) + " but " +
                                      end_label(c.b, c.b_at_end) + format_point(b) + ", " + format_number(miss) + " apart (tolerance " +
                                      tolerance_text + ")" + corner_fix(pts, tol));
  }
  for (const CornerEnds& c : kCorners) {
    Vec3& a = c.a_at_end ? pts[static_cast<int>(c.a)].back() : pts[static_cast<int>(c.a)].front();
    Vec3& b = c.b_at_end ? pts[static_cast<int>(c.b)].back() : pts[static_cast<int>(c.b)].front();
    const Vec3 mean = 0.5 * (a + b);  // exactly a when a == b
    max_snap_ = std::max({max_snap_, (a - mean).norm(), (b - mean).norm()});
    a = b = mean;
  }

  for (Side s : kSides) {
    check_side_length(s, polyline_length(pts[static_cast<int>(s)]), size, std::max(tol, kCornerTolerance * size));
    sides_[static_cast<int>(s)] = Polyline(std::move(pts[static_cast<int>(s)]));
  }
  check_area(*this, size);
  check_boundary_shape(sides_, size);
}

Boundary::Boundary(Polyline bottom, Polyline right, Polyline top, Polyline left)
    : sides_{std::move(bottom), std::move(right), std::move(top), std::move(left)} {
  for (Side s : kSides)
    if (side(s).size() < 2) fail(ErrorCode::InvalidArgument, side_label(s) + " is empty");
  for (const CornerEnds& c : kCorners) {
    const Vec3& a = c.a_at_end ? side(c.a).back() : side(c.a).front();
    const Vec3& b = c.b_at_end ? side(c.b).back() : side(c.b).front();
    if (a != b)
      fail(ErrorCode::Degenerate, corner_label(c) + ": " + end_label(c.a, c.a_at_end) + format_point(a) + " but " +
                                      end_label(c.b, c.b_at_end) + format_point(b) + "; the sides must share the corner exactly");
  }
  const double size = checked_size(bounds());
  for (Side s : kSides) check_side_length(s, side(s).length(), size, kCornerTolerance * size);
  check_area(*this, size);
}

Vec3 Boundary::corner(int u, int v) const {
  const Polyline& row = v == 0 ? bottom() : top();
  return u == 0 ? row.front() : row.back();
}

Box3 Boundary::bounds() const {
  Box3 box;
  for (const Polyline& s : sides_)
    for (const Vec3& p : s.points()) box.extend(p);
  return box;
}

}  // namespace dbs
