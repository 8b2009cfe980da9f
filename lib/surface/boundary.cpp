#include "boundary.hpp"

#include <Eigen/Geometry>
#include <cstdio>
#include <string>

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
void check_side_length(Side s, double length, double size) {
  const double tol = Boundary::kCornerTolerance * size;
  if (length == 0.0) fail(ErrorCode::Degenerate, side_label(s) + " has zero length (all its points coincide)");
  if (length <= tol)
    fail(ErrorCode::Degenerate, side_label(s) + " has length " + format_number(length) + ", below the corner tolerance " +
                                    format_number(tol) + " (" + format_number(Boundary::kCornerTolerance) + " of the boundary size " +
                                    format_number(size) + ")");
}

double checked_size(const Box3& box) {
  const double size = box.diagonal();
  if (!std::isfinite(size)) fail(ErrorCode::OutOfRange, "boundary coordinates are too large (its size overflows)");
  if (size == 0.0) fail(ErrorCode::Degenerate, "boundary has zero size: all its points coincide");
  return size;
}

// Unsigned area of the boundary's Coons patch, from a sampled triangulation. A boundary
// whose sides are collinear, or fold back onto each other, spans (almost) none.
double coons_area(const Boundary& boundary) {
  constexpr int n = 8;
  const CoonsPatch coons(boundary);
  std::vector<Vec3> samples;
  samples.reserve((n + 1) * (n + 1));
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) samples.push_back(coons.eval(static_cast<double>(i) / n, static_cast<double>(j) / n));
  double area = 0.0;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const Vec3& p00 = samples[j * (n + 1) + i];
      const Vec3& p10 = samples[j * (n + 1) + i + 1];
      const Vec3& p01 = samples[(j + 1) * (n + 1) + i];
      const Vec3& p11 = samples[(j + 1) * (n + 1) + i + 1];
      area += 0.5 * ((p10 - p00).cross(p11 - p00).norm() + (p11 - p00).cross(p01 - p00).norm());
    }
  return area;
}

// The spanned area is compared with size^2: its mean width (area / size) must exceed the
// corner tolerance, below which points of the boundary count as the same point.
void check_area(const Boundary& boundary, double size) {
  const double area = coons_area(boundary);
  const double tol = Boundary::kCornerTolerance * size * size;
  if (!(area > tol))
    fail(ErrorCode::Degenerate, "boundary spans (almost) no area: its Coons patch has area " + format_number(area) + ", below " +
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

Boundary::Boundary(std::vector<Vec3> bottom, std::vector<Vec3> right, std::vector<Vec3> top, std::vector<Vec3> left) {
  std::array<std::vector<Vec3>, 4> pts = {std::move(bottom), std::move(right), std::move(top), std::move(left)};
  Box3 box;
  for (Side s : kSides) {
    check_side_points(s, pts[static_cast<int>(s)]);
    for (const Vec3& p : pts[static_cast<int>(s)]) box.extend(p);
  }
  const double size = checked_size(box);

  const double tol = kCornerTolerance * size;
  for (const CornerEnds& c : kCorners) {
    Vec3& a = c.a_at_end ? pts[static_cast<int>(c.a)].back() : pts[static_cast<int>(c.a)].front();
    Vec3& b = c.b_at_end ? pts[static_cast<int>(c.b)].back() : pts[static_cast<int>(c.b)].front();
    const double miss = (a - b).norm();
    if (miss > tol)
      fail(ErrorCode::Degenerate, corner_label(c) + ": " + end_label(c.a, c.a_at_end) + format_point(a) + " but " +
                                      end_label(c.b, c.b_at_end) + format_point(b) + ", " + format_number(miss) + " apart (tolerance " +
                                      format_number(kCornerTolerance) + " of the boundary size " + format_number(size) + ")");
    a = b = 0.5 * (a + b);  // exactly a when a == b
  }

  for (Side s : kSides) {
    check_side_length(s, polyline_length(pts[static_cast<int>(s)]), size);
    sides_[static_cast<int>(s)] = Polyline(std::move(pts[static_cast<int>(s)]));
  }
  check_area(*this, size);
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
  for (Side s : kSides) check_side_length(s, side(s).length(), size);
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
