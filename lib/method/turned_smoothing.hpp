// Smoothing of the (u,v) on turned sheets (DBS_OPT_SMOOTH_TURNED). Where a leaf's surface is
// turned against the cloud (turned_sheets.hpp: under an overhang, up a steep wall, where
// leaves meet at the foot of a feature), the orthogonal feet of neighbouring points jump
// about in (u,v) and their triangles fold, while the (u,v) of their neighbourhood as a whole
// follows the cloud. Each point on such a sheet and each of its kSmoothingNeighbours nearest
// points takes the (u,v) that a least-squares affine map of its neighbourhood predicts for it,
// then the leaves they land on are refitted to their points (leaf_refit.hpp).
//
// The neighbourhood: the point's kSmoothingNeighbours nearest points whose oriented normal
// (the fold measure's) lies within 60 degrees of its own, so that the other face of a thin
// flap (a finger's, a mushroom cap's underside) does not take part; their offsets are laid
// into the plane of their principal axes at their own length ("unfolded": a crease's other
// side keeps its distance instead of being foreshortened). A neighbourhood that is not flat
// (smallest principal variance over the middle one above kFlatNone: an apex, a finger's tip)
// leaves the point where it is, and the step is scaled down from kFlatFull to kFlatNone so
// that smoothed and unsmoothed points meet without a seam. Points on the domain's edge,
// clamped points and the repair's outliers stay; the new (u,v) are computed from the old ones
// (every point reads the same state), so the result does not depend on the thread count.
//
// Measured with dbs-bench-folds (48 clean runs: 12 shapes x densities 1-2.5; 40 noisy ones),
// each run's smoothing kept only when its mean distance stays within the larger of the one
// before and the target and the run does not stop meeting the target (the driver's rule): folded
// reference triangles 440 -> 301 clean and 1,463 -> 1,145 noisy; the 6,084-point mushroom 22 ->
// 1, the 10,201-point tall dome 90 -> 1 (the 10,201-point mushroom is undone: its leaves miss
// the target already). The cost: points on turned sheets +16% / +19% (the refits bend the leaves
// to the moved points), the mean distance about the same (geometric mean x1.01), and four runs
// fold 1-3 triangles more. Not on by default for that cost (see NEWS.md).

#pragma once
#include <cstddef>
#include <vector>

#include "cloud_index.hpp"
#include "result.hpp"
#include "work_meter.hpp"

namespace dbs {

constexpr std::size_t kSmoothingNeighbours = 24;  ///< neighbourhood of the affine prediction, and the ring around each turned point
constexpr double kSmoothingSheetCosine = 0.5;     ///< a neighbour's oriented normal within 60 degrees of the point's
constexpr double kFlatFull = 0.1;                 ///< smallest / middle principal variance up to which the point takes the whole step ...
constexpr double kFlatNone = 0.4;                 ///< ... and from which it stays where it is
constexpr std::size_t kMinSmoothingPoints = 6;    ///< fewer neighbours on the point's sheet: it stays

/// What smooth_turned_sheets did: the points it moved (whose (u,v) changed), the leaves it refitted, and every leaf
/// whose points changed (those the moved points left or entered, and the refitted ones), in
/// increasing order.
struct TurnedSmoothing {
  std::size_t moved = 0;
  std::vector<int> refitted;
  std::vector<int> touched;
};

/// Smooths the (u,v) of the points flagged in `turned` and of their kSmoothingNeighbours nearest
/// points, as the header says, and refits the leaves they land on (`index`: of all `points`).
/// `normals` is each point's oriented normal (zero: none; such a point neither moves nor
/// counts as a neighbour) and `outlier` flags points that neither move nor take part (the
/// repair's: left out of the result, far points standing alone). A point whose leaf is not
/// refitted (its fit failed, or would have moved the surface away from most of its points)
/// keeps its new (u,v), at its distance to the surface there; a prediction beyond the domain
/// is clamped onto its edge. Throws Error(InvalidArgument) for flags or normals not of every
/// point. Every point counts a unit of work on `meter` (optional), where a cancel takes
/// effect.
TurnedSmoothing smooth_turned_sheets(Result& result, const std::vector<Vec3>& points, const CloudIndex& index, const std::vector<char>& turned, const std::vector<Vec3>& normals,
                                     const std::vector<char>& outlier, int threads, WorkMeter* meter = nullptr);

}  // namespace dbs
