#include "subdivide.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

#include "curve_projection.hpp"
#include "curve_refinement.hpp"
#include "departure_guard.hpp"
#include "error.hpp"

namespace dbs {

namespace {

/// Samples of a middle curve taken on the parent surface before densification. Even, so
/// the centre (parameter 1/2) is a sample. The parent surface is a cubic spline over a grid
/// of at most a few tens of intervals, so 64 chords follow it closely; densification then
/// brings the node spacing down to the cloud's length scale.
constexpr int kMiddleCurveIntervals = 64;
/// Node spacing of a projected middle curve in units of h: the spacing the grid projection
/// uses, so the smoothing weight gamma means the same on seams and inside patches.
constexpr double kNodeSpacing = 2.0;
/// Upper bound on the nodes of one projected middle curve, so a very dense cloud does not
/// make the curve projection (and every descendant's boundary) needlessly long.
constexpr double kMaxMiddleCurveNodes = 2048.0;
/// The directed projection (eq. 5) weighs points by their distance to the projected point as
/// well as to the ray, so a node far from the cloud sees a mean biased towards the near side
/// of a curved cloud. The seams are final boundaries of the children, so the projection is
/// repeated from the projected nodes (same directions) until it settles: the data term is
/// then evaluated where the curve ends up. On a bump of height 20 h one pass leaves the curve
/// about 1 h below the cloud, three passes 0.1 h.
constexpr int kMaxProjectionPasses = 3;
/// A pass moving no node farther than this (in units of h) ends the repetition.
constexpr double kSettledOffset = 0.01;

/// A middle curve projected onto the cloud, split at the shared centre.
struct SplitCurve {
  Polyline first;   // from the start point to the centre
  Polyline second;  // from the centre to the end point
};

/// Projects the middle curve t -> S(at(t)) (t in [0,1]) onto the cloud with the smooth curve
/// projection, its ends fixed at `start` / `end` and its centre (t = 1/2) fixed at `centre`.
/// The three fixed points are copied bitwise into the result.
template <class ParamAt>
SplitCurve project_middle_curve(const BaseSurface& surface, ParamAt at, const Vec3& start, const Vec3& centre, const Vec3& end, const DirectedProjector& projector, double gamma, const RefinementSettings& refinement, const char* name) {
  const int samples = kMiddleCurveIntervals + 1;
  const int centre_sample = kMiddleCurveIntervals / 2;
  std::vector<Vec3> points(samples), directions(samples);
  double length = 0.0;
  for (int k = 0; k < samples; ++k) {
    const Vec2 uv = at(static_cast<double>(k) / kMiddleCurveIntervals);
    points[k] = surface.eval(uv.x(), uv.y());
    directions[k] = surface.normal(uv.x(), uv.y());
    if (k > 0) length += (points[k] - points[k - 1]).norm();
  }
  points.front() = start;
  points.back() = end;
  if (!(length > 0.0)) fail(ErrorCode::Degenerate, std::string("subdivide: the middle curve ") + name + " of the parent surface has zero length");

  const double spacing = std::max(kNodeSpacing * projector.length_scale(), length / kMaxMiddleCurveNodes);
  std::vector<std::size_t> original;
  CurveProjectionInput input = densify_polygon(points, directions, spacing, original);
  const std::size_t centre_node = original[centre_sample];
  input.nodes[centre_node] = centre;
  input.fixed.push_back(centre_node);

  for (int pass = 0; pass < kMaxProjectionPasses; ++pass) {
    const std::vector<double> offsets = solve_curve_near(projector, input, gamma, RefinementSettings());
    double largest = 0.0;
    for (std::size_t k = 0; k < offsets.size(); ++k) {
      input.nodes[k] += offsets[k] * input.directions[k];
      largest = std::max(largest, std::abs(offsets[k]));
    }
    if (largest <= kSettledOffset * projector.length_scale()) break;
  }
  if (refinement.enabled) {
    // The Ceres refinement from where the linear passes settled.
    const std::vector<double> offsets = refine_curve(projector, input, gamma, std::vector<double>(input.nodes.size(), 0.0), refinement);
    for (std::size_t k = 0; k < offsets.size(); ++k) input.nodes[k] += offsets[k] * input.directions[k];
  }
  std::vector<Vec3> nodes = std::move(input.nodes);
  nodes.front() = start;
  nodes[centre_node] = centre;
  nodes.back() = end;

  std::vector<Vec3> first(nodes.begin(), nodes.begin() + static_cast<std::ptrdiff_t>(centre_node) + 1);
  std::vector<Vec3> second(nodes.begin() + static_cast<std::ptrdiff_t>(centre_node), nodes.end());
  return {Polyline(std::move(first)), Polyline(std::move(second))};
}

/// The patch centre S(1/2,1/2) projected onto the cloud along the surface normal (repeated
/// like the curves' projection); it stays where it is once the ray meets no cloud weight (a
/// hole keeps the parent's shape) or a pass would take it off the cloud (departs()).
Vec3 projected_centre(const BaseSurface& surface, const DirectedProjector& projector) {
  Vec3 centre = surface.eval(0.5, 0.5);
  const Vec3 normal = surface.normal(0.5, 0.5);
  for (int pass = 0; pass < kMaxProjectionPasses; ++pass) {
    double t = 0.0;
    if (!projector.project(centre, normal, t)) break;
    if (departs(projector, centre, centre + t * normal)) break;  // a ray grazing the sheet (departure_guard.hpp)
    centre += t * normal;
    if (std::abs(t) * normal.norm() <= kSettledOffset * projector.length_scale()) break;
  }
  return centre;
}

/// A child's initial surface: its boundary, and a grid x grid sample of the parent surface
/// over the quarter starting at parent parameters (u0, v0), corrected towards the child's
/// boundary. The seams were projected onto the cloud, so they lie off the parent surface;
/// a sample taken as it is would jump from the seam to the parent surface within one grid
/// cell and could turn that cell over (a pleat the child then inherits). The correction is
/// the Coons blend of the seams' offsets from the parent's own curves, so the interior
/// follows the seams smoothly. The grid's border holds the child's boundary (BaseSurface
/// ignores it; it keeps the stored grid on the patch).
Patch make_child(const Patch& parent, Boundary boundary, double u0, double v0, int grid, Rect rect) {
  auto on_parent = [&](double s, double t) { return parent.surface.eval(u0 + 0.5 * s, v0 + 0.5 * t); };
  // Offsets of the child's sides from the parent surface along the quarter's sides.
  auto bottom = [&](double s) { return Vec3(boundary.bottom().at(s) - on_parent(s, 0.0)); };
  auto top = [&](double s) { return Vec3(boundary.top().at(s) - on_parent(s, 1.0)); };
  auto left = [&](double t) { return Vec3(boundary.left().at(t) - on_parent(0.0, t)); };
  auto right = [&](double t) { return Vec3(boundary.right().at(t) - on_parent(1.0, t)); };
  const Vec3 c00 = bottom(0.0), c10 = bottom(1.0), c01 = top(0.0), c11 = top(1.0);
  Grid points(grid, grid);
  for (int j = 0; j < grid; ++j) {
    for (int i = 0; i < grid; ++i) {
      const double s = points.u(i), t = points.v(j);
      if (i == 0) {
        points(i, j) = boundary.left().at(t);
      } else if (i == grid - 1) {
        points(i, j) = boundary.right().at(t);
      } else if (j == 0) {
        points(i, j) = boundary.bottom().at(s);
      } else if (j == grid - 1) {
        points(i, j) = boundary.top().at(s);
      } else {
        const Vec3 correction = (1.0 - t) * bottom(s) + t * top(s) + (1.0 - s) * left(t) + s * right(t) -
                                ((1.0 - s) * (1.0 - t) * c00 + s * (1.0 - t) * c10 + (1.0 - s) * t * c01 + s * t * c11);
        points(i, j) = on_parent(s, t) + correction;
      }
    }
  }
  Patch child{BaseSurface(std::move(boundary), points)};
  child.grid = std::move(points);
  child.level = parent.level + 1;
  child.parent = parent.id;
  child.rect = rect;
  return child;
}

}  // namespace

std::array<Patch, 4> subdivide_patch(const Patch& parent, const DirectedProjector& projector, double gamma, int grid, const RefinementSettings& refinement) {
  if (grid < 2) fail(ErrorCode::InvalidArgument, "subdivide_patch: grid must be at least 2, got " + std::to_string(grid));
  const BaseSurface& surface = parent.surface;
  const Boundary& boundary = surface.boundary();

  // A1.2: the outer sides split at their arc-length midpoints.
  const auto bottom = boundary.bottom().split(0.5);
  const auto right = boundary.right().split(0.5);
  const auto top = boundary.top().split(0.5);
  const auto left = boundary.left().split(0.5);

  // A1.1: the middle curves, meeting at the projected centre.
  const Vec3 centre = projected_centre(surface, projector);
  const SplitCurve u_half = project_middle_curve(
      surface, [](double t) { return Vec2(0.5, t); }, bottom.first.back(), centre, top.first.back(), projector, gamma, refinement, "u = 1/2");
  const SplitCurve v_half = project_middle_curve(
      surface, [](double t) { return Vec2(t, 0.5); }, left.first.back(), centre, right.first.back(), projector, gamma, refinement, "v = 1/2");

  // A1.3/A1.4: the children, sharing the middle curves' halves as seams.
  const Rect& r = parent.rect;
  const double um = 0.5 * (r.u0 + r.u1), vm = 0.5 * (r.v0 + r.v1);
  return {{
      make_child(parent, Boundary(bottom.first, u_half.first, v_half.first, left.first), 0.0, 0.0, grid, Rect{r.u0, r.v0, um, vm}),
      make_child(parent, Boundary(bottom.second, right.first, v_half.second, u_half.first), 0.5, 0.0, grid, Rect{um, r.v0, r.u1, vm}),
      make_child(parent, Boundary(v_half.first, u_half.second, top.first, left.second), 0.0, 0.5, grid, Rect{r.u0, vm, um, r.v1}),
      make_child(parent, Boundary(v_half.second, right.second, top.second, u_half.second), 0.5, 0.5, grid, Rect{um, vm, r.u1, r.v1}),
  }};
}

}  // namespace dbs
