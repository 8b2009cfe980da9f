// The Ceres refinement of the grid projection (issue 11): with the weights frozen one
// Gauss-Newton step is the linear solve; on a high-curvature bump the refined nodes lie much
// closer to the true surface; on a plane and a gentle height field both solvers agree; with
// gross outliers the robust loss keeps the surface on the clean one and the stopping rule
// does not subdivide for them; results do not depend on the thread count and are invariant
// to scale (x1000) and rigid motion. A build without Ceres refuses the solver.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <functional>
#include <random>

#include "analytic_clouds.hpp"
#include "cloud_index.hpp"
#include "curve_refinement.hpp"
#include "options.hpp"
#include "parameterize.hpp"
#include "robust_loss.hpp"

#include "core_test_support.hpp"

using namespace dbs;
using namespace dbs_test;

namespace {

using Height = std::function<double(double, double)>;

// The helpers only the Ceres tests use are [[maybe_unused]] in a build without Ceres.

/// A bump of height 0.3 and width 0.1 (about 57 h and 19 h): curvature about 30 at its top.
[[maybe_unused]] double bump(double x, double y) { return 0.3 * std::exp(-((x - 0.5) * (x - 0.5) + (y - 0.5) * (y - 0.5)) / (2 * 0.1 * 0.1)); }
double gentle(double x, double y) { return 0.05 * std::sin(M_PI * x) * std::sin(M_PI * y); }
[[maybe_unused]] double dome(double x, double y) { return 0.2 * std::sin(M_PI * x) * std::sin(M_PI * y); }

/// A jittered n x n sampling of a height field over the unit square.
std::vector<Vec3> jittered(const Height& f, int n, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> jitter(-0.3, 0.3);
  std::vector<Vec3> pts;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const double x = std::clamp((i + 0.5 + jitter(rng)) / n, 0.0, 1.0), y = std::clamp((j + 0.5 + jitter(rng)) / n, 0.0, 1.0);
      pts.emplace_back(x, y, f(x, y));
    }
  return pts;
}

/// The dome's cloud with every 50th point (2%) moved 0.1 (10% of the size) up or down.
[[maybe_unused]] std::vector<Vec3> dome_with_outliers() {
  std::vector<Vec3> pts = jittered(dome, 150, 5);
  std::mt19937_64 rng(11);
  std::uniform_int_distribution<int> sign(0, 1);
  std::uniform_int_distribution<int> percent(0, 99);
  // 2% of the points, drawn at random: a regular pattern (every 50th point) would alias with
  // the evenly strided sample the evolution measures its error on.
  for (Vec3& p : pts)
    if (percent(rng) < 2) p.z() += sign(rng) ? 0.1 : -0.1;
  return pts;
}

Boundary boundary_of_height(const Height& f) {
  return boundary_of([&](double a, double b) { return Vec3(a, b, f(a, b)); }, 60);
}

/// Distance of p to the height field, to first order in the offset.
[[maybe_unused]] double height_distance(const Height& f, const Vec3& p) {
  const double e = 1e-6;
  const double fx = (f(p.x() + e, p.y()) - f(p.x() - e, p.y())) / (2 * e), fy = (f(p.x(), p.y() + e) - f(p.x(), p.y() - e)) / (2 * e);
  return std::abs(p.z() - f(p.x(), p.y())) / std::sqrt(1 + fx * fx + fy * fy);
}

/// Mean distance of the interior grid nodes of the root to the true surface.
[[maybe_unused]] double node_distance(const Height& f, const Result& r) {
  const Grid& g = r.patches[0].grid;
  double sum = 0;
  int n = 0;
  for (int j = 1; j + 1 < g.nv; ++j)
    for (int i = 1; i + 1 < g.nu; ++i) {
      sum += height_distance(f, g(i, j));
      ++n;
    }
  return sum / n;
}

/// Fixed grids (one 11 x 11 root): both solvers fit the same unknowns.
[[maybe_unused]] Options fixed_grid(Solver solver, LossKind loss = LossKind::None) {
  Options o;
  o.max_level = 0;
  o.initial_grid = o.max_grid = 11;
  o.threads = 2;
  o.solver = solver;
  o.loss = loss;
  // The grids compared here are the solvers' own: the repair's refit of a leaf (on by
  // default) would replace them by a least-squares fit (which alone put the linear solver's
  // nodes within 1% of the Huber ones on the dome with outliers).
  o.repair = 0;
  return o;
}

[[maybe_unused]] double max_uv_difference(const Result& a, const Result& b) {
  double worst = 0.0;
  for (std::size_t i = 0; i < a.u.size(); ++i) worst = std::max({worst, std::abs(a.u[i] - b.u[i]), std::abs(a.v[i] - b.v[i])});
  return worst;
}

void losses_have_their_formulas(void**) {
  // Huber: d itself up to the scale, sqrt(2 a d - a^2) beyond; Cauchy and soft-L1 below d.
  assert_true(robust_distance(LossKind::None, 1.0, 7.0) == 7.0);
  assert_true(robust_distance(LossKind::Huber, 1.0, 0.5) == 0.5);
  assert_true(std::abs(robust_distance(LossKind::Huber, 1.0, 4.0) - std::sqrt(7.0)) < 1e-15);
  assert_true(std::abs(robust_rho(LossKind::Cauchy, 2.0, 12.0) - 4.0 * std::log(4.0)) < 1e-14);
  assert_true(std::abs(robust_rho(LossKind::SoftL1, 2.0, 12.0) - 8.0 * (2.0 - 1.0)) < 1e-14);
  // Near 0 every loss is the square.
  for (LossKind k : {LossKind::Huber, LossKind::Cauchy, LossKind::SoftL1}) assert_true(std::abs(robust_distance(k, 1.0, 1e-4) - 1e-4) < 1e-11);
  assert_true(robust_distance(LossKind::Cauchy, 1.0, 100.0) < 3.1);  // bounded like a sqrt(2 log(d / a))
}

#if DBS_HAVE_CERES

/// A middle row of the bump's cloud, densified from the flat plane z = 0 (directions +z,
/// slightly tilted so the nodes' lines differ), its centre fixed.
CurveProjectionInput bump_row(double h, std::vector<std::size_t>& original) {
  std::vector<Vec3> points, directions;
  for (int k = 0; k <= 10; ++k) {
    points.emplace_back(0.1 * k, 0.45, 0.0);
    directions.push_back(Vec3(0.05 * std::sin(k), 0.0, 1.0).normalized());
  }
  CurveProjectionInput input = densify_polygon(points, directions, 2.0 * h, original);
  input.fixed.push_back(original[5]);
  return input;
}

void frozen_weights_gauss_newton_step_is_the_linear_solve(void**) {
  const std::vector<Vec3> pts = jittered(bump, 120, 3);
  CloudIndex index(pts);
  const double h = cloud_spacing(index);
  const DirectedProjector projector(index, h);
  std::vector<std::size_t> original;
  const CurveProjectionInput input = bump_row(h, original);
  const double gamma = 0.5;
  const std::vector<double> linear = project_curve(projector, input, gamma);
  RefinementSettings frozen;
  frozen.enabled = true;
  frozen.freeze_weights = true;
  frozen.max_iterations = 1;
  frozen.trust_region_radius = 1e16;  // Levenberg-Marquardt's damping vanishes: Gauss-Newton
  frozen.reach = 1e6;                 // the step from t = 0 goes all the way
  RefinementCounts counts;
  const std::vector<double> step = refine_curve(projector, input, gamma, std::vector<double>(input.nodes.size(), 0.0), frozen, &counts);
  double worst = 0.0, largest = 0.0;
  for (std::size_t k = 0; k < linear.size(); ++k) {
    worst = std::max(worst, std::abs(step[k] - linear[k]));
    largest = std::max(largest, std::abs(linear[k]));
  }
  std::printf("frozen Gauss-Newton step vs linear: max |dt| = %.3g h (offsets up to %.3g h)\n", worst / h, largest / h);
  assert_true(largest > 10.0 * h);  // the row rises onto the bump: a real step
  assert_true(worst <= 1e-8 * h);
  assert_int_equal(counts.curves, 1);
  assert_true(counts.iterations >= 1);
  assert_true(step[original[5]] == 0.0 && step.front() == 0.0 && step.back() == 0.0);

  // With the weights following the nodes, the refinement moves them on from the linear
  // solution (the start's weights saw a mean biased towards the bump's foot).
  RefinementSettings moving;
  moving.enabled = true;
  const std::vector<double> refined = refine_curve(projector, input, gamma, linear, moving);
  double moved = 0.0, linear_error = 0.0, refined_error = 0.0;
  for (std::size_t k = 0; k < linear.size(); ++k) {
    moved = std::max(moved, std::abs(refined[k] - linear[k]));
    linear_error += height_distance(bump, input.nodes[k] + linear[k] * input.directions[k]);
    refined_error += height_distance(bump, input.nodes[k] + refined[k] * input.directions[k]);
  }
  std::printf("bump row: mean node distance linear %.3g h, refined %.3g h\n", linear_error / linear.size() / h, refined_error / linear.size() / h);
  assert_true(moved > 0.2 * h);
  assert_true(refined_error < 0.9 * linear_error);
  assert_true(refined[original[5]] == 0.0 && refined.front() == 0.0 && refined.back() == 0.0);
}

void refine_curve_checks_its_input(void**) {
  const std::vector<Vec3> pts = jittered(bump, 40, 3);
  CloudIndex index(pts);
  const DirectedProjector projector(index, cloud_spacing(index));
  std::vector<std::size_t> original;
  const CurveProjectionInput input = bump_row(projector.length_scale(), original);
  RefinementSettings s;
  s.enabled = true;
  core_test::expect_error([&] { refine_curve(projector, input, 0.5, std::vector<double>(3, 0.0), s); }, ErrorCode::InvalidArgument, {"3 start offsets"});
  std::vector<double> start(input.nodes.size(), 0.0);
  start[2] = NAN;
  core_test::expect_error([&] { refine_curve(projector, input, 0.5, start, s); }, ErrorCode::NonFinite, {"node 2"});
  start[2] = 0.0;
  core_test::expect_error([&] { refine_curve(projector, input, 1.5, start, s); }, ErrorCode::OutOfRange, {"gamma"});
  s.loss_scale = 0.0;
  core_test::expect_error([&] { refine_curve(projector, input, 0.5, start, s); }, ErrorCode::InvalidArgument, {"loss scale"});
}

void bump_nodes_lie_closer_to_the_surface(void**) {
  PointCloud cloud(jittered(bump, 150, 3));
  const Boundary b = boundary_of_height(bump);
  const Result lin = parameterize(cloud, b, fixed_grid(Solver::Linear));
  const Result cer = parameterize(cloud, b, fixed_grid(Solver::Ceres));
  const double dl = node_distance(bump, lin), dc = node_distance(bump, cer);
  std::printf("bump, 11 x 11: node distance linear %.3g, Ceres %.3g (%.2fx); point mean distance %.3g, %.3g; Ceres iterations %zu over %zu sections\n", dl, dc, dc / dl,
              lin.mean_distance, cer.mean_distance, cer.ceres_iterations, cer.refined_curves);
  assert_true(dc <= 0.7 * dl);
  assert_true(cer.mean_distance < lin.mean_distance);
  assert_int_equal(cer.solver, 1);
  assert_int_equal(lin.solver, 0);
  assert_int_equal(cer.refined_curves, 16 + 18);  // 8 + 8 sections at the 10 x 10 warm-up, 9 + 9 at 11 x 11
  assert_true(cer.ceres_iterations >= cer.refined_curves);
  assert_true(lin.ceres_iterations == 0 && lin.refined_curves == 0);
}

void plane_and_gentle_field_agree(void**) {
  // A plane at a fixed grid: both solvers put every node on it.
  const Height flat = [](double, double) { return 0.0; };
  PointCloud plane(jittered(flat, 120, 7));
  const Result pl = parameterize(plane, boundary_of_height(flat), fixed_grid(Solver::Linear));
  const Result pc = parameterize(plane, boundary_of_height(flat), fixed_grid(Solver::Ceres));
  assert_true(max_uv_difference(pl, pc) <= 1e-4);
  assert_true(pl.mean_distance < 1e-12 && pc.mean_distance < 1e-12);
  // A gentle height field (9 h high), the grid evolving from 5 to 11 (each linear projection
  // then starts from the last surface, as Ceres's weights do).
  PointCloud field(jittered(gentle, 120, 7));
  Options ol = fixed_grid(Solver::Linear), oc = fixed_grid(Solver::Ceres);
  ol.initial_grid = oc.initial_grid = 5;
  ol.noise_floor = oc.noise_floor = 0;
  ol.accuracy = oc.accuracy = 1e-9;  // every grid size
  const Result gl = parameterize(field, boundary_of_height(gentle), ol);
  const Result gc = parameterize(field, boundary_of_height(gentle), oc);
  const double duv = max_uv_difference(gl, gc);
  std::printf("gentle field: max |delta uv| %.3g, mean distance linear %.4g, Ceres %.4g\n", duv, gl.mean_distance, gc.mean_distance);
  assert_true(duv <= 1e-4);
  assert_true(std::abs(gc.mean_distance - gl.mean_distance) <= 0.02 * gl.mean_distance);
}

void robust_loss_ignores_gross_outliers(void**) {
  PointCloud cloud(dome_with_outliers());
  const Boundary b = boundary_of_height(dome);
  const Result lin = parameterize(cloud, b, fixed_grid(Solver::Linear));
  const Result plain = parameterize(cloud, b, fixed_grid(Solver::Ceres));
  const Result huber = parameterize(cloud, b, fixed_grid(Solver::Ceres, LossKind::Huber));
  const double dl = node_distance(dome, lin), dp = node_distance(dome, plain), dh = node_distance(dome, huber);
  std::printf("2%% outliers, 11 x 11: node distance to the clean surface linear %.3g, Ceres %.3g, Ceres + Huber %.3g (scale %.3g = h %.3g)\n", dl, dp, dh, huber.loss_scale, huber.length_scale);
  assert_true(dh < dp && dh < dl);
  // The derived scale: 3 sigma of a clean cloud's noise is below h, so h.
  assert_true(huber.loss_scale == huber.length_scale);
  assert_true(plain.loss_scale == 0.0);

  // The default stopping rule: the outliers' distances alone miss the target, so the plain
  // solvers subdivide; measured with the loss they do not.
  Options subdividing;
  subdividing.max_level = 2;
  subdividing.threads = 2;
  Options robust = subdividing;
  subdividing.solver = robust.solver = Solver::Ceres;
  robust.loss = LossKind::Huber;
  const Result split = parameterize(cloud, b, subdividing);
  const Result whole = parameterize(cloud, b, robust);
  std::printf("default stopping rule: Ceres %d levels %zu leaves, Ceres + Huber %d levels %zu leaves (mean distance %.3g, target %.3g)\n", split.levels, split.leaf_count(),
              whole.levels, whole.leaf_count(), whole.mean_distance, whole.accuracy);
  assert_true(split.levels > 1);
  assert_int_equal(whole.levels, 1);
  assert_true(whole.accuracy_met);
  assert_true(whole.mean_distance > whole.accuracy);  // the plain mean still counts the outliers
}

void same_result_for_any_thread_count(void**) {
  PointCloud cloud(dome_with_outliers());
  const Boundary b = boundary_of_height(dome);
  Options o;
  o.max_level = 2;
  o.solver = Solver::Ceres;
  o.loss = LossKind::Cauchy;
  o.accuracy = 2e-4;  // a few patches, so the levels run patches in parallel
  o.threads = 1;
  const Result one = parameterize(cloud, b, o);
  o.threads = 3;
  const Result three = parameterize(cloud, b, o);
  assert_true(one.patches.size() > 1);
  assert_int_equal(one.patches.size(), three.patches.size());
  assert_true(one.ceres_iterations == three.ceres_iterations);
  for (std::size_t i = 0; i < one.u.size(); ++i) {
    assert_true(one.u[i] == three.u[i]);
    assert_true(one.v[i] == three.v[i]);
    assert_true(one.distance[i] == three.distance[i]);
  }
}

void invariant_to_scale_and_rigid_motion(void**) {
  std::vector<Vec3> pts = dome_with_outliers();
  std::vector<Vec3> moved_pts;
  for (const Vec3& p : pts) moved_pts.push_back(move_and_scale(p, 1000.0));
  const Surface s = [](double a, double b) { return Vec3(a, b, dome(a, b)); };
  const Surface moved = [&](double a, double b) { return move_and_scale(s(a, b), 1000.0); };
  Options o = fixed_grid(Solver::Ceres, LossKind::SoftL1);
  o.initial_grid = 7;
  const Result r1 = parameterize(PointCloud(pts), boundary_of(s, 60), o);
  const Result r2 = parameterize(PointCloud(moved_pts), boundary_of(moved, 60), o);
  const double worst = max_uv_difference(r1, r2);
  std::printf("x1000 and a rigid motion with Ceres + soft-L1: max |delta uv| %.3g\n", worst);
  assert_true(worst < 1e-9);
  assert_true(std::abs(r2.loss_scale / r1.loss_scale - 1000.0) < 1e-6);
}

#else

void without_ceres_the_solver_is_refused(void**) {
  assert_false(ceres_available());
  Options o;
  assert_true(core_test::throws(ErrorCode::Unsupported, [&] { set_option(o, static_cast<int>(OptionId::Solver), 1.0); }));
  assert_true(o.solver == Solver::Linear);
  o.solver = Solver::Ceres;  // set behind set_option's back: parameterize refuses it too
  PointCloud cloud(jittered(gentle, 20, 1));
  core_test::expect_error([&] { parameterize(cloud, boundary_of_height(gentle), o); }, ErrorCode::Unsupported, {"built without Ceres"});
  std::vector<std::size_t> original;
  CloudIndex index(cloud.points());
  const DirectedProjector projector(index, cloud_spacing(index));
  CurveProjectionInput input;
  input.nodes = {Vec3(0, 0, 0), Vec3(0.5, 0, 0), Vec3(1, 0, 0)};
  input.directions = {Vec3(0, 0, 1), Vec3(0, 0, 1), Vec3(0, 0, 1)};
  RefinementSettings s;
  s.enabled = true;
  core_test::expect_error([&] { refine_curve(projector, input, 0.5, {0.0, 0.0, 0.0}, s); }, ErrorCode::Unsupported, {"built without Ceres"});
}

#endif

}  // namespace

int main(int argc, char** argv) {
  // "--quick" (the sanitizer build): the single-patch tests; the runs that subdivide or run
  // twice at several levels take minutes there.
  const bool quick = argc > 1 && std::strcmp(argv[1], "--quick") == 0;
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(losses_have_their_formulas),
#if DBS_HAVE_CERES
      cmocka_unit_test(frozen_weights_gauss_newton_step_is_the_linear_solve),
      cmocka_unit_test(refine_curve_checks_its_input),
      cmocka_unit_test(bump_nodes_lie_closer_to_the_surface),
      cmocka_unit_test(plane_and_gentle_field_agree),
#else
      cmocka_unit_test(without_ceres_the_solver_is_refused),
#endif
  };
  int failed = cmocka_run_group_tests_name("curve_refinement", tests, nullptr, nullptr);
#if DBS_HAVE_CERES
  const struct CMUnitTest slow[] = {
      cmocka_unit_test(robust_loss_ignores_gross_outliers),
      cmocka_unit_test(same_result_for_any_thread_count),
      cmocka_unit_test(invariant_to_scale_and_rigid_motion),
  };
  if (!quick) failed += cmocka_run_group_tests_name("curve_refinement_whole_runs", slow, nullptr, nullptr);
#else
  (void)quick;
#endif
  return failed;
}
