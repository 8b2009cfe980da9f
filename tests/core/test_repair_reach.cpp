// The reach of the last-resort repair (fold_repair.hpp): the narrow and the wide reaches from
// the same unrepaired result, the driver's choice among them, the snapshot that lets the
// driver undo one, and far points of a sparsely sampled sheet repaired rather than left as
// outliers. Reference triangles (fold_shapes) only score; the library never sees them.
#include <algorithm>
#include <cstdio>
#include <string>
#include <vector>

#include "boundary.hpp"
#include "fold_measure.hpp"
#include "fold_repair.hpp"
#include "fold_shapes.hpp"
#include "parameterize.hpp"
#include "point_cloud.hpp"
#include "repair_snapshot.hpp"

#include "core_test_support.hpp"
#include "fold_shape_runs.hpp"

namespace {

using dbs::Vec3;
using dbs_folds::FoldShape;

using fold_runs::points_of;
using fold_runs::reference_folds;

dbs::Result run(const FoldShape& shape, int repair, int threads = 0, int max_level = dbs::Options().max_level) {
  const dbs::Boundary boundary = fold_runs::boundary_of(shape);
  dbs::Options options;
  // The reaches are judged on the plain pass's result (the coarse pass, when it runs, repairs its own).
  options.coarse_pass = 0;
  options.repair = repair;
  options.threads = threads;
  options.max_level = max_level;
  return dbs::parameterize(dbs::PointCloud(points_of(shape.xyz)), boundary, options);
}

std::size_t doubted(const dbs::FoldMeasure& m) {
  std::size_t count = 0;
  for (std::int8_t s : m.state) count += dbs::doubted_verdict(s);
  return count;
}

/// The repair with `reach` applied to a copy of the unrepaired `plain`.
dbs::Result repaired(const dbs::Result& plain, const std::vector<Vec3>& points, dbs::RepairReach reach) {
  dbs::Result r = plain;
  const dbs::FoldMeasure first = dbs::measure_folds(points, r.u, r.v, r.noise, 1);
  r.repaired_points = dbs::repair_folds(r, points, dbs::doubtful_points(r, points, {}, first.state, 1, nullptr, reach), 1).repaired;
  return r;
}

bool same_parameters(const dbs::Result& a, const dbs::Result& b) {
  return a.u == b.u && a.v == b.v && a.distance == b.distance && a.patch == b.patch && a.level == b.level && a.repaired == b.repaired && a.repaired_points == b.repaired_points;
}

/// The mean distance of every point (repair_folds leaves the result's statistics to the
/// driver; the shapes here have no point left out).
double mean_distance(const dbs::Result& r) {
  double sum = 0.0;
  for (double d : r.distance) sum += d;
  return sum / static_cast<double>(r.distance.size());
}

/// The narrow reach and the wide ones of 1 .. kMaxWideRings rings, each from `plain`, and the
/// driver's rule: the narrow one, then a wide one wherever the measure doubts fewer points
/// than after the best so far and the mean distance is at most the unrepaired one.
struct Candidates {
  std::vector<dbs::Result> results;  // [0] narrow, [k] k wide rings
  std::vector<std::size_t> folds, doubts;
  std::vector<double> means;
  std::size_t best = 0;
  std::size_t refused_for_distance = 0;  // wide candidates that doubted less but fitted worse
};

Candidates candidates(const FoldShape& shape, const std::vector<Vec3>& points, const dbs::Result& plain) {
  Candidates c;
  for (int rings = 0; rings <= dbs::kMaxWideRings; ++rings) {
    c.results.push_back(repaired(plain, points, dbs::RepairReach{rings}));
    const dbs::Result& r = c.results.back();
    c.folds.push_back(reference_folds(shape, r));
    c.doubts.push_back(doubted(dbs::measure_folds(points, r.u, r.v, r.noise, 1)));
    c.means.push_back(mean_distance(r));
    if (rings > 0 && c.doubts.back() < c.doubts[c.best]) {
      if (c.means.back() <= mean_distance(plain)) c.best = c.results.size() - 1;
      else ++c.refused_for_distance;
    }
    std::printf("%s: %d wide rings: %zu reference folds, %zu doubted points, mean distance %.3g (unrepaired %.3g)\n", shape.name.c_str(), rings, c.folds.back(),
                c.doubts.back(), c.means.back(), mean_distance(plain));
  }
  return c;
}

/// The driver's last step on the chosen repair: its regions untangled (untangle_repaired),
/// kept only when neither the mean distance nor the points the measure doubts rise.
dbs::Result untangled(const dbs::Result& chosen, const std::vector<Vec3>& points) {
  dbs::Result r = chosen;
  if (dbs::untangle_repaired(r, points, 1).repaired == 0 || mean_distance(r) > mean_distance(chosen)) return chosen;
  if (doubted(dbs::measure_folds(points, r.u, r.v, r.noise, 1)) > doubted(dbs::measure_folds(points, chosen.u, chosen.v, chosen.noise, 1))) return chosen;
  return r;
}

/// A shape unrepaired, its candidate repairs, what the driver should make of them (the best
/// candidate untangled) and the driver's result (two threads).
struct Trial {
  FoldShape shape;
  std::vector<Vec3> points;
  dbs::Result plain, chosen;
  Candidates c;
  dbs::Result expected;
};

Trial trial(const char* name, double density, int max_level = dbs::Options().max_level, double noise = 0.0) {
  Trial t{dbs_folds::fold_shape(name, density, noise), {}, {}, {}, {}, {}};
  t.points = points_of(t.shape.xyz);
  t.plain = run(t.shape, 0, 0, max_level);
  t.c = candidates(t.shape, t.points, t.plain);
  t.chosen = run(t.shape, 1, 2, max_level);
  t.expected = untangled(t.c.results[t.c.best], t.points);
  std::printf("%s x%.2f: chosen candidate %zu (%zu reference folds), untangled %zu\n", name, density, t.c.best, t.c.folds[t.c.best], reference_folds(t.shape, t.expected));
  return t;
}

void wide_reach_unfolds_a_feature_the_surfaces_missed(void**) {
  // The mushroom at scan density: the surfaces never reach under its cap. The narrow fill is
  // held by misplaced points around it; a wide one reaches sound ground and folds far less
  // (180 narrow against 50 reference folds with 2 rings, 1104 without any repair; 96 before
  // the wide reaches took the points torn off their sheet at the stem's foot,
  // fold_measure.hpp), and the driver keeps the one the fold measure doubts least, then
  // untangles it.
  const Trial t = trial("mushroom", 2.5);
  const FoldShape& shape = t.shape;
  const std::vector<Vec3>& points = t.points;
  const dbs::Result &plain = t.plain, &chosen = t.chosen;
  const Candidates& c = t.c;
  const dbs::Result one_thread = run(shape, 1, 1);
  std::printf("mushroom x2.5: %zu reference folds unrepaired, %zu chosen\n", reference_folds(shape, plain), reference_folds(shape, chosen));
  assert_true(c.best > 0);
  assert_true(same_parameters(chosen, t.expected));
  assert_true(same_parameters(chosen, one_thread));  // the choice does not depend on the threads
  assert_true(3 * c.folds[c.best] < 2 * c.folds[0]);
  assert_true(chosen.mean_distance <= plain.mean_distance);
  // The untangling of the chosen repair: 50 -> 27 reference folds, no higher mean distance.
  assert_false(same_parameters(t.expected, c.results[c.best]));
  assert_true(3 * reference_folds(shape, chosen) < 2 * c.folds[c.best]);
  assert_true(mean_distance(chosen) <= c.means[c.best]);

  // The cap is sampled at about a tenth of the plate's density (its points spread along the
  // profile): far points there have fewer neighbours within a few spacings than a sheet at the
  // cloud's spacing would, which alone made them look like gross outliers, left at their
  // misplaced (u,v) amid the fill. Most of their nearest points are far too, so they are a
  // sheet and are repaired (the few left are those whose leaf's refit was not kept).
  const dbs::Result& narrow = c.results[0];
  std::size_t far = 0, left = 0;
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (!(plain.distance[i] > dbs::kRepairFactor * plain.accuracy && plain.distance[i] > dbs::kRepairSpacings * plain.length_scale)) continue;
    ++far;
    left += narrow.u[i] == plain.u[i] && narrow.v[i] == plain.v[i] && !narrow.repaired[i];
  }
  std::printf("mushroom x2.5: %zu far points, %zu left where they were\n", far, left);
  assert_true(far > 100);
  assert_true(left * 20 <= far);
}

void choice_on_a_tall_feature(void**) {
  // The tall dome at scan density: a wider fill crushes its walls (a harmonic map's (u,v)
  // shrink up a tube; with 3 rings, 3.9 times the narrow reach's reference folds), which the
  // measure sees; the driver keeps the reach it doubts least, here the one of 1 ring (189
  // reference folds and 56 doubted points; narrow: 226 and 67; 2 rings: 351 and 90), and
  // untangles it. (The narrow one was kept, 62 doubted points against 63, before the points
  // torn off their sheet at the dome's foot counted as doubted and were taken by the wide
  // reaches.)
  const Trial t = trial("tall-dome", 2.5);
  const FoldShape& shape = t.shape;
  const std::vector<Vec3>& points = t.points;
  const dbs::Result& chosen = t.chosen;
  const Candidates& c = t.c;
  assert_true(same_parameters(chosen, t.expected));
  assert_int_equal(c.best, 1);
  assert_true(c.doubts[dbs::kMaxWideRings] > c.doubts[0]);
  const dbs::Result crushed = repaired(t.plain, points, dbs::RepairReach{3});
  const std::size_t crushed_doubts = doubted(dbs::measure_folds(points, crushed.u, crushed.v, crushed.noise, 1));
  std::printf("tall dome x2.5: 3 wide rings: %zu reference folds, %zu doubted points\n", reference_folds(shape, crushed), crushed_doubts);
  assert_true(reference_folds(shape, crushed) > 2 * c.folds[0]);
  assert_true(crushed_doubts > c.doubts[c.best]);
  // Its walls' thin triangles untangled: 189 -> 90 reference folds.
  assert_true(2 * reference_folds(shape, chosen) < c.folds[c.best]);
  assert_true(mean_distance(chosen) <= c.means[c.best]);
}

void no_reach_raises_the_mean_distance(void**) {
  // The tall dome at scan density with at most 2 levels: the leaves never reach up its walls
  // and the repair fills them. The wide reaches leave fewer points the measure doubts (169
  // against 201 with 2 rings) but refill points off their feet, raising the mean distance
  // above the unrepaired one (0.0053 against 0.0016): the driver refuses them and keeps the
  // narrow repair (1024 reference folds to 409; it raises the mean distance too, to 0.0027:
  // with 2 levels this cloud is outside the set on which the repair was shown to lower both;
  // untangled, 337).
  const Trial t = trial("tall-dome", 2.5, 2);
  const FoldShape& shape = t.shape;
  const dbs::Result &plain = t.plain, &chosen = t.chosen;
  const Candidates& c = t.c;
  std::printf("tall dome x2.5, 2 levels: %zu wide candidates refused for their distance; reference folds %zu unrepaired, %zu chosen\n", c.refused_for_distance,
              reference_folds(shape, plain), reference_folds(shape, chosen));
  assert_true(c.refused_for_distance > 0);
  assert_true(same_parameters(chosen, t.expected));
  assert_int_equal(c.best, 0);
  assert_true(2 * reference_folds(shape, chosen) < reference_folds(shape, plain));
}

void reach_grows_with_the_points_across_the_cloud(void**) {
  // A ring is a step to the nearest points: the widest reach tried grows with sqrt(points), so
  // that it spans the same share of a denser cloud.
  assert_int_equal(dbs::max_wide_rings(0, false), dbs::kMaxWideRings);
  assert_int_equal(dbs::max_wide_rings(4096, false), 2);
  assert_int_equal(dbs::max_wide_rings(14399, false), 2);
  assert_int_equal(dbs::max_wide_rings(14400, false), 3);
  assert_int_equal(dbs::max_wide_rings(28223, false), 3);
  assert_int_equal(dbs::max_wide_rings(28224, false), 4);
  // Over the fold measure's sample of a large cloud (20,000 points), 3; on a cloud whose noise
  // floor is above the requested target, 2 at any size.
  assert_int_equal(dbs::max_wide_rings(20000, false), 3);
  assert_int_equal(dbs::max_wide_rings(20000, true), dbs::kMaxWideRings);
  assert_int_equal(dbs::max_wide_rings(4096, true), dbs::kMaxWideRings);
  // The fingers at 4 times the points (16,240): their missed tips span more rings than at
  // scan density. Up to 2 rings the repair left 287 folded reference triangles (dbs-bench-folds);
  // trying 3 leaves 15, at a lower mean distance.
  const FoldShape shape = dbs_folds::fold_shape("fingers", 4.0);
  const std::vector<Vec3> points = points_of(shape.xyz);
  assert_int_equal(dbs::max_wide_rings(points.size(), false), 3);
  const dbs::Result plain = run(shape, 0), chosen = run(shape, 1);
  const Candidates c = candidates(shape, points, plain);
  const std::size_t fewest = *std::min_element(c.folds.begin(), c.folds.end());
  std::printf("fingers x4: reference folds %zu unrepaired, %zu at best within 2 rings (before the untangling), %zu chosen; mean distance %.3g unrepaired, %.3g chosen\n",
              reference_folds(shape, plain), fewest, reference_folds(shape, chosen), plain.mean_distance, chosen.mean_distance);
  assert_true(4 * reference_folds(shape, chosen) < fewest);
  assert_true(reference_folds(shape, chosen) <= 40);
  assert_true(chosen.mean_distance <= plain.mean_distance);
}

void noisy_cloud_keeps_two_rings(void**) {
  // The tall dome at 4 times the points with noise of 0.5% of the diagonal along the normal:
  // its size alone would allow 3 rings, but its noise floor is above the requested target, so
  // the driver chooses among the narrow reach and 1 .. 2 rings only, as the candidates here
  // (with 3 the dome folded 266 -> 392 triangles at a higher mean distance, dbs-bench-folds).
  const Trial t = trial("tall-dome", 4.0, dbs::Options().max_level, 0.005);
  assert_int_equal(dbs::max_wide_rings(t.points.size(), false), 3);
  assert_true(t.chosen.accuracy > t.chosen.requested_accuracy);
  assert_true(same_parameters(t.chosen, t.expected));
}

void snapshot_puts_the_result_back_bit_for_bit(void**) {
  const FoldShape shape = dbs_folds::fold_shape("mushroom");
  const std::vector<Vec3> points = points_of(shape.xyz);
  dbs::Result r = run(shape, 0);
  const dbs::Result before = r;
  const dbs::RepairSnapshot snapshot(r);
  const dbs::FoldMeasure first = dbs::measure_folds(points, r.u, r.v, r.noise, 1);
  const dbs::Repair repair = dbs::repair_folds(r, points, dbs::doubtful_points(r, points, {}, first.state, 1, nullptr, dbs::RepairReach{dbs::kMaxWideRings}), 1);
  assert_true(repair.repaired > 0);
  assert_false(repair.refitted.empty());
  assert_false(same_parameters(r, before));
  // Everything the snapshot claims to put back is overwritten first (the driver's judging of
  // refitted leaves writes their figures, repair_folds does not); it keeps leaves only, as
  // no other patch is refitted or judged.
  r.repaired_points = 123456;
  for (dbs::Patch& p : r.patches) {
    if (!p.is_leaf()) continue;
    p.mean_distance = p.max_distance = p.error = -1.0;
    p.accurate = !p.accurate;
  }
  snapshot.restore(r);
  assert_true(same_parameters(r, before));
  for (std::size_t k = 0; k < r.patches.size(); ++k) {
    const dbs::Patch &a = r.patches[k], &b = before.patches[k];
    assert_true(a.mean_distance == b.mean_distance && a.max_distance == b.max_distance && a.error == b.error && a.accurate == b.accurate);
    assert_int_equal(a.grid.nu, b.grid.nu);
    for (int j = 0; j < a.grid.nv; ++j)
      for (int i = 0; i < a.grid.nu; ++i) assert_true(a.grid(i, j) == b.grid(i, j));
    for (double s : {0.1, 0.5, 0.9}) assert_true(a.surface.eval(s, 1.0 - s) == b.surface.eval(s, 1.0 - s));
  }
  // Restoring into another result is refused, not done.
  dbs::Result other = run(dbs_folds::fold_shape("cone"), 0);
  assert_true(core_test::throws(dbs::ErrorCode::Internal, [&] { snapshot.restore(other); }));
}

}  // namespace

int main() {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(snapshot_puts_the_result_back_bit_for_bit),
      cmocka_unit_test(wide_reach_unfolds_a_feature_the_surfaces_missed),
      cmocka_unit_test(choice_on_a_tall_feature),
      cmocka_unit_test(no_reach_raises_the_mean_distance),
      cmocka_unit_test(reach_grows_with_the_points_across_the_cloud),
      cmocka_unit_test(noisy_cloud_keeps_two_rings),
  };
  return cmocka_run_group_tests_name("repair_reach", tests, nullptr, nullptr);
}
