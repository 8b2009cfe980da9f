// The last step of a patch's evolution that misses the target: its grid fitted by least
// squares to its error sample at their feet. The grid projection (eq. 5) moves each node to a
// weighted mean of the points near its ray, which leaves a patch's surface short of where a
// fit of the same grid to the same points would lie: on the 4,096-point sphere cap of
// dbs-bench-folds the root's largest grid ends at 1.9 times the target, and a fit at the
// sample's feet lies within 0.56 times it. Such a patch need not be subdivided: fewer
// patches and levels, fewer seams for points to fold across, and less time (the caps from
// 89-209 patches to one; rippled 1M of dbs-bench from 21 patches to 5). The fit is kept only
// where it comes clearly below the target (kFitMargin of it: the caps' fits reach 0.56-0.61,
// rippled 1M's 0.79, while the fits that only just met it were plate leaves of the noisy
// fingers at 6 times dbs-bench-folds' points, 0.88-1.00 of their target, which the noise
// floor had raised: the fit shaved their noise and spared them the deeper leaves that follow
// the fingers' walls, 826 -> 1,562 folded reference triangles), and only where it turns the
// surface under no sample point
// (Su x Sv at its foot against the projected surface's at the point's foot there: an
// unguarded fit pleats where the sample is thin, as on the mushroom and the tall dome,
// where it was tried on every patch above the target and folded 3,805 instead of 437
// reference triangles over 60 clouds). The grid must be carried by its data: at least
// kFitPointsPerNode sample points a node it moves (fits of an 11 x 11 grid to a few dozen
// points of a deep leaf passed through them and collapsed others between them on the cone).
// Also on noisy clouds (whose target the noise floor raised): without the fit the noisy
// rippled field of dbs-bench-folds chased its noise down to 5 levels at 4,096 points and
// missed the target; with it, 2 levels like the clean field (its fits reach 0.71-0.76).
// The fit is judged on the points it was fitted to: with at least 4 of them a node (the
// sample holds up to 8,192 points, the largest default grid 81 moved nodes) the optimism is
// small, and a leaf is judged again on all its points by the projection of A2. The fit is
// plain least squares also under a robust loss (the target is then judged on the loss), and
// grids above 23 x 23 are not fitted (kMaxRefitNodes, grid_fit.hpp).
#pragma once
#include <cstddef>
#include <vector>

#include "evolve.hpp"

namespace dbs {

constexpr double kFitPointsPerNode = 4.0;  ///< sample points a moved grid node, at least
constexpr double kFitReach = 4.0;          ///< a fit is tried from at most this x the target ...
constexpr double kFitMargin = 0.85;        ///< ... and kept when it reaches this x the target

/// Fits `patch` (evolved, its error `error` above settings.accuracy, measured on the whole
/// sample) to the sample points patch.subcloud[k * stride] at their feet feet[k] on its
/// surface (local parameters; NaN: not measured, left out), as described above. When the
/// fit is kept, patch's surface and grid are the fitted ones and mean, max and error those
/// of the sample on it; otherwise nothing changes. True when kept. Deterministic for any
/// thread count.
bool fit_to_target(Patch& patch, const std::vector<Vec3>& points, std::size_t stride, const std::vector<Vec2>& feet, const EvolveSettings& settings, double& mean, double& max,
                   double& error);

}  // namespace dbs
