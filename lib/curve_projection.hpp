// Smooth polygonal-curve projection (algorithm A3, eqs. 6-9): nodes p_k move along their
// directions n_k to p_k + t_k n_k minimizing (1-gamma) D + gamma (L + C). D is quadratic in
// each t_k through the ray moments, L and C are quadratic in the t's, so the minimizer solves
// one banded (pentadiagonal) linear system. Lengths are measured in units of h.
#pragma once
#include <vector>

#include "directed_projection.hpp"

namespace dbs {

struct CurveProjectionInput {
  std::vector<Vec3> nodes;       // K >= 2 nodes p_k
  std::vector<Vec3> directions;  // K directions n_k (unit)
  std::vector<std::size_t> fixed;  // indices of interior nodes that must not move (ends always fixed)
};

/// Offsets t_k (t = 0 for fixed nodes). Nodes whose ray meets no cloud weight follow the
/// smoothing terms alone (a hole keeps the curve's shape). Throws Error(Numerical) only if
/// the system is singular, which the fixed ends prevent.
std::vector<double> project_curve(const DirectedProjector& projector, const CurveProjectionInput& input, double gamma);

/// A3.1: densify a polygon of m points to nodes at a near-constant spacing such that every
/// original point is a node: segment s gets `per_segment[s]` sub-segments. Directions are
/// interpolated linearly and renormalized. out_original[i] is the node index of point i.
CurveProjectionInput densify_polygon(const std::vector<Vec3>& points, const std::vector<Vec3>& directions, double spacing, std::vector<std::size_t>& out_original, std::size_t max_nodes_per_segment = 64);

}  // namespace dbs
