// Moves that leave the cloud. The directed projection (eq. 3) moves a node to the weighted
// mean of the points near its ray. Where the ray grazes the cloud (the current surface
// crosses the cloud steeply: near a small rim the patch surface is stretched and its normal
// runs along the sheet), the points along the ray all weigh about the same and the mean
// lies many spacings away along the sheet: a node that sat on the cloud is sent off it, and
// a seam or grid line through it forms a spike (measured: 46 h on the 270-degree sphere cap,
// where the parent surface fitted to 0.17 h; the children sampled from it fitted 3.5x worse
// than their parent and folded 5.8% of the surface).
//
// The guard holds such a node where it is: a node that would end farther from its nearest
// cloud point than it started, by more than a tolerance, becomes a fixed node of the curve
// and the curve is solved again (its neighbours then follow the smoothing terms around it).
// A node approaching the cloud, or moving across a hole (its distance to the cloud changes
// little), is never held. The guard is applied to the seams of a subdivision, which are final
// boundaries of the children, and to the patch centre they share (departs()). (On the grid sections it was tried and rejected: a grid is
// projected again at every size and the pleat guard judges its cells, and holding nodes there
// kept the 270-degree cap from wrapping: 330 reference folds against 4.)
#pragma once
#include <cstddef>
#include <vector>

#include "curve_projection.hpp"
#include "curve_refinement.hpp"

namespace dbs {

/// How much farther from its nearest cloud point a node may end than it started, in h.
constexpr double kDepartureTolerance = 1.0;

/// Whether moving a point from `from` to `to` takes it more than kDepartureTolerance h farther
/// from its nearest point of projector.index() (false for an empty index).
bool departs(const DirectedProjector& projector, const Vec3& from, const Vec3& to);

/// Appends to input.fixed the free interior nodes whose move by offsets[k] along
/// input.directions[k] takes them more than `tolerance` (cloud units) farther from their
/// nearest point of projector.index(); returns how many. Error(InvalidArgument) for offsets
/// or directions not one per node, Error(OutOfRange) for a fixed index beyond the nodes.
std::size_t hold_departing_nodes(const DirectedProjector& projector, CurveProjectionInput& input, const std::vector<double>& offsets, double tolerance);

/// solve_curve (curve_refinement.hpp), the nodes it would send off the cloud held and the
/// curve solved again, until no node departs (at most a few rounds; `input.fixed` keeps the
/// held nodes). `out_held`, when given, is added the number of nodes held. The solve of each
/// round (the Ceres refinement too, when settings.enabled) is judged, so a held node stays
/// where it was in every later round.
std::vector<double> solve_curve_near(const DirectedProjector& projector, CurveProjectionInput& input, double gamma, const RefinementSettings& settings, RefinementCounts* counts = nullptr,
                                     std::size_t* out_held = nullptr);

}  // namespace dbs
