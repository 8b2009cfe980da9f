// The body of a cloud and the points far outside it: a point 1e9 (or 1e160, 1e300) away
// from a unit-size scan is a glitch of the scanner or the export, not part of the surface.
// Left in, it would decide the relative target (the cloud's size), the spacing h and every
// mean, and overflow the arithmetic of distances. The body is what lies within kFarOutside
// times the cloud's extent of the box between its kBodyQuantile and 1 - kBodyQuantile
// coordinate quantiles, measured in the boundary's corner frame (so that a rigid motion of
// the input changes nothing); a cloud without such points is all body, and its size is then
// exactly the diagonal of its box, as before.
#pragma once
#include <cstddef>
#include <vector>

#include "boundary.hpp"
#include "geometry.hpp"

namespace dbs {

constexpr double kBodyQuantile = 0.01;       ///< the central box: between these coordinate quantiles
constexpr double kFarOutside = 10.0;         ///< far: beyond this x the cloud's extent from the central box
constexpr std::size_t kBodySample = 100000;  ///< quantiles from at most this many evenly strided points

struct CloudBody {
  std::vector<std::size_t> body;  ///< indices of the points of the body, increasing
  std::vector<char> far;          ///< per point: 1 when far outside the body
  double diagonal = 0.0;          ///< diagonal of the body's box in the corner frame
};

/// The body of `points` (at least one) in the frame of `boundary`'s corners.
CloudBody cloud_body(const std::vector<Vec3>& points, const Boundary& boundary);

}  // namespace dbs
