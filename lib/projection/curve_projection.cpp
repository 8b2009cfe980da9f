#include "curve_projection.hpp"

#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>

#include <algorithm>
#include <cmath>
#include <string>

#include "error.hpp"
#include "number_text.hpp"

namespace dbs {

namespace {

/// The normal equations of the least-squares problem in the free offsets (t in units of h).
/// Every term of (1-gamma) D + gamma (L + C) is omega |d + sum_j c_j t_j n_j|^2 over at most
/// three consecutive nodes; fixed nodes have t = 0 and drop out, so the matrix stays banded.
class NormalEquations {
 public:
  NormalEquations(const CurveProjectionInput& input, const std::vector<long>& free_index)
      : input_(input), free_(free_index), rhs_(Eigen::VectorXd::Zero(count_free(free_index))) {}

  template <int M>
  void add(double omega, const std::size_t (&nodes)[M], const double (&coeffs)[M], const Vec3& d) {
    for (int a = 0; a < M; ++a) {
      const long fa = free_[nodes[a]];
      if (fa < 0) continue;
      const Vec3& na = input_.directions[nodes[a]];
      rhs_[fa] -= omega * coeffs[a] * na.dot(d);
      for (int b = 0; b < M; ++b) {
        const long fb = free_[nodes[b]];
        if (fb < 0) continue;
        triplets_.emplace_back(fa, fb, omega * coeffs[a] * coeffs[b] * na.dot(input_.directions[nodes[b]]));
      }
    }
  }

  Eigen::VectorXd solve() const {
    const Eigen::Index n = rhs_.size();
    Eigen::SparseMatrix<double> matrix(n, n);
    matrix.setFromTriplets(triplets_.begin(), triplets_.end());
    // Natural ordering keeps the pentadiagonal band: the factor has no fill-in.
    Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>, Eigen::Lower, Eigen::NaturalOrdering<int>> solver(matrix);
    if (solver.info() != Eigen::Success) fail(ErrorCode::Numerical, "project_curve: the curve system is singular");
    Eigen::VectorXd t = solver.solve(rhs_);
    if (solver.info() != Eigen::Success || !t.allFinite()) fail(ErrorCode::Numerical, "project_curve: the curve system has no finite solution");
    return t;
  }

 private:
  static Eigen::Index count_free(const std::vector<long>& free_index) {
    return std::count_if(free_index.begin(), free_index.end(), [](long f) { return f >= 0; });
  }

  const CurveProjectionInput& input_;
  const std::vector<long>& free_;
  Eigen::VectorXd rhs_;
  std::vector<Eigen::Triplet<double>> triplets_;
};

void check_input(const CurveProjectionInput& input, double gamma) {
  const std::size_t k = input.nodes.size();
  if (k < 2) fail(ErrorCode::InvalidArgument, "project_curve: " + std::to_string(k) + " nodes, at least 2 needed");
  if (input.directions.size() != k)
    fail(ErrorCode::InvalidArgument, "project_curve: " + std::to_string(input.directions.size()) + " directions for " + std::to_string(k) + " nodes");
  for (std::size_t f : input.fixed)
    if (f >= k) fail(ErrorCode::OutOfRange, "project_curve: fixed node " + std::to_string(f) + " is not below the node count " + std::to_string(k));
  if (!input.known_moments.empty() && input.known_moments.size() != k)
    fail(ErrorCode::InvalidArgument, "project_curve: " + std::to_string(input.known_moments.size()) + " known moments for " + std::to_string(k) + " nodes");
  if (!(gamma >= 0.0 && gamma <= 1.0)) fail(ErrorCode::OutOfRange, "project_curve: gamma = " + significant_text(gamma, 6) + " is outside [0, 1]");
  for (std::size_t i = 0; i < k; ++i)
    if (!is_finite(input.nodes[i]) || !is_finite(input.directions[i])) fail(ErrorCode::NonFinite, "project_curve: node " + std::to_string(i) + " or its direction is not finite");
}

}  // namespace

double node_spacing(const std::vector<Vec3>& nodes, double h) {
  double length = 0.0;
  for (std::size_t k = 0; k + 1 < nodes.size(); ++k) length += (nodes[k + 1] - nodes[k]).norm();
  const double s = length / static_cast<double>(nodes.size() - 1) / h;
  return s > 0.0 ? s : 1.0;
}

std::vector<double> project_curve(const DirectedProjector& projector, const CurveProjectionInput& input, double gamma) {
  check_input(input, gamma);
  const std::size_t k_count = input.nodes.size();
  const double h = projector.length_scale();

  std::vector<long> free_index(k_count, 0);
  free_index.front() = free_index.back() = -1;
  for (std::size_t f : input.fixed) free_index[f] = -1;
  long next = 0;
  for (long& f : free_index)
    if (f == 0) f = next++;

  NormalEquations system(input, free_index);
  for (std::size_t k = 0; k < k_count; ++k) {
    if (free_index[k] < 0) continue;
    const RayMoments m = input.known_moments.empty() || input.known_moments[k] == nullptr ? projector.moments(input.nodes[k], input.directions[k]) : *input.known_moments[k];
    // Data weight normalized as explained in the header: c0 / (c0 + 1).
    const double weight = (1.0 - gamma) * m.c0 / (m.c0 + 1.0);
    if (!(weight > 0.0) && gamma == 0.0)
      fail(ErrorCode::Numerical, "project_curve: node " + std::to_string(k) + " meets no cloud weight and gamma = 0 leaves it unconstrained");
    if (weight > 0.0) system.add<1>(weight, {k}, {1.0}, (input.nodes[k] - m.mean) / h);
  }
  if (gamma > 0.0) {
    // Differences per node spacing s (in h): L and C then weigh slope and curvature, as
    // explained in the header.
    const double s = node_spacing(input.nodes, h);
    const double slope = gamma / (s * s), curvature = slope / (s * s);
    for (std::size_t k = 0; k + 1 < k_count; ++k) system.add<2>(slope, {k, k + 1}, {1.0, -1.0}, (input.nodes[k] - input.nodes[k + 1]) / h);
    for (std::size_t k = 0; k + 2 < k_count; ++k)
      system.add<3>(curvature, {k, k + 1, k + 2}, {1.0, -2.0, 1.0}, (input.nodes[k] - 2.0 * input.nodes[k + 1] + input.nodes[k + 2]) / h);
  }

  std::vector<double> offsets(k_count, 0.0);
  if (next == 0) return offsets;
  const Eigen::VectorXd t = system.solve();
  for (std::size_t k = 0; k < k_count; ++k)
    if (free_index[k] >= 0) offsets[k] = t[free_index[k]] * h;
  return offsets;
}

CurveProjectionInput densify_polygon(const std::vector<Vec3>& points, const std::vector<Vec3>& directions, double spacing, std::vector<std::size_t>& out_original, std::size_t max_nodes_per_segment) {
  const std::size_t m = points.size();
  if (m < 2) fail(ErrorCode::InvalidArgument, "densify_polygon: " + std::to_string(m) + " points, at least 2 needed");
  if (directions.size() != m)
    fail(ErrorCode::InvalidArgument, "densify_polygon: " + std::to_string(directions.size()) + " directions for " + std::to_string(m) + " points");
  if (!(spacing > 0.0) || !std::isfinite(spacing)) fail(ErrorCode::InvalidArgument, "densify_polygon: spacing = " + significant_text(spacing, 6) + " must be positive and finite");
  if (max_nodes_per_segment < 1) fail(ErrorCode::InvalidArgument, "densify_polygon: max_nodes_per_segment must be at least 1");
  for (std::size_t i = 0; i < m; ++i) {
    if (!is_finite(points[i]) || !is_finite(directions[i])) fail(ErrorCode::NonFinite, "densify_polygon: point " + std::to_string(i) + " or its direction is not finite");
    if (!(directions[i].norm() > 0.0)) fail(ErrorCode::Degenerate, "densify_polygon: direction " + std::to_string(i) + " is zero");
  }

  CurveProjectionInput out;
  out_original.assign(m, 0);
  for (std::size_t s = 0; s + 1 < m; ++s) {
    const Vec3 &a = points[s], &b = points[s + 1];
    const Vec3 da = directions[s].normalized(), db = directions[s + 1].normalized();
    const double pieces = std::round((b - a).norm() / spacing);
    const std::size_t count = static_cast<std::size_t>(std::clamp(pieces, 1.0, static_cast<double>(max_nodes_per_segment)));
    out_original[s] = out.nodes.size();
    out.nodes.push_back(a);
    out.directions.push_back(da);
    for (std::size_t j = 1; j < count; ++j) {
      const double f = static_cast<double>(j) / static_cast<double>(count);
      const Vec3 blend = (1.0 - f) * da + f * db;
      out.nodes.push_back(a + f * (b - a));
      // Opposite end directions cancel half-way: keep the nearer end's direction there.
      const double length = blend.norm();
      out.directions.push_back(length > 1e-12 ? Vec3(blend / length) : (f < 0.5 ? da : db));
    }
  }
  out_original[m - 1] = out.nodes.size();
  out.nodes.push_back(points.back());
  out.directions.push_back(directions.back().normalized());
  return out;
}

}  // namespace dbs
