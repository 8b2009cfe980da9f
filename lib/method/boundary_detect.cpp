#include "boundary_detect.hpp"

#include <limits>
#include <string>

#include "boundary_from_loop.hpp"
#include "error.hpp"
#include "number_text.hpp"
#include "outline_corners.hpp"

namespace dbs {

namespace {

std::vector<std::vector<Vec3>> hole_points(const Outline& outline) {
  std::vector<std::vector<Vec3>> holes;
  for (const OutlineLoop& hole : outline.holes) holes.push_back(hole.points);
  return holes;
}

DetectedBoundary cut(const Outline& outline, const std::array<std::size_t, 4>& corners) {
  const OutlineLoop& loop = outline.outer;
  DetectedBoundary out{boundary_from_loop(loop.points, corners), {}, hole_points(outline)};
  for (int c = 0; c < 4; ++c) out.corner_points[static_cast<std::size_t>(c)] = loop.sources[corners[static_cast<std::size_t>(c)]];
  return out;
}

}  // namespace

DetectedBoundary detect_boundary(const std::vector<Vec3>& points, std::size_t neighbours, int threads) {
  const Outline outline = find_outline(points, neighbours, threads);
  const std::array<std::size_t, 4> in_loop_order = outline_corners(outline.outer);
  const std::vector<std::size_t>& source = outline.outer.sources;
  std::size_t first = 0;
  for (std::size_t c = 1; c < 4; ++c)
    if (source[in_loop_order[c]] < source[in_loop_order[first]]) first = c;
  const bool forward = source[in_loop_order[(first + 1) % 4]] < source[in_loop_order[(first + 3) % 4]];
  std::array<std::size_t, 4> corners{};
  for (std::size_t c = 0; c < 4; ++c) corners[c] = in_loop_order[(first + (forward ? c : 4 - c)) % 4];
  return cut(outline, corners);
}

DetectedBoundary boundary_from_corners(const std::vector<Vec3>& points, const std::array<Vec3, 4>& corners, std::size_t neighbours, int threads) {
  for (int c = 0; c < 4; ++c)
    if (!is_finite(corners[static_cast<std::size_t>(c)])) fail(ErrorCode::NonFinite, "corner " + std::to_string(c) + " has a non-finite coordinate");
  const Outline outline = find_outline(points, neighbours, threads);
  const std::vector<Vec3>& loop = outline.outer.points;
  std::array<std::size_t, 4> snapped{};
  for (std::size_t c = 0; c < 4; ++c) {
    double nearest = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < loop.size(); ++i) {
      const double d = (loop[i] - corners[c]).norm();
      if (d < nearest) {
        nearest = d;
        snapped[c] = i;
      }
    }
    if (nearest > kMaxCornerOffset * outline.outer.perimeter)
      fail(ErrorCode::InvalidArgument, "corner " + std::to_string(c) + " lies " + shortest_text(nearest) + " from the cloud's outline (perimeter " + shortest_text(outline.outer.perimeter) +
                                           "): not a point of it");
    for (std::size_t k = 0; k < c; ++k)
      if (snapped[k] == snapped[c]) fail(ErrorCode::InvalidArgument, "corners " + std::to_string(k) + " and " + std::to_string(c) + " meet at one point of the outline");
  }
  return cut(outline, snapped);
}

}  // namespace dbs
