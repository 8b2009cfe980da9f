// The smoothing of turned sheets (DBS_OPT_SMOOTH_TURNED, turned_smoothing.hpp) on the hard
// shapes of tests/support/fold_shapes, against the default run (which leaves it off):
// - under the mushroom's cap (6,084 points) it takes 22 folded reference triangles to 1 and
//   the 8,281-point tall dome's wall 33 to 2, within the target, and never moves a point on
//   the domain's edge; the same result for one and two threads;
// - above the 20,000 points the fold measure judges (24,649; a target of 0.2% of the diagonal,
//   which the smoothing keeps to) it takes the tall dome's 641 folded triangles to 221;
// - it is undone where it would take the mean distance above both the one before and the
//   target (the 10,201-point mushroom, whose leaves miss the target already: 0.0022 against
//   0.00146), and does nothing where no sheet is turned (the saddle): then the result is the
//   default one, bit for bit;
// - flags or normals not of every point are refused; with every point of the saddle flagged,
//   the interior moves by little and the domain's edge stays.
// Its cost, more points on turned sheets, is bounded here at today's figures with a margin.
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "cloud_index.hpp"
#include "fold_shapes.hpp"
#include "parameterize.hpp"
#include "point_cloud.hpp"
#include "fold_measure.hpp"
#include "fold_repair.hpp"
#include "turned_sheets.hpp"
#include "turned_smoothing.hpp"

#include "core_test_support.hpp"
#include "fold_shape_runs.hpp"

namespace {

using dbs::Vec3;
using dbs_folds::FoldShape;

using fold_runs::points_of;

struct Run {
  dbs::Result result;
  std::size_t folds = 0;  // folded reference triangles (inverted or collapsed)
};

Run run(const FoldShape& shape, int smooth, int threads = 2, double relative_accuracy = dbs::Options().relative_accuracy) {
  dbs::Options options;
  // The smoothing is judged on the plain pass's result, which its figures below are of.
  options.coarse_pass = 0;
  options.smooth_turned = smooth;
  options.threads = threads;
  options.relative_accuracy = relative_accuracy;
  options.warning = [](const char*) {};
  Run r{dbs::parameterize(dbs::PointCloud(points_of(shape.xyz)), fold_runs::boundary_of(shape), options), 0};
  r.folds = fold_runs::reference_folds(shape, r.result);
  return r;
}

bool same_parameters(const dbs::Result& a, const dbs::Result& b) { return a.u == b.u && a.v == b.v && a.distance == b.distance && a.patch == b.patch; }

/// No point whose (u,v) lay on the domain's edge in `plain` moved in `smoothed`.
bool edge_points_stay(const dbs::Result& plain, const dbs::Result& smoothed) {
  for (std::size_t i = 0; i < plain.u.size(); ++i) {
    const bool on_edge = plain.u[i] == 0.0 || plain.u[i] == 1.0 || plain.v[i] == 0.0 || plain.v[i] == 1.0;
    if (on_edge && (smoothed.u[i] != plain.u[i] || smoothed.v[i] != plain.v[i])) return false;
  }
  return true;
}

void check_unfolds(const FoldShape& shape, std::size_t plain_folds_at_least, std::size_t smoothed_folds_at_most, double max_turned_share) {
  const Run plain = run(shape, 0);
  const Run smoothed = run(shape, 1);
  assert_int_equal(plain.result.smoothed_points, 0);
  assert_true(plain.folds >= plain_folds_at_least);
  assert_true(smoothed.folds <= smoothed_folds_at_most);
  assert_true(smoothed.result.smoothed_points > 0);
  // The driver's rule: within the larger of the mean distance before and the target.
  assert_true(smoothed.result.mean_distance <= std::max(plain.result.mean_distance, plain.result.accuracy));
  assert_true(smoothed.result.turned_share <= max_turned_share);
  assert_true(edge_points_stay(plain.result, smoothed.result));
  const Run one_thread = run(shape, 1, 1);
  assert_true(same_parameters(one_thread.result, smoothed.result));
  assert_int_equal(one_thread.result.smoothed_points, smoothed.result.smoothed_points);
}

void mushroom_unfolds_under_its_cap(void**) {
  // Today: 22 -> 1 folded triangles, 96 points on turned sheets (1.58%) against 52.
  check_unfolds(dbs_folds::fold_shape("mushroom", 1.5), 15, 3, 0.02);
}

void tall_dome_unfolds_on_its_wall(void**) {
  // Today: 33 -> 2 folded triangles, mean distance 0.000506 -> 0.000897 (target 0.00153),
  // 806 points on turned sheets (9.7%) against 585.
  check_unfolds(dbs_folds::fold_shape("tall-dome", 2.0), 25, 5, 0.11);
}

/// The mean distance of the points a result counts (as the driver measures it).
double counted_mean(const dbs::Result& r) {
  const std::vector<double> d = r.counted_distances();
  double sum = 0.0;
  for (double x : d) sum += x;
  return sum / static_cast<double>(d.size());
}

void undone_above_the_target(void**) {
  // The 10,201-point mushroom: smoothed, its mean distance would be 0.0030, above both the
  // 0.0022 before and the target (shown by the smoothing itself on the plain result, with
  // the fold measure's turned points and normals): the run keeps the plain result, its
  // leaves included.
  const FoldShape shape = dbs_folds::fold_shape("mushroom", 2.5);
  const Run plain = run(shape, 0);
  const Run smoothed = run(shape, 1);
  const std::vector<Vec3> points = points_of(shape.xyz);
  const std::size_t n = points.size();
  const dbs::FoldMeasure measure = dbs::measure_folds(points, plain.result.u, plain.result.v, plain.result.noise, 2);
  const dbs::TurnedSheets turned = dbs::turned_sheets(plain.result, {}, measure, 2);
  assert_true(turned.turned > 100);
  std::vector<char> flags(n, 0);
  for (std::size_t i : turned.points) flags[i] = 1;
  dbs::Result tried = plain.result;
  const dbs::CloudIndex index(points);
  const dbs::TurnedSmoothing would = dbs::smooth_turned_sheets(tried, points, index, flags, measure.right_normal, dbs::refit_outliers(tried, points, index, 2), 2);
  assert_true(would.moved > 1000);
  assert_true(counted_mean(tried) > std::max(counted_mean(plain.result), plain.result.accuracy));

  assert_int_equal(smoothed.result.smoothed_points, 0);
  assert_true(same_parameters(plain.result, smoothed.result));
  assert_true(plain.result.mean_distance == smoothed.result.mean_distance && plain.result.accuracy_met == smoothed.result.accuracy_met);
  assert_true(plain.result.turned_points == smoothed.result.turned_points && plain.result.folded_points == smoothed.result.folded_points);
  assert_int_equal(plain.result.patches.size(), smoothed.result.patches.size());
  for (std::size_t id = 0; id < plain.result.patches.size(); ++id) {
    const dbs::Patch &a = plain.result.patches[id], &b = smoothed.result.patches[id];
    assert_true(a.grid.points == b.grid.points && a.mean_distance == b.mean_distance && a.accurate == b.accurate);
  }
}

void sampled_cloud_smoothed_whole(void**) {
  // 24,649 points, more than the 20,000 the fold measure judges: every point takes the turned
  // verdict and the normal of its nearest judged point. With a target of 0.2% of the diagonal
  // the smoothing is kept: 641 -> 221 folded triangles today, 5,569 points moved; the same for
  // one and two threads.
  const FoldShape shape = dbs_folds::fold_shape("tall-dome", 6.0);
  const Run plain = run(shape, 0, 2, 0.002);
  const Run smoothed = run(shape, 1, 2, 0.002);
  assert_true(plain.result.judged_points < plain.result.u.size());
  assert_true(plain.folds >= 400);
  assert_true(2 * smoothed.folds < plain.folds);
  assert_true(smoothed.result.smoothed_points > 2000);
  assert_true(smoothed.result.mean_distance <= std::max(plain.result.mean_distance, plain.result.accuracy));
  const Run one_thread = run(shape, 1, 1, 0.002);
  assert_true(same_parameters(one_thread.result, smoothed.result));
}

void nothing_turned_nothing_moved(void**) {
  const FoldShape shape = dbs_folds::fold_shape("saddle");
  const Run plain = run(shape, 0);
  const Run smoothed = run(shape, 1);
  assert_int_equal(plain.result.turned_points, 0);
  assert_int_equal(smoothed.result.smoothed_points, 0);
  assert_true(same_parameters(plain.result, smoothed.result));
}

void flags_of_every_point(void**) {
  const FoldShape shape = dbs_folds::fold_shape("saddle");
  Run r = run(shape, 0);
  const std::vector<Vec3> points = points_of(shape.xyz);
  const std::size_t n = points.size();
  const std::vector<char> flags(n, 0), short_flags(n - 1, 0);
  const std::vector<Vec3> normals(n, Vec3(0.0, 0.0, 1.0)), short_normals(n - 1, Vec3(0.0, 0.0, 1.0));
  const dbs::CloudIndex index(points);
  core_test::expect_error([&] { dbs::smooth_turned_sheets(r.result, points, index, short_flags, normals, flags, 1); }, dbs::ErrorCode::InvalidArgument, {"turned flags", std::to_string(n) + " points"});
  core_test::expect_error([&] { dbs::smooth_turned_sheets(r.result, points, index, flags, short_normals, flags, 1); }, dbs::ErrorCode::InvalidArgument, {"normals"});
  core_test::expect_error([&] { dbs::smooth_turned_sheets(r.result, points, index, flags, normals, short_flags, 1); }, dbs::ErrorCode::InvalidArgument, {"outlier flags"});
  // No turned point: nothing moves.
  const dbs::Result before = r.result;
  const dbs::TurnedSmoothing none = dbs::smooth_turned_sheets(r.result, points, index, flags, normals, flags, 1);
  assert_int_equal(none.moved, 0);
  assert_true(none.refitted.empty() && none.touched.empty());
  assert_true(same_parameters(before, r.result));
}

void every_point_turned_edge_stays(void**) {
  // Every point of the saddle flagged (its normals within 60 degrees of +z), after the points
  // within 0.015 of the domain's edge were put onto it (as a scan's points on its boundary
  // are): the interior moves by little (its map is smooth), and the points on the edge, whose
  // neighbourhoods are one-sided, stay where they are.
  const FoldShape shape = dbs_folds::fold_shape("saddle");
  Run r = run(shape, 0);
  auto snap = [](double x) { return x < 0.015 ? 0.0 : x > 0.985 ? 1.0 : x; };
  for (std::size_t i = 0; i < r.result.u.size(); ++i) {
    r.result.u[i] = snap(r.result.u[i]);
    r.result.v[i] = snap(r.result.v[i]);
  }
  const dbs::Result before = r.result;
  const std::vector<Vec3> points = points_of(shape.xyz);
  const std::size_t n = points.size();
  const dbs::CloudIndex index(points);
  const dbs::TurnedSmoothing all = dbs::smooth_turned_sheets(r.result, points, index, std::vector<char>(n, 1), std::vector<Vec3>(n, Vec3(0.0, 0.0, 1.0)), std::vector<char>(n, 0), 2);
  std::size_t on_edge = 0;
  double largest = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    if (before.u[i] == 0.0 || before.u[i] == 1.0 || before.v[i] == 0.0 || before.v[i] == 1.0) ++on_edge;
    else largest = std::max(largest, std::hypot(r.result.u[i] - before.u[i], r.result.v[i] - before.v[i]));
  }
  assert_true(on_edge >= 200);
  assert_true(all.moved + on_edge == n);
  assert_true(edge_points_stay(before, r.result));
  assert_true(largest < 0.01);  // below the saddle's spacing in (u,v), 1/64
}

}  // namespace

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(mushroom_unfolds_under_its_cap), cmocka_unit_test(tall_dome_unfolds_on_its_wall), cmocka_unit_test(undone_above_the_target),
      cmocka_unit_test(sampled_cloud_smoothed_whole),   cmocka_unit_test(nothing_turned_nothing_moved),   cmocka_unit_test(flags_of_every_point),         cmocka_unit_test(every_point_turned_edge_stays),
  };
  return cmocka_run_group_tests(tests, nullptr, nullptr);
}
