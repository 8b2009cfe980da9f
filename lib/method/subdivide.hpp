// Algorithm A1 (steps A1.1-A1.4): split a patch into four children. The middle curves
// u = 1/2 and v = 1/2 of the parent surface are sampled and projected onto the parent's
// subcloud with the smooth curve projection (A3), repeated from the projected nodes until it
// settles (the seams are final boundaries of the children), a node the projection would send
// off the cloud held where it is (departure_guard.hpp); the patch centre is projected
// once for both curves and is a fixed interior node of each, so the curves meet there. The
// outer sides are split at their arc-length midpoints, the middle curves at the centre.
// Children share the middle curves' halves as boundaries (seams C0 by construction); their
// initial surfaces interpolate grids sampled from the parent surface over their quarter.
#pragma once
#include <array>

#include "curve_refinement.hpp"
#include "directed_projection.hpp"
#include "patch.hpp"

namespace dbs {

/// Children in the order (u-,v-), (u+,v-), (u-,v+), (u+,v+), with level, parent and rect set
/// (id left for the caller). `projector` indexes the parent's subcloud; `grid` is the
/// children's initial grid size per side. With `refinement.enabled` each middle curve's
/// linear projection is refined with Ceres (curve_refinement.hpp) once it has settled.
std::array<Patch, 4> subdivide_patch(const Patch& parent, const DirectedProjector& projector, double gamma, int grid, const RefinementSettings& refinement = RefinementSettings());

}  // namespace dbs
