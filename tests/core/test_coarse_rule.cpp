// The coarse pass's rules (coarse_pass.hpp) on made-up results: when the pass runs, the ratio
// at which it is given up, and which result is kept, fit first and folds first, at the edges
// of each bound (kCoarseTurnedShare, kCoarseScrambleRatio, kCoarseScrambledShare,
// kCoarseFitSlack).
#include "boundary.hpp"
#include "coarse_pass.hpp"

#include "core_test_support.hpp"

namespace {

using dbs::Options;
using dbs::Result;

Options mode(int coarse_pass) {
  Options o;
  o.coarse_pass = coarse_pass;
  return o;
}

/// A result of 10,000 judged points with the figures the rules read.
Result result(double mean_distance, std::size_t turned, std::size_t folded, std::size_t undecided) {
  Result r;
  r.accuracy = 1.0;
  r.mean_distance = mean_distance;
  r.turned_points = turned;
  r.judged_points = 10000;
  r.folded_points = folded;
  r.undecided_points = undecided;
  return r;
}

/// A plain result whose root was (or was not) far above its target, with `levels` levels.
Result pleated(bool far_above, int levels, double turned_share) {
  Result r = result(1.0, 0, 0, 0);
  const dbs::Boundary square({{0, 0, 0}, {1, 0, 0}}, {{1, 0, 0}, {1, 1, 0}}, {{0, 1, 0}, {1, 1, 0}}, {{0, 0, 0}, {0, 1, 0}});
  r.patches.emplace_back(dbs::BaseSurface(square));
  r.patches.front().far_above = far_above;
  r.levels = levels;
  r.turned_share = turned_share;
  return r;
}

void runs_where_the_plain_pass_pleated(void**) {
  assert_true(dbs::coarse_pass_wanted(mode(dbs::kCoarseFoldsFirst), pleated(true, 2, 0.031)));
  assert_true(dbs::coarse_pass_wanted(mode(dbs::kCoarseFitFirst), pleated(true, 5, 0.2)));
  assert_false(dbs::coarse_pass_wanted(mode(0), pleated(true, 5, 0.2)));
  assert_false(dbs::coarse_pass_wanted(mode(dbs::kCoarseFoldsFirst), pleated(false, 5, 0.2)));
  assert_false(dbs::coarse_pass_wanted(mode(dbs::kCoarseFoldsFirst), pleated(true, 1, 0.2)));
  assert_false(dbs::coarse_pass_wanted(mode(dbs::kCoarseFoldsFirst), pleated(true, 5, dbs::kCoarseTurnedShare)));
  assert_false(dbs::coarse_pass_wanted(mode(dbs::kCoarseFoldsFirst), Result()));
}

void gives_up_at_the_mode_s_ratio(void**) {
  assert_true(dbs::coarse_abandon_ratio(mode(dbs::kCoarseFitFirst)) == 1.0);
  assert_true(dbs::coarse_abandon_ratio(mode(dbs::kCoarseFoldsFirst)) == dbs::kCoarseAbandonRatio);
  assert_true(dbs::kCoarseAbandonRatio > 1.0);
}

void fit_first_keeps_on_the_fit(void**) {
  const Options fit = mode(dbs::kCoarseFitFirst);
  // Within the larger of the plain mean distance and the target, fewer turned points.
  assert_true(dbs::coarse_is_better(fit, result(0.5, 100, 0, 0), result(1.0, 99, 0, 0)));
  assert_true(dbs::coarse_is_better(fit, result(2.0, 100, 0, 0), result(2.0, 99, 0, 0)));
  assert_false(dbs::coarse_is_better(fit, result(2.0, 100, 0, 0), result(2.0, 100, 0, 0)));
  assert_false(dbs::coarse_is_better(fit, result(2.0, 100, 0, 0), result(2.001, 10, 0, 0)));
  // More unpassed points do not matter, nor does a scrambled plain result buy any slack.
  assert_true(dbs::coarse_is_better(fit, result(2.0, 100, 0, 10), result(2.0, 99, 50, 500)));
  assert_false(dbs::coarse_is_better(fit, result(1.0, 100, 100, 900), result(1.5, 10, 0, 0)));
}

void folds_first_refuses_more_unpassed_points(void**) {
  const Options folds = mode(dbs::kCoarseFoldsFirst);
  assert_true(dbs::coarse_is_better(folds, result(2.0, 100, 5, 10), result(2.0, 99, 5, 10)));
  assert_false(dbs::coarse_is_better(folds, result(2.0, 100, 5, 10), result(2.0, 99, 5, 11)));
  assert_false(dbs::coarse_is_better(folds, result(2.0, 100, 5, 10), result(1.0, 99, 16, 0)));
  assert_false(dbs::coarse_is_better(folds, result(2.0, 100, 0, 0), result(1.0, 100, 0, 0)));
}

void folds_first_trades_fit_where_the_plain_result_is_scrambled(void**) {
  const Options folds = mode(dbs::kCoarseFoldsFirst);
  // Scrambled: 101 > 2 x 50 unpassed points, and above 0.5% of the 10,000 judged.
  const Result plain = result(0.5, 100, 1, 100);
  assert_true(dbs::coarse_is_better(folds, plain, result(dbs::kCoarseFitSlack, 99, 0, 50)));
  assert_false(dbs::coarse_is_better(folds, plain, result(dbs::kCoarseFitSlack * 1.001, 99, 0, 50)));
  // The slack is on the larger of the plain mean distance and the target.
  assert_true(dbs::coarse_is_better(folds, result(2.0, 100, 1, 100), result(2.0 * dbs::kCoarseFitSlack, 99, 0, 50)));
  // Not scrambled: exactly twice the coarse result's unpassed points ...
  assert_false(dbs::coarse_is_better(folds, result(0.5, 100, 0, 100), result(1.5, 99, 0, 50)));
  // ... or too few of the judged points (50 = 0.5%), however many times the coarse result's.
  assert_false(dbs::coarse_is_better(folds, result(0.5, 100, 0, 50), result(1.5, 99, 0, 0)));
  assert_true(dbs::coarse_is_better(folds, result(0.5, 100, 0, 51), result(1.5, 99, 0, 0)));
  // Still never with as many points on turned sheets.
  assert_false(dbs::coarse_is_better(folds, plain, result(1.5, 100, 0, 0)));
}

}  // namespace

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(runs_where_the_plain_pass_pleated),
      cmocka_unit_test(gives_up_at_the_mode_s_ratio),
      cmocka_unit_test(fit_first_keeps_on_the_fit),
      cmocka_unit_test(folds_first_refuses_more_unpassed_points),
      cmocka_unit_test(folds_first_trades_fit_where_the_plain_result_is_scrambled),
  };
  return cmocka_run_group_tests(tests, nullptr, nullptr);
}
