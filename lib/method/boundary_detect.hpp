// Four-sided boundaries from a scan itself: its outline (outline.hpp) cut at four corners,
// found where it turns most (outline_corners.hpp) or given as points near it.
#pragma once
#include <array>
#include <cstddef>
#include <vector>

#include "boundary.hpp"
#include "outline.hpp"

namespace dbs {

/// A given corner farther than this fraction of the outline's perimeter from it is not taken
/// for one of its points.
constexpr double kMaxCornerOffset = 0.05;

struct DetectedBoundary {
  Boundary boundary;
  std::array<std::size_t, 4> corner_points;  ///< cloud points the corners (0,0), (1,0), (1,1), (0,1) were smoothed from
  std::vector<std::vector<Vec3>> holes;      ///< the inner loops, each closed (first point not repeated)
};

/// The outer loop of the outline cut at its four corners. Of the corners (in loop order), the
/// one smoothed from the lowest cloud index becomes (0,0), and the bottom runs towards the
/// neighbouring corner of the lower cloud index: the same choice for the cloud moved,
/// rotated or scaled. Throws what find_outline and outline_corners throw.
DetectedBoundary detect_boundary(const std::vector<Vec3>& points, std::size_t neighbours, int threads);

/// The outer loop cut at the loop points nearest to `corners`, which become (0,0), (1,0),
/// (1,1), (0,1) (they must follow each other around the outline, in either direction).
/// Throws Error: InvalidArgument (two corners at one loop point, corners not in cyclic
/// order, a corner farther than kMaxCornerOffset of the perimeter from the outline),
/// NonFinite, and what find_outline throws.
DetectedBoundary boundary_from_corners(const std::vector<Vec3>& points, const std::array<Vec3, 4>& corners, std::size_t neighbours, int threads);

}  // namespace dbs
