// The coarse pass (DBS_OPT_COARSE_PASS, coarse_pass.hpp) on the hard shapes of
// tests/support/fold_shapes, against a run without it:
// - the 10,201-point tall dome: its root ends far above the target and 9% of its points lie on
//   turned sheets, so the coarse pass runs and is kept: 90 folded reference triangles -> 7,
//   points on turned sheets 915 -> 172, the mean distance 0.00071 -> 0.00033 (target
//   0.00153); the same result for one and two threads;
// - the same run counts both passes' time, reports its progress up to 1.0 ("done" last and
//   only once) and its levels for both passes (each from level 0), and a cancel from either
//   callback during the second pass stops it;
// - a shape that does not pleat (the 4,096-point tall dome: 2.7% turned) runs once, bit for bit
//   the run without the option;
// - where the coarse pass's first level fits more than twice worse than the first pass's
//   (the 7,744-point tall dome, whose coarse root leaves the wall unreached), that pass is
//   given up after level 0 and the first result is kept, bit for bit;
// - where the plain result is scrambled (the 8,649-point mushroom: the plain surfaces reach
//   the cap by pleating and scatter its points in (u,v), 126 points the fold measure cannot
//   pass against 15), the coarse result is kept although it fits worse (within
//   kCoarseFitSlack): 23 -> 10 folded reference triangles; fit first (DBS_OPT_COARSE_PASS 2),
//   its second pass is given up after level 0 and the first result stands;
// - folds first refuses a coarse result with more points the fold measure cannot pass (the
//   4,489-point tall dome: 120 against 12, 6 folded reference triangles against 2), which fit
//   first keeps for its fit (3.7 -> 0.97 times the target);
// - a coarse result with more points on turned sheets (the 9,025-point mushroom) is dropped
//   after its whole run, and the first result is kept, bit for bit.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <string>
#include <vector>

#include "coarse_pass.hpp"
#include "fold_shapes.hpp"
#include "parameterize.hpp"
#include "point_cloud.hpp"

#include "core_test_support.hpp"
#include "fold_shape_runs.hpp"

namespace {

using dbs_folds::FoldShape;

struct Run {
  dbs::Result result;
  std::size_t folds = 0;  // folded reference triangles (inverted or collapsed)
};

Run run(const FoldShape& shape, int coarse_pass, int threads = 2, dbs::Options options = dbs::Options()) {
  options.coarse_pass = coarse_pass;
  options.threads = threads;
  if (!options.warning) options.warning = [](const char*) {};
  Run r{dbs::parameterize(dbs::PointCloud(fold_runs::points_of(shape.xyz)), fold_runs::boundary_of(shape), options), 0};
  r.folds = fold_runs::reference_folds(shape, r.result);
  return r;
}

/// run() with the levels the level callback saw, in order, into `levels`.
Run run_recording_levels(const FoldShape& shape, int coarse_pass, std::vector<int>& levels) {
  dbs::Options options;
  options.on_level = [&levels](int level, const std::vector<const dbs::Patch*>&) {
    levels.push_back(level);
    return false;
  };
  return run(shape, coarse_pass, 2, options);
}

/// Whether a second pass after `plain`'s was given up after its first level: the level
/// callback saw the plain pass's levels and level 0 once more.
bool given_up_after_level_0(const std::vector<int>& levels, const Run& plain) {
  return static_cast<int>(levels.size()) == plain.result.levels + 1 && levels.back() == 0;
}

void print_run(const char* name, const Run& r) {
  std::printf("%s: passes %d, coarse %d, mean distance %.3g (target %.3g), %zu folded reference triangles\n", name, r.result.passes, r.result.coarse ? 1 : 0, r.result.mean_distance,
              r.result.accuracy, r.folds);
}

bool same_parameters(const dbs::Result& a, const dbs::Result& b) {
  return a.u == b.u && a.v == b.v && a.distance == b.distance && a.patch == b.patch && a.level == b.level && a.mean_distance == b.mean_distance;
}

void tall_dome_keeps_the_coarse_pass(void**) {
  const FoldShape shape = dbs_folds::fold_shape("tall-dome", 2.5);
  const Run plain = run(shape, 0);
  const Run coarse = run(shape, 1);
  std::printf("tall dome x2.5: %zu -> %zu folded reference triangles, %zu -> %zu turned points, mean distance %.3g -> %.3g (target %.3g), passes %d, coarse %d\n", plain.folds, coarse.folds,
              plain.result.turned_points, coarse.result.turned_points, plain.result.mean_distance, coarse.result.mean_distance, coarse.result.accuracy, coarse.result.passes,
              coarse.result.coarse ? 1 : 0);
  assert_int_equal(plain.result.passes, 1);
  assert_false(plain.result.coarse);
  assert_true(plain.result.patches.at(0).far_above);
  assert_true(plain.result.turned_share > dbs::kCoarseTurnedShare);
  assert_int_equal(coarse.result.passes, 2);
  assert_true(coarse.result.coarse);
  // The rule that kept it, and what it bought: a tenth of the folds or less, fewer turned points.
  assert_true(coarse.result.mean_distance <= std::max(plain.result.accuracy, plain.result.mean_distance));
  assert_true(coarse.result.turned_points < plain.result.turned_points);
  assert_true(plain.folds >= 60);
  assert_true(coarse.folds * 5 <= plain.folds);
  assert_true(coarse.result.mean_distance <= coarse.result.accuracy);
  const Run one_thread = run(shape, 1, 1);
  assert_true(same_parameters(one_thread.result, coarse.result));
}

void callbacks_over_two_passes(void**) {
  const FoldShape shape = dbs_folds::fold_shape("tall-dome", 2.5);
  dbs::Options options;
  std::vector<std::pair<double, std::string>> reports;
  options.progress = [&](double fraction, const char* stage) {
    reports.emplace_back(fraction, stage);
    return false;
  };
  std::vector<int> levels;
  options.on_level = [&](int level, const std::vector<const dbs::Patch*>&) {
    levels.push_back(level);
    return false;
  };
  const auto start = std::chrono::steady_clock::now();
  const Run r = run(shape, 1, 2, options);
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  assert_int_equal(r.result.passes, 2);
  // Both passes' time is counted (each alone is well under the whole), and the stages add up to it.
  assert_true(r.result.seconds >= 0.9 * wall && r.result.seconds <= wall);
  const dbs::Result::StageSeconds& s = r.result.stage_seconds;
  assert_true(std::abs(s.index + s.evolve + s.subdivide + s.parameterize + s.folds - r.result.seconds) <= 0.05 * r.result.seconds);
  // Monotone, "done" once and last, at exactly 1.
  for (std::size_t k = 1; k < reports.size(); ++k) assert_true(reports[k].first >= reports[k - 1].first);
  assert_true(reports.back().first == 1.0 && reports.back().second == "done");
  assert_int_equal(std::count_if(reports.begin(), reports.end(), [](const auto& r) { return r.second == "done"; }), 1);
  for (std::size_t k = 0; k + 1 < reports.size(); ++k) assert_true(reports[k].first < 1.0);
  // Each pass reports its levels from 0 up.
  assert_int_equal(std::count(levels.begin(), levels.end(), 0), 2);
  assert_true(levels.size() >= 2 * 2);
  // A cancel during the second pass stops the run: from the level callback ...
  auto cancelled_by = [&](const dbs::Options& cancelling) {
    try {
      run(shape, 1, 2, cancelling);
    } catch (const dbs::Error& e) {
      return e.code() == dbs::ErrorCode::Cancelled;
    }
    return false;
  };
  dbs::Options cancelling;
  bool second = false;
  cancelling.on_level = [&](int level, const std::vector<const dbs::Patch*>&) {
    if (level == 0 && second) return true;
    if (level == 0) second = true;
    return false;
  };
  assert_true(cancelled_by(cancelling));
  // ... and from the progress callback, once the second pass indexes the cloud.
  dbs::Options by_progress;
  bool folds_seen = false;
  by_progress.progress = [&](double, const char* stage) {
    if (std::string(stage) == "folds") folds_seen = true;
    return folds_seen && std::string(stage) == "index";
  };
  assert_true(cancelled_by(by_progress));
}

void unpleated_runs_once(void**) {
  const FoldShape shape = dbs_folds::fold_shape("tall-dome");
  const Run plain = run(shape, 0);
  const Run coarse = run(shape, 1);
  // Far above the target at its root, but few points on turned sheets.
  assert_true(plain.result.patches.at(0).far_above);
  assert_true(plain.result.turned_share <= dbs::kCoarseTurnedShare);
  assert_int_equal(coarse.result.passes, 1);
  assert_false(coarse.result.coarse);
  assert_true(same_parameters(plain.result, coarse.result));
}

void far_worse_first_level_gives_up(void**) {
  const FoldShape shape = dbs_folds::fold_shape("tall-dome", 1.9);
  const Run plain = run(shape, 0);
  std::vector<int> levels;
  const Run r = run_recording_levels(shape, 1, levels);
  print_run("tall dome x1.9", r);
  assert_int_equal(r.result.passes, 2);
  assert_false(r.result.coarse);
  assert_true(same_parameters(plain.result, r.result));
  assert_true(given_up_after_level_0(levels, plain));
}

void scrambled_plain_keeps_the_coarse_pass(void**) {
  const FoldShape shape = dbs_folds::fold_shape("mushroom", 2.1);
  const Run plain = run(shape, 0);
  const Run coarse = run(shape, 1);
  std::printf("mushroom x2.1: %zu -> %zu folded reference triangles, %zu -> %zu points the fold measure cannot pass, %zu -> %zu turned points, mean distance %.3g -> %.3g (target %.3g), coarse %d\n",
              plain.folds, coarse.folds, dbs::unpassed_points(plain.result), dbs::unpassed_points(coarse.result), plain.result.turned_points, coarse.result.turned_points, plain.result.mean_distance,
              coarse.result.mean_distance, coarse.result.accuracy, coarse.result.coarse ? 1 : 0);
  assert_int_equal(coarse.result.passes, 2);
  assert_true(coarse.result.coarse);
  // Kept on the slack of a scrambled plain result: it fits worse than the plain one and the
  // target, within kCoarseFitSlack, and the plain result has more than kCoarseScrambleRatio
  // times its doubted points.
  const double fit = std::max(plain.result.accuracy, plain.result.mean_distance);
  assert_true(coarse.result.mean_distance > fit);
  assert_true(coarse.result.mean_distance <= dbs::kCoarseFitSlack * fit);
  assert_true(static_cast<double>(dbs::unpassed_points(plain.result)) > dbs::kCoarseScrambleRatio * static_cast<double>(dbs::unpassed_points(coarse.result)));
  assert_true(coarse.result.turned_points < plain.result.turned_points);
  // What it bought: half the folds or fewer.
  assert_true(plain.folds >= 15);
  assert_true(coarse.folds * 2 <= plain.folds);
  // Fit first, the same second pass is given up after its first level, which fits worse than
  // the plain pass's (but not twice worse), and the plain result stands, bit for bit.
  assert_true(coarse.result.first_level_error > plain.result.first_level_error);
  assert_true(coarse.result.first_level_error <= dbs::kCoarseAbandonRatio * plain.result.first_level_error);
  std::vector<int> levels;
  const Run fit_first = run_recording_levels(shape, dbs::kCoarseFitFirst, levels);
  assert_int_equal(fit_first.result.passes, 2);
  assert_false(fit_first.result.coarse);
  assert_true(same_parameters(plain.result, fit_first.result));
  assert_true(given_up_after_level_0(levels, plain));
}

void folds_first_refuses_more_unpassed_points(void**) {
  const FoldShape shape = dbs_folds::fold_shape("tall-dome", 1.1);
  const Run plain = run(shape, 0);
  const Run folds_first = run(shape, dbs::kCoarseFoldsFirst);
  const Run fit_first = run(shape, dbs::kCoarseFitFirst);
  std::printf("tall dome x1.1: plain %zu folded reference triangles, %zu points the fold measure cannot pass, mean distance %.3g; coarse %zu, %zu, %.3g (target %.3g)\n", plain.folds,
              dbs::unpassed_points(plain.result), plain.result.mean_distance, fit_first.folds, dbs::unpassed_points(fit_first.result), fit_first.result.mean_distance,
              plain.result.accuracy);
  // The coarse result fits better and has fewer points on turned sheets: fit first keeps it ...
  assert_int_equal(fit_first.result.passes, 2);
  assert_true(fit_first.result.coarse);
  assert_true(fit_first.result.mean_distance <= plain.result.mean_distance);
  assert_true(fit_first.result.turned_points < plain.result.turned_points);
  // ... but it has more points the fold measure cannot pass, and more folds: folds first keeps
  // the plain result, bit for bit.
  assert_true(dbs::unpassed_points(fit_first.result) > dbs::unpassed_points(plain.result));
  assert_true(fit_first.folds > plain.folds);
  assert_int_equal(folds_first.result.passes, 2);
  assert_false(folds_first.result.coarse);
  assert_true(same_parameters(plain.result, folds_first.result));
}

void more_turned_points_keep_the_first(void**) {
  const FoldShape shape = dbs_folds::fold_shape("mushroom", 2.2);
  const Run plain = run(shape, 0);
  std::vector<int> levels;
  const Run r = run_recording_levels(shape, 1, levels);
  print_run("mushroom x2.2", r);
  // The second pass ran to its end (its first level fit less than twice worse) and was
  // dropped: the first result stands, bit for bit.
  assert_int_equal(r.result.passes, 2);
  assert_false(r.result.coarse);
  assert_true(same_parameters(plain.result, r.result));
  assert_int_equal(std::count(levels.begin(), levels.end(), 0), 2);
  assert_true(static_cast<int>(levels.size()) > plain.result.levels + 2);
}

}  // namespace

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(tall_dome_keeps_the_coarse_pass),
      cmocka_unit_test(callbacks_over_two_passes),
      cmocka_unit_test(unpleated_runs_once),
      cmocka_unit_test(far_worse_first_level_gives_up),
      cmocka_unit_test(scrambled_plain_keeps_the_coarse_pass),
      cmocka_unit_test(more_turned_points_keep_the_first),
      cmocka_unit_test(folds_first_refuses_more_unpassed_points),
  };
  return cmocka_run_group_tests(tests, nullptr, nullptr);
}
