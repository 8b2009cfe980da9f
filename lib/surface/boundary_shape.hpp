// The shape checks of a boundary's own geometry: its four sides must form a simple loop.
// A side that folds back on itself, or a loop that crosses (or touches) itself, bounds no
// patch a surface can fill without folding, so the boundary is refused at creation.
#pragma once
#include <array>

#include "polyline.hpp"

namespace dbs {

/// A side folds back on itself where its direction over the stretch before a point and its
/// direction over the stretch after it (each kFoldWindow of the side's length, or one
/// segment where the points are sparser) differ by more than kFoldAngleDegrees: it runs
/// back over itself for a noticeable part of its length (a back-step of a few points of a
/// noisy or detected side does not count).
constexpr double kFoldAngleDegrees = 160.0;
constexpr double kFoldWindow = 0.05;

/// Two parts of the loop that cross in the projection along the normal of the loop's
/// best-fit plane cross in fact when they are closer than this fraction of the boundary's
/// size in 3D (a loop that only seems to cross, its strands far apart along the normal, as
/// the rim of a strongly curved part seen from one side, is accepted).
constexpr double kCrossingGap = 0.01;

/// A crossing that closes a curl of the loop shorter than this fraction of the loop's
/// length (a small knot of a side, as an outline found from a scan may have near a corner)
/// is tolerated: what is refused is a loop crossing itself at large, as a bow-tie does.
constexpr double kCurlLength = 0.05;

/// Throws Error(Degenerate) for a side folding back (naming it, the point and the angle) or
/// for a loop crossing itself (naming the two sides, their points and where, in 3D and in
/// the best-fit plane). `sides` in the order bottom, right, top, left, with the corners
/// shared as in FORMATS.md; `size` is the boundary's bounding-box diagonal (> 0).
void check_boundary_shape(const std::array<Polyline, 4>& sides, double size);

}  // namespace dbs
