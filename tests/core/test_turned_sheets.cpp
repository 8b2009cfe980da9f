// Points on a turned sheet (turned_sheets.hpp): the result surface's Su x Sv at a point's (u,v)
// against the normal the fold measure finds for it from the cloud. A surface that agrees with
// its (u,v) turns nothing; the same surface under (u,v) mirrored (the fold measure's majority
// flips, the surface does not) turns every judged point; on a shape whose surfaces do turn
// over in places (the tall dome of the fold shapes), the verdicts are those of each judged
// point's own (u,v) and normal, for a subset too, and parameterize reports the same count;
// the counts do not depend on the thread count; sizes and indices that do not fit are refused.
#include <cmath>
#include <cstdint>
#include <vector>

#include "analytic_clouds.hpp"
#include "boundary.hpp"
#include "fold_measure.hpp"
#include "fold_shapes.hpp"
#include "parameterize.hpp"
#include "point_cloud.hpp"
#include "turned_sheets.hpp"

#include "core_test_support.hpp"

using namespace dbs;

namespace {

struct Fixture {
  std::vector<Vec3> points;
  Result result;
};

/// The height field of 3,000 random points, parameterized with the default options.
const Fixture& fixture() {
  static const Fixture f = [] {
    Fixture out;
    out.points = dbs_test::random_points(dbs_test::height_field(), 3000, 11);
    out.result = parameterize(PointCloud(out.points), dbs_test::boundary_of(dbs_test::height_field(), 40), Options());
    return out;
  }();
  return f;
}

/// The result with every u mirrored (u -> 1 - u), its surface unchanged.
Result mirrored(const Result& r) {
  Result m = r;
  for (double& u : m.u) u = 1.0 - u;
  return m;
}

void a_surface_that_agrees_with_its_uv_turns_nothing(void**) {
  const Fixture& f = fixture();
  assert_int_equal(f.result.turned_points, 0);
  assert_true(f.result.turned_share == 0.0);
  const FoldMeasure folds = measure_folds(f.points, f.result.u, f.result.v, f.result.noise, 2);
  const TurnedSheets t = turned_sheets(f.result, {}, folds, 2);
  assert_true(t.judged >= f.points.size() * 9 / 10);  // every point inside the orientation graph but a few at the rim
  assert_int_equal(t.turned, 0);
  assert_true(t.share == 0.0);
}

void a_mirrored_uv_on_the_same_surface_turns_every_point(void**) {
  const Fixture& f = fixture();
  const Result m = mirrored(f.result);
  const FoldMeasure folds = measure_folds(f.points, m.u, m.v, f.result.noise, 2);
  assert_int_equal(folds.folded, 0);  // a mirrored map folds nothing: the measure cannot see it
  const TurnedSheets t = turned_sheets(m, {}, folds, 2);
  assert_true(t.judged >= f.points.size() * 9 / 10);
  assert_int_equal(t.turned, t.judged);
  assert_true(t.share == 1.0);
}

void a_judged_subset_gives_the_same_verdicts(void**) {
  const Fixture& f = fixture();
  const Result m = mirrored(f.result);
  std::vector<std::size_t> judged;
  std::vector<Vec3> subset;
  std::vector<double> u, v, mu;
  for (std::size_t i = 0; i < f.points.size(); i += 3) {
    judged.push_back(i);
    subset.push_back(f.points[i]);
    u.push_back(f.result.u[i]);
    v.push_back(f.result.v[i]);
    mu.push_back(m.u[i]);
  }
  const TurnedSheets right = turned_sheets(f.result, judged, measure_folds(subset, u, v, f.result.noise, 1), 1);
  assert_true(right.judged >= judged.size() * 9 / 10);
  assert_int_equal(right.turned, 0);
  const TurnedSheets turned = turned_sheets(m, judged, measure_folds(subset, mu, v, f.result.noise, 1), 1);
  assert_true(turned.judged >= judged.size() * 9 / 10);
  assert_int_equal(turned.turned, turned.judged);
}

std::vector<Vec3> points_of(const std::vector<double>& xyz) {
  std::vector<Vec3> p;
  for (std::size_t i = 0; i + 2 < xyz.size(); i += 3) p.emplace_back(xyz[i], xyz[i + 1], xyz[i + 2]);
  return p;
}

/// Judged point k (points[judged[k]]) counted turned, each from its own (u,v) and normal.
std::size_t turned_by_hand(const Result& r, const std::vector<std::size_t>& judged, const FoldMeasure& folds) {
  std::size_t turned = 0;
  for (std::size_t k = 0; k < judged.size(); ++k) {
    if (folds.right_normal[k].isZero() || beyond_repair_reach(r, judged[k])) continue;
    Vec3 su, sv;
    r.derivatives(r.u[judged[k]], r.v[judged[k]], su, sv);
    turned += su.cross(sv).dot(folds.right_normal[k]) > 0.0 ? 0 : 1;
  }
  return turned;
}

void each_point_is_judged_at_its_own_uv(void**) {
  const dbs_folds::FoldShape shape = dbs_folds::fold_shape("tall-dome");
  const std::vector<Vec3> points = points_of(shape.xyz);
  const Boundary boundary(points_of(shape.bottom), points_of(shape.right), points_of(shape.top), points_of(shape.left));
  const Result r = parameterize(PointCloud(points), boundary, Options());
  // What parameterize reports is the count on every point against the last fold measure.
  const FoldMeasure all = measure_folds(points, r.u, r.v, r.noise, 2);
  const TurnedSheets whole = turned_sheets(r, {}, all, 2);
  assert_int_equal(whole.turned, r.turned_points);
  assert_true(whole.share == r.turned_share);
  // ... and its flags are those points, each once.
  assert_int_equal(whole.points.size(), whole.turned);
  const std::vector<std::int32_t> flags = r.point_flags();
  std::size_t flagged = 0;
  for (std::size_t i = 0; i < flags.size(); ++i) flagged += (flags[i] & kPointTurned) != 0;
  assert_int_equal(flagged, whole.turned);
  for (std::size_t i : whole.points) assert_true((flags[i] & kPointTurned) != 0);
  // Some turned, most not: a verdict read at another point's (u,v) would change the count.
  assert_true(whole.turned > 50 && whole.turned < whole.judged / 4);
  std::vector<std::size_t> every(points.size());
  for (std::size_t i = 0; i < every.size(); ++i) every[i] = i;
  assert_int_equal(whole.turned, turned_by_hand(r, every, all));
  // Every second point, judged from the subset's own measure.
  std::vector<std::size_t> judged;
  std::vector<Vec3> subset;
  std::vector<double> u, v;
  for (std::size_t i = 1; i < points.size(); i += 2) {
    judged.push_back(i);
    subset.push_back(points[i]);
    u.push_back(r.u[i]);
    v.push_back(r.v[i]);
  }
  const FoldMeasure half = measure_folds(subset, u, v, r.noise, 2);
  const TurnedSheets some = turned_sheets(r, judged, half, 2);
  assert_true(some.turned > 25 && some.turned < some.judged / 4);
  assert_int_equal(some.turned, turned_by_hand(r, judged, half));
  for (std::size_t i : some.points) assert_true(i % 2 == 1);  // indices of the result, not of the subset
}

void the_counts_do_not_depend_on_the_thread_count(void**) {
  const Fixture& f = fixture();
  const Result m = mirrored(f.result);
  const FoldMeasure folds = measure_folds(f.points, m.u, m.v, f.result.noise, 1);
  const TurnedSheets one = turned_sheets(m, {}, folds, 1);
  for (int threads : {2, 3, 0}) {
    const TurnedSheets other = turned_sheets(m, {}, folds, threads);
    assert_int_equal(other.judged, one.judged);
    assert_int_equal(other.turned, one.turned);
  }
}

void sizes_and_indices_that_do_not_fit_are_refused(void**) {
  const Fixture& f = fixture();
  const FoldMeasure folds = measure_folds(f.points, f.result.u, f.result.v, f.result.noise, 2);
  core_test::expect_error([&] { turned_sheets(f.result, {0, 1, 2}, folds, 1); }, ErrorCode::InvalidArgument, {"turned_sheets", "3 judged points", "3000 normals"});
  FoldMeasure fewer = folds;
  fewer.right_normal.pop_back();
  core_test::expect_error([&] { turned_sheets(f.result, {}, fewer, 1); }, ErrorCode::InvalidArgument, {"turned_sheets", "2999 normals for 3000 points"});
  std::vector<std::size_t> judged(3000);
  for (std::size_t i = 0; i < judged.size(); ++i) judged[i] = i;
  judged[7] = 3000;
  core_test::expect_error([&] { turned_sheets(f.result, judged, folds, 1); }, ErrorCode::InvalidArgument, {"turned_sheets", "judged point 3000 is not one of the 3000 points"});
}

}  // namespace

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(a_surface_that_agrees_with_its_uv_turns_nothing),
      cmocka_unit_test(a_mirrored_uv_on_the_same_surface_turns_every_point),
      cmocka_unit_test(a_judged_subset_gives_the_same_verdicts),
      cmocka_unit_test(each_point_is_judged_at_its_own_uv),
      cmocka_unit_test(the_counts_do_not_depend_on_the_thread_count),
      cmocka_unit_test(sizes_and_indices_that_do_not_fit_are_refused),
  };
  return cmocka_run_group_tests(tests, nullptr, nullptr);
}
