// The one file of libdbs that knows Ceres (and glog, which Ceres logs through).
#include "curve_refinement.hpp"

#include <algorithm>
#include <cmath>
#include <memory>
#include <string>

#include "error.hpp"
#include "number_text.hpp"

#if DBS_HAVE_CERES
#include <ceres/ceres.h>
#include <glog/logging.h>

#include <mutex>
#endif

namespace dbs {

namespace {

void check_refinement(const CurveProjectionInput& input, double gamma, const std::vector<double>& start, const RefinementSettings& settings) {
  const std::size_t k = input.nodes.size();
  if (k < 2 || input.directions.size() != k)
    fail(ErrorCode::InvalidArgument, "refine_curve: " + std::to_string(k) + " nodes and " + std::to_string(input.directions.size()) + " directions (at least 2, as many of each)");
  if (start.size() != k) fail(ErrorCode::InvalidArgument, "refine_curve: " + std::to_string(start.size()) + " start offsets for " + std::to_string(k) + " nodes");
  for (std::size_t f : input.fixed)
    if (f >= k) fail(ErrorCode::OutOfRange, "refine_curve: fixed node " + std::to_string(f) + " is not below the node count " + std::to_string(k));
  if (!(gamma >= 0.0 && gamma <= 1.0)) fail(ErrorCode::OutOfRange, "refine_curve: gamma = " + significant_text(gamma, 6) + " is outside [0, 1]");
  for (std::size_t i = 0; i < k; ++i)
    if (!is_finite(input.nodes[i]) || !is_finite(input.directions[i]) || !std::isfinite(start[i]))
      fail(ErrorCode::NonFinite, "refine_curve: node " + std::to_string(i) + ", its direction or its start offset is not finite");
  if (!(settings.loss_scale > 0.0) || !std::isfinite(settings.loss_scale)) fail(ErrorCode::InvalidArgument, "refine_curve: the loss scale must be positive and finite");
  if (settings.max_iterations < 1) fail(ErrorCode::InvalidArgument, "refine_curve: at least one iteration is needed");
  if (!(settings.function_tolerance > 0.0)) fail(ErrorCode::InvalidArgument, "refine_curve: the function tolerance must be positive");
  if (!(settings.reach > 0.0)) fail(ErrorCode::InvalidArgument, "refine_curve: the reach must be positive");
  if (!(settings.trust_region_radius > 0.0)) fail(ErrorCode::InvalidArgument, "refine_curve: the trust region radius must be positive");
}

}  // namespace

std::vector<double> solve_curve(const DirectedProjector& projector, const CurveProjectionInput& input, double gamma, const RefinementSettings& settings, RefinementCounts* counts) {
  std::vector<double> offsets = project_curve(projector, input, gamma);
  if (!settings.enabled) return offsets;
  return refine_curve(projector, input, gamma, offsets, settings, counts);
}

#if DBS_HAVE_CERES

namespace {

/// r rho <= R holds every point whose eq. (5) weight can reach DirectedProjector::kNeglectedWeight
/// (directed_projection.hpp): the neighbourhood the linear solve sums over.
const double kProductBound = std::sqrt(1.0 / DirectedProjector::kNeglectedWeight - 1.0);

/// A host that has not initialised glog would see every message Ceres logs on its stderr
/// (glog writes there until InitGoogleLogging). Only fatal ones are let through then; a host
/// that initialised glog keeps its own settings.
void quiet_glog() {
  static std::once_flag once;
  std::call_once(once, [] {
    if (!google::IsGoogleLoggingInitialized()) FLAGS_minloglevel = std::max<int>(FLAGS_minloglevel, google::GLOG_FATAL);
  });
}

/// A point near a node's line: its offset from the node p_k (t = 0) in h, along the line
/// (d0n = (p_k - p_mu).n / h) and squared across it (rho2 = |((p_k - p_mu) / h) x n|^2);
/// rho does not depend on t, the line being fixed.
struct NearPoint {
  double d0n, d0_squared, rho2;
};

/// The weight rho'(s) of a point at squared offset s (in h^2) along the ray under the loss of
/// scale b (in h): 1 within the scale, less beyond. T is double or a Ceres Jet.
template <class T>
T loss_weight(LossKind kind, double b, const T& s) {
  using std::sqrt;
  const double b2 = b * b;
  switch (kind) {
    case LossKind::Huber: return s <= T(b2) ? T(1.0) : T(b) / sqrt(s);
    case LossKind::Cauchy: return T(1.0) / (T(1.0) + s / b2);
    case LossKind::SoftL1: return T(1.0) / sqrt(T(1.0) + s / b2);
    case LossKind::None: break;
  }
  return T(1.0);
}

/// Node k's data residual, n.(q - m(q)) sqrt(w(q)) / h: the signed distance along its line
/// from q = p + t n (t in h) to the weighted mean m(q) of the points near the line, with each
/// point's eq. (5) weight a(q) = 1 / (1 + r^2 rho^2) and loss weight rho'(d^2) (d its offset
/// along the line) taken at q, and w(q) = (1 - gamma) C / (C + 1) the linear solve's data
/// weight for C = sum of the weights. Frozen: the weights of the start, and the residual is
/// sqrt(w) (t + (p - m).n / h), the linear solve's data term. Differentiated by Ceres's
/// automatic differentiation (one unknown).
class NodeData {
 public:
  NodeData(std::vector<NearPoint> points, double gamma, LossKind loss, double loss_scale, const std::vector<double>* frozen)
      : points_(std::move(points)), data_share_(1.0 - gamma), loss_(loss), scale_(loss_scale), frozen_(frozen ? *frozen : std::vector<double>()) {}

  template <class T>
  bool operator()(const T* const t, T* residual) const {
    T weight_sum(0.0), offset_sum(0.0);
    for (std::size_t i = 0; i < points_.size(); ++i) {
      const NearPoint& p = points_[i];
      const T along = T(p.d0n) + t[0];  // n.(q - p_mu) / h
      T weight;
      if (!frozen_.empty()) {
        weight = T(frozen_[i]);
      } else {
        const T r2 = T(p.d0_squared) + T(2.0 * p.d0n) * t[0] + t[0] * t[0];
        weight = loss_weight(loss_, scale_, along * along) / (T(1.0) + r2 * p.rho2);
      }
      weight_sum += weight;
      offset_sum += weight * along;
    }
    if (!(weight_sum > T(0.0))) {
      residual[0] = T(0.0);
      return true;
    }
    using std::sqrt;
    residual[0] = sqrt(T(data_share_) / (weight_sum + T(1.0))) * offset_sum / sqrt(weight_sum);
    return true;
  }

 private:
  std::vector<NearPoint> points_;
  double data_share_;
  LossKind loss_;
  double scale_;
  std::vector<double> frozen_;
};

/// A smoothing term of the linear solve: sqrt(omega) (d + sum_j c_j t_j n_j), over M
/// consecutive nodes (slope M = 2, curvature M = 3); linear in the t's, and up to a
/// constant the same with d replaced by its part in the span of the n_j.
class SmoothingTerm final : public ceres::CostFunction {
 public:
  SmoothingTerm(double omega, const Vec3& d, std::vector<double> coeffs, std::vector<Vec3> directions)
      : root_(std::sqrt(omega)), d_(in_span(d, directions)), coeffs_(std::move(coeffs)), directions_(std::move(directions)) {
    set_num_residuals(3);
    mutable_parameter_block_sizes()->assign(coeffs_.size(), 1);
  }

  /// The part of d in the span of the directions. The rest (mostly the node spacing along
  /// the curve) adds a constant to the cost that no t changes; left in, it would make
  /// Ceres's relative function tolerance judge the changes against it and stop at once.
  static Vec3 in_span(const Vec3& d, const std::vector<Vec3>& directions) {
    Vec3 basis[3];
    int count = 0;
    for (const Vec3& n : directions) {
      Vec3 v = n;
      for (int b = 0; b < count; ++b) v -= basis[b].dot(v) * basis[b];
      const double length = v.norm();
      if (length > 1e-9 && count < 3) basis[count++] = v / length;
    }
    Vec3 projected = Vec3::Zero();
    for (int b = 0; b < count; ++b) projected += basis[b].dot(d) * basis[b];
    return projected;
  }

  bool Evaluate(double const* const* parameters, double* residuals, double** jacobians) const override {
    Vec3 e = d_;
    for (std::size_t j = 0; j < coeffs_.size(); ++j) e += coeffs_[j] * parameters[j][0] * directions_[j];
    for (int i = 0; i < 3; ++i) residuals[i] = root_ * e[i];
    if (jacobians) {
      for (std::size_t j = 0; j < coeffs_.size(); ++j)
        if (jacobians[j])
          for (int i = 0; i < 3; ++i) jacobians[j][i] = root_ * coeffs_[j] * directions_[j][i];
    }
    return true;
  }

 private:
  double root_;
  Vec3 d_;
  std::vector<double> coeffs_;
  std::vector<Vec3> directions_;
};

/// The problem of one curve; owns its terms (Ceres is told not to).
class CurveProblem {
 public:
  CurveProblem(const DirectedProjector& projector, const CurveProjectionInput& input, double gamma, const std::vector<double>& start, const RefinementSettings& settings)
      : projector_(projector), input_(input), h_(projector.length_scale()), settings_(settings), problem_(problem_options()), t_(input.nodes.size()) {
    const std::size_t count = input.nodes.size();
    std::vector<char> fixed(count, 0);
    fixed.front() = fixed.back() = 1;
    for (std::size_t f : input.fixed) fixed[f] = 1;
    units_.resize(count);
    const double s = node_spacing(input.nodes, h_);
    const double reach = std::max(settings.reach, 2.0 * s);
    for (std::size_t k = 0; k < count; ++k) {
      units_[k] = input.directions[k].normalized();
      t_[k] = fixed[k] ? 0.0 : start[k] / h_;
      problem_.AddParameterBlock(&t_[k], 1);
      if (fixed[k]) {
        problem_.SetParameterBlockConstant(&t_[k]);
      } else {
        problem_.SetParameterLowerBound(&t_[k], 0, t_[k] - reach);
        problem_.SetParameterUpperBound(&t_[k], 0, t_[k] + reach);
        add_data(k, gamma);
      }
    }
    if (gamma > 0.0) {
      const double slope = gamma / (s * s), curvature = slope / (s * s);
      for (std::size_t k = 0; k + 1 < count; ++k)
        add_smoothing(slope, {k, k + 1}, {1.0, -1.0}, (input.nodes[k] - input.nodes[k + 1]) / h_);
      for (std::size_t k = 0; k + 2 < count; ++k)
        add_smoothing(curvature, {k, k + 1, k + 2}, {1.0, -2.0, 1.0}, (input.nodes[k] - 2.0 * input.nodes[k + 1] + input.nodes[k + 2]) / h_);
    }
  }

  /// Solves; returns the offsets in cloud units (the start when Ceres finds nothing usable).
  std::vector<double> solve(const std::vector<double>& start, RefinementCounts* counts) {
    ceres::Solver::Options options;
    options.minimizer_type = ceres::TRUST_REGION;
    options.trust_region_strategy_type = ceres::LEVENBERG_MARQUARDT;
    options.initial_trust_region_radius = settings_.trust_region_radius;
    // The normal equations are banded (pentadiagonal): a sparse Cholesky in Eigen, which
    // runs on this thread only (no BLAS threads), keeps the cost linear in the nodes.
    options.linear_solver_type = ceres::SPARSE_NORMAL_CHOLESKY;
    options.sparse_linear_algebra_library_type = ceres::EIGEN_SPARSE;
    options.num_threads = 1;
    options.max_num_iterations = settings_.max_iterations;
    options.function_tolerance = settings_.function_tolerance;
    options.logging_type = ceres::SILENT;
    options.minimizer_progress_to_stdout = false;
    ceres::Solver::Summary summary;
    ceres::Solve(options, &problem_, &summary);
    if (counts) {
      // Ceres's "minimizer iterations": the steps it tried.
      counts->iterations += static_cast<std::size_t>(summary.num_successful_steps + summary.num_unsuccessful_steps);
    }
    std::vector<double> offsets(t_.size(), 0.0);
    if (!summary.IsSolutionUsable()) return start;
    for (std::size_t k = 0; k < t_.size(); ++k) {
      if (!std::isfinite(t_[k])) return start;
      offsets[k] = t_[k] * h_;
    }
    for (std::size_t f : input_.fixed) offsets[f] = 0.0;
    offsets.front() = offsets.back() = 0.0;
    return offsets;
  }

 private:
  static ceres::Problem::Options problem_options() {
    ceres::Problem::Options options;
    options.cost_function_ownership = ceres::DO_NOT_TAKE_OWNERSHIP;
    options.enable_fast_removal = false;
    return options;
  }

  /// Node k's data residual (NodeData) over the points near its line where it starts: the
  /// neighbourhood of eq. (5) there (what the linear solve sums over), kept while the node
  /// moves within its reach.
  void add_data(std::size_t k, double gamma) {
    if (!(gamma < 1.0)) return;
    const Vec3& n = units_[k];
    const Vec3 start = input_.nodes[k] + (t_[k] * h_) * n;
    std::vector<std::size_t> near;
    projector_.index().near_ray(start, n, kProductBound * h_ * h_, near);
    if (near.empty()) return;
    const std::vector<Vec3>& points = projector_.index().points();
    std::vector<NearPoint> terms;
    std::vector<double> frozen;
    terms.reserve(near.size());
    for (std::size_t i : near) {
      const Vec3 d0 = (input_.nodes[k] - points[i]) / h_;
      NearPoint p{d0.dot(n), d0.squaredNorm(), d0.cross(n).squaredNorm()};
      terms.push_back(p);
      if (settings_.freeze_weights) {
        const double along = p.d0n + t_[k];
        const double r2 = p.d0_squared + 2.0 * p.d0n * t_[k] + t_[k] * t_[k];
        frozen.push_back(loss_weight(settings_.loss, settings_.loss_scale, along * along) / (1.0 + r2 * p.rho2));
      }
    }
    data_.push_back(std::make_unique<ceres::AutoDiffCostFunction<NodeData, 1, 1>>(
        new NodeData(std::move(terms), gamma, settings_.loss, settings_.loss_scale, settings_.freeze_weights ? &frozen : nullptr)));
    problem_.AddResidualBlock(data_.back().get(), nullptr, &t_[k]);
  }

  void add_smoothing(double omega, std::vector<std::size_t> nodes, std::vector<double> coeffs, const Vec3& d) {
    std::vector<Vec3> directions;
    std::vector<double*> blocks;
    for (std::size_t k : nodes) {
      directions.push_back(units_[k]);
      blocks.push_back(&t_[k]);
    }
    smoothing_.push_back(std::make_unique<SmoothingTerm>(omega, d, std::move(coeffs), std::move(directions)));
    problem_.AddResidualBlock(smoothing_.back().get(), nullptr, blocks);
  }

  const DirectedProjector& projector_;
  const CurveProjectionInput& input_;
  double h_;
  RefinementSettings settings_;
  // The terms outlive the problem (declared before it, destroyed after it).
  std::vector<std::unique_ptr<ceres::CostFunction>> data_;
  std::vector<std::unique_ptr<SmoothingTerm>> smoothing_;
  ceres::Problem problem_;
  std::vector<double> t_;  // offsets in h, one parameter block each
  std::vector<Vec3> units_;
};

/// Most rounds of one refinement: a round whose nodes all stayed well inside their reach
/// ends it; otherwise the next starts where it ended, its neighbourhoods gathered there.
constexpr int kMaxRounds = 4;
/// A node that moved more than this share of its reach may have been held by its bound.
constexpr double kNearBound = 0.9;

/// Rounds of CurveProblem with `settings` from `start`.
std::vector<double> solve_rounds(const DirectedProjector& projector, const CurveProjectionInput& input, double gamma, std::vector<double> start, const RefinementSettings& settings, RefinementCounts* counts) {
  const double h = projector.length_scale();
  const double reach = std::max(settings.reach, 2.0 * node_spacing(input.nodes, h)) * h;
  for (int round = 0;; ++round) {
    CurveProblem problem(projector, input, gamma, start, settings);
    std::vector<double> offsets = problem.solve(start, counts);
    double moved = 0.0;
    for (std::size_t k = 0; k < offsets.size(); ++k) moved = std::max(moved, std::abs(offsets[k] - start[k]));
    if (settings.freeze_weights || round + 1 >= kMaxRounds || moved <= kNearBound * reach) return offsets;
    start = std::move(offsets);
  }
}

}  // namespace

bool ceres_available() { return true; }

std::vector<double> refine_curve(const DirectedProjector& projector, const CurveProjectionInput& input, double gamma, const std::vector<double>& start_offsets, const RefinementSettings& settings, RefinementCounts* counts) {
  check_refinement(input, gamma, start_offsets, settings);
  quiet_glog();
  if (counts) ++counts->curves;
  if (settings.loss == LossKind::None || settings.freeze_weights) return solve_rounds(projector, input, gamma, start_offsets, settings, counts);
  // A loss that flattens beyond its scale (Cauchy most) keeps a node near where it starts
  // when that start is farther than the scale from the cloud, as the linear solution may be
  // on a curved cloud: the loss is switched on once the refinement without it has settled.
  RefinementSettings plain = settings;
  plain.loss = LossKind::None;
  const std::vector<double> settled = solve_rounds(projector, input, gamma, start_offsets, plain, counts);
  return solve_rounds(projector, input, gamma, settled, settings, counts);
}

#else

bool ceres_available() { return false; }

std::vector<double> refine_curve(const DirectedProjector&, const CurveProjectionInput& input, double gamma, const std::vector<double>& start_offsets, const RefinementSettings& settings, RefinementCounts*) {
  check_refinement(input, gamma, start_offsets, settings);
  fail(ErrorCode::Unsupported, "the Ceres solver is not available: this libdbs was built without Ceres");
}

#endif

}  // namespace dbs
