// Nonlinear refinement of a projected curve with Ceres (issue 11, DESIGN.md decision 5).
//
// The linear solve (curve_projection.hpp) evaluates the weights of eq. (5) once, at the node
// where it starts; a node far from a curved cloud then sees a mean biased towards the near
// side, and a least-squares fit lets gross outliers pull the curve. The refinement starts
// from the linear solution and minimizes the linear solve's own objective, in units of h,
// except that each node's weights are those of its current position q_k = p_k + t_k n_k:
//
//   sum_k w_k(q_k) ((q_k - m_k(q_k)).n_k)^2  +  gamma (L / s^2 + C / s^4)
//
// where m_k(q) is the weighted mean of the points near the node's line, each point weighted
// by a_mu(q) = 1 / (1 + r^2 rho_mu^2) of eq. (5) (r = |q - p_mu|, rho_mu the point's distance
// to the line, both in h) times the robust loss's weight rho'(d_mu^2) of its offset d_mu along
// the line (robust_loss.hpp; 1 without a loss), w_k(q) = (1 - gamma) c0 / (c0 + 1) the linear
// solve's data weight for c0 the sum of those weights, and L, C the slope and curvature sums
// of the linear solve per node spacing s. With the weights frozen at the start, the data term
// is w_k |q_k - m_k|^2 of the linear solve less a constant (the part across the line), so one
// Gauss-Newton step from the start is the linear solution. With the weights following the
// node, a node settles at the mean of its own neighbourhood as seen from where it ends up (a
// zero residual), which the linear solve reaches only when it starts there; the robust
// weights make that mean an M-estimate that gross outliers barely move. With a loss the
// refinement first settles without it: a loss that flattens beyond its scale would hold a
// node that starts farther than the scale from the cloud where it is.
//
// Each node moves along its own direction (one unknown; fixed and end nodes do not move) and
// at most RefinementSettings::reach h (or two node spacings if more) from where it started
// (Ceres parameter bounds): the points near its line are gathered there. A node that gets
// near its bound starts another round from where it got to (at most four), so a linear
// solution far off the cloud is still reached. Ceres runs single-threaded (callers run patches in
// parallel), so the result is the same for any thread count. Only curve_refinement.cpp knows
// Ceres; in a build without it, refine_curve throws Error(Unsupported).
#pragma once
#include <cstddef>
#include <vector>

#include "curve_projection.hpp"
#include "robust_loss.hpp"

namespace dbs {

struct RefinementSettings {
  bool enabled = false;               // false: the linear solve alone
  LossKind loss = LossKind::None;
  double loss_scale = 1.0;            // the loss's scale a, in units of h (> 0)
  int max_iterations = 25;            // Ceres iterations per solve (a curve takes 1-4 rounds)
  double function_tolerance = 1e-6;   // Ceres's relative cost change to stop at
  double trust_region_radius = 1e4;   // Ceres's initial trust region (1e16: Gauss-Newton)
  bool freeze_weights = false;        // weights of the start kept (the linear objective)
  double reach = 4.0;                 // how far a node may move, in h (at least two node spacings)
};

/// What the refinements of a patch did.
struct RefinementCounts {
  std::size_t curves = 0;      // curves refined
  std::size_t iterations = 0;  // Ceres iterations over them
};

/// Whether this build has the Ceres refinement.
bool ceres_available();

/// Offsets t_k (cloud units) of the refined curve, starting from `start_offsets` (usually
/// the linear solution; t = 0 for fixed nodes). `counts`, when given, is added to. Throws
/// like project_curve for bad input, Error(InvalidArgument) for a wrong number of start
/// offsets or settings outside their ranges, Error(Unsupported) without Ceres.
std::vector<double> refine_curve(const DirectedProjector& projector, const CurveProjectionInput& input, double gamma, const std::vector<double>& start_offsets, const RefinementSettings& settings, RefinementCounts* counts = nullptr);

/// The linear solve, refined when settings.enabled.
std::vector<double> solve_curve(const DirectedProjector& projector, const CurveProjectionInput& input, double gamma, const RefinementSettings& settings, RefinementCounts* counts = nullptr);

}  // namespace dbs
