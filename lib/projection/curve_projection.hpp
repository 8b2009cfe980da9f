// Smooth polygonal-curve projection (algorithm A3, eqs. 6-9): nodes p_k move along their
// directions n_k to p_k + t_k n_k minimizing (1-gamma) D + gamma (L + C). D is quadratic in
// each t_k through the ray moments, L and C are quadratic in the t's, so the minimizer solves
// one banded (pentadiagonal) linear system. Lengths are measured in units of h.
//
// Balance of the terms (the paper leaves it open). Everything is measured in units of h, so
// the input's unit drops out. Two choices then fix the balance:
// - Data weight. The paper's E(p*_k) = c0_k |p*_k - m_k|^2 + const carries c0_k = sum a_mu,
//   which grows with the number of points near the ray: taken raw, a thick cloud would drown
//   the smoothing. Each node's data term is weighted w_k = c0_k / (c0_k + 1) instead: about
//   0.8 for a node on a surface cloud (c0 ~ pi^2/2 at one point per h^2, eq. 5 in units of
//   h), saturating at 1 for denser or thicker clouds, and tending to 0 where the ray meets no
//   points (c0 -> 0), so that a node over a hole is placed by L + C alone and bridges it.
// - Node spacing. The sums of (8) and (9) grow with the number of nodes and their
//   differences with the node spacing s (in h), so the same gamma would smooth more when the
//   curve is densified more coarsely. L and C are therefore taken per spacing, L / s^2 and
//   C / s^4 (slope and curvature in units of h): the minimizer then approximates that of
//   (1-gamma) int w d^2 + gamma int (|q'|^2 + |q''|^2) along the curve, whatever the
//   densification. With gamma = 1/2 and w ~ 0.8 the smoothing acts over about one h; a curve
//   of curvature kappa is drawn inwards by about 1.25 kappa h^2.
#pragma once
#include <vector>

#include "directed_projection.hpp"

namespace dbs {

struct CurveProjectionInput {
  std::vector<Vec3> nodes;       // K >= 2 nodes p_k
  std::vector<Vec3> directions;  // K directions n_k (unit)
  std::vector<std::size_t> fixed;  // indices of interior nodes that must not move (ends always fixed)
  /// Empty, or K entries: the ray moments of node k already taken (projector.moments(p_k,
  /// n_k), the same numbers), or null where project_curve takes them itself. A grid's row and
  /// column cross at its points, and both would otherwise cast the same ray there.
  std::vector<const RayMoments*> known_moments;
};

/// Offsets t_k (t = 0 for fixed nodes). Nodes whose ray meets no cloud weight follow the
/// smoothing terms alone (a hole keeps the curve's shape). gamma in [0,1]. Throws
/// Error(InvalidArgument) for K < 2 or mismatched sizes, Error(OutOfRange) for a fixed index
/// >= K or gamma outside [0,1], and Error(Numerical) only if the system is singular, which
/// the fixed ends prevent unless gamma = 0 leaves a node without data and without smoothing.
std::vector<double> project_curve(const DirectedProjector& projector, const CurveProjectionInput& input, double gamma);

/// Mean distance between consecutive nodes (K >= 2) in units of h: the spacing s the
/// smoothing terms are taken per; 1 for a curve collapsed to a point.
double node_spacing(const std::vector<Vec3>& nodes, double h);

/// A3.1: densify a polygon of m >= 2 points to nodes at a near-constant spacing such that
/// every original point is a node: a segment of length l gets round(l / spacing) sub-segments
/// (at least 1, at most max_nodes_per_segment). Directions are interpolated linearly and
/// renormalized. out_original[i] is the node index of point i. No fixed nodes are set.
CurveProjectionInput densify_polygon(const std::vector<Vec3>& points, const std::vector<Vec3>& directions, double spacing, std::vector<std::size_t>& out_original, std::size_t max_nodes_per_segment = 64);

}  // namespace dbs
