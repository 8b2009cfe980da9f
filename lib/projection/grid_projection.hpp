// Grid projection (section 5.2): every row and every column of a grid on a base surface is
// projected onto the cloud with the smooth curve projection (A3); each interior grid point
// moves along its surface normal by the mean of its row and column offsets. Border points
// stay on the boundary. Each section is densified to nodes about 2 h apart (at most 512 per
// section, so a very large patch gets a coarser spacing); the sections are projected in
// parallel, each writing only its own offsets, so the result does not depend on the thread
// count. A row and a column both put a node on the grid point where they cross, with its
// unit normal: that ray is cast once, before the sections, and both take its moments
// (CurveProjectionInput::known_moments), the result being the one of each section alone.
#pragma once
#include "base_surface.hpp"
#include "curve_projection.hpp"
#include "curve_refinement.hpp"
#include "pleat_guard.hpp"
#include "work_meter.hpp"

namespace dbs {

/// Node spacing of a densified grid section, in units of h: a few nodes per data feature.
constexpr double kNodeSpacing = 2.0;
/// Most nodes in one section: bounds the cost of a section on a very large patch, where the
/// spacing then grows beyond kNodeSpacing h.
constexpr std::size_t kMaxSectionNodes = 512;

/// Samples `surface` on an nu x nv grid, projects it onto the cloud, returns the projected
/// grid (border points unchanged). `gamma` as in eq. (6). The move is pleat-free
/// (pleat_guard.hpp): `out_damped_nodes`, when given, receives the number of nodes whose
/// offset the guard reduced. With `refinement.enabled`, each section's linear solution is
/// refined with Ceres (curve_refinement.hpp) before the guard; `counts`, when given, is added
/// to. Up to `threads` threads; `meter` (may be null) counts a unit per ray cast (a densified
/// node; a grid point's once).
Grid project_grid(const BaseSurface& surface, int nu, int nv, const DirectedProjector& projector, double gamma, std::size_t* out_damped_nodes = nullptr,
                  const RefinementSettings& refinement = RefinementSettings(), RefinementCounts* counts = nullptr, int threads = 1, WorkMeter* meter = nullptr);

}  // namespace dbs
