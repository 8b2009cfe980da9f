// A start for the root surface from a meshless parameterization of its cloud. The root
// evolves from the Coons patch of its boundary along that surface's normals; on a cloud that
// closes over a small rim (a head open only at its neck, a sphere cap of 330 degrees) the
// rays from the small disk the rim spans never reach the far side of the cloud, and however
// the grids warm up the surface does not wrap it (330-degree cap: the root's error 0.74-0.83,
// the final mean distance 0.15-0.17 once the repair had filled nearly every point, against a
// target of 0.0034). A meshless map does not need the surface to reach anything:
// each point the inverse-distance mean of its k nearest points' (u,v), the points nearest the
// boundary's vertices fixed on the boundary (after Floater and Reimers, "Meshless
// parameterization and surface reconstruction", 2001; one sparse solve), and the root's grid
// fitted to the points at those (u,v) (grid_fit.hpp) lies on the cloud (the same cap, an
// 11 x 11 fit: 0.0044).
// It folds where the map does, so it is only a start: the evolution then projects grids from
// it as from any other surface.
#pragma once
#include <cstddef>
#include <vector>

#include "patch.hpp"
#include "work_meter.hpp"

namespace dbs {

constexpr std::size_t kSeedPoints = 8192;  ///< most points of the root's subcloud the map is solved for (evenly strided)
constexpr std::size_t kSeedNeighbours = 12;  ///< k of the inverse-distance weights
constexpr double kSeedBoundarySpacings = 3.0;  ///< a boundary position is on the cloud within this many spacings of the sample ...
constexpr double kSeedBoundaryShare = 0.9;     ///< ... and the map is solved only when this share of them is
constexpr double kSeedBeyondShare = 0.2;      ///< ... and the median share of the points near it beyond the boundary is at most this (0 on a border, 1/2 across a cloud)
constexpr std::size_t kSeedBorderNeighbours = 48;  ///< "near it": its nearest sample points, their plane wide enough to stand above noise of half a spacing
constexpr int kMaxSeedGrid = 23;               ///< the largest grid the fit takes (grid_fit.hpp: kMaxRefitNodes)

/// Fits `patch`'s grid, resampled to grid x grid (3 <= grid <= kMaxSeedGrid), to the meshless
/// map of (a sample of) its subcloud points[patch.subcloud] and its boundary; the map's (u,v)
/// are mapped onto patch.rect. Its sides are walked at the sample's spacing and the sample
/// point nearest each position is fixed there, where it lies within kSeedBoundarySpacings;
/// points with no path of neighbours to a fixed one (a detached clump) are left out of the
/// map and the fit. False, the patch untouched, when the subcloud has too few points, they
/// all coincide, the boundary does not lie on the cloud (fewer than kSeedBoundaryShare of
/// its positions within reach) or is not its border (a median share above kSeedBeyondShare
/// of the points near its positions lie beyond it: a cloud larger than its boundary), the
/// sparse solve fails or the fit fails. `meter` (may be null) counts a unit per sample point
/// whose neighbours are looked up and per boundary position; what it throws (Error(Cancelled))
/// is the only exception but std::bad_alloc, the patch then untouched too.
bool seed_from_meshless_map(Patch& patch, const std::vector<Vec3>& points, int grid, WorkMeter* meter = nullptr);

}  // namespace dbs
