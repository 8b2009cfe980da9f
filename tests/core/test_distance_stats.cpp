// Distance statistics: exact values on a known set, per-patch grouping, the share within a
// tolerance, percentile interpolation, argument errors.
#include <cmath>
#include <vector>

#include "distance_stats.hpp"
#include "error.hpp"
#include "summary_stats.hpp"
#include "core_test_support.hpp"  // last of the dbs headers

namespace {

using core_test::error_code_of;

bool near(double a, double b) { return std::abs(a - b) <= 1e-12 * std::max(1.0, std::abs(b)); }

void test_known_values(void**) {
  // distances 1..100 in scrambled order; odd ones on patch 0, even ones on patch 2, patch 1 empty
  std::vector<double> d;
  std::vector<std::int32_t> patch;
  for (int k = 0; k < 100; ++k) {
    const int value = (k * 37) % 100 + 1;
    d.push_back(value);
    patch.push_back(value % 2 == 1 ? 0 : 2);
  }
  const dbs::DistanceReport r = dbs::distance_statistics(d, patch, 3, 90.0);
  const dbs::DistanceStats& all = r.overall;
  assert_int_equal(all.count, 100);
  assert_true(near(all.mean, 50.5));
  assert_true(near(all.rms, std::sqrt(338350.0 / 100.0)));  // sum of k^2 = 338350
  assert_true(near(all.max, 100.0));
  assert_true(near(all.p50, 50.5));
  assert_true(near(all.p90, 90.1));
  assert_true(near(all.p95, 95.05));
  assert_true(near(all.p99, 99.01));
  assert_true(near(all.within, 0.9));
  assert_int_equal(r.per_patch.size(), 3);
  assert_int_equal(r.per_patch[0].count, 50);
  assert_true(near(r.per_patch[0].mean, 50.0));  // 1, 3, ..., 99
  assert_true(near(r.per_patch[0].max, 99.0));
  assert_true(near(r.per_patch[0].within, 45.0 / 50.0));
  assert_int_equal(r.per_patch[1].count, 0);
  assert_true(r.per_patch[1].mean == 0.0 && r.per_patch[1].within == 0.0);
  assert_true(near(r.per_patch[2].mean, 51.0));  // 2, 4, ..., 100
  assert_true(near(r.per_patch[2].p50, 51.0));
  // the tolerance is inclusive
  assert_true(near(dbs::distance_statistics(d, patch, 3, 1.0).overall.within, 0.01));
  assert_true(near(dbs::distance_statistics(d, patch, 3, 0.0).overall.within, 0.0));
}

void test_percentile(void**) {
  const std::vector<double> sorted{1.0, 2.0, 4.0, 8.0};
  assert_true(near(dbs::percentile_of_sorted(sorted, 0.0), 1.0));
  assert_true(near(dbs::percentile_of_sorted(sorted, 100.0), 8.0));
  assert_true(near(dbs::percentile_of_sorted(sorted, 50.0), 3.0));
  assert_true(near(dbs::percentile_of_sorted(sorted, 200.0 / 3.0), 4.0));
  assert_true(dbs::percentile_of_sorted({}, 50.0) == 0.0);
  const dbs::MeasureSummary s = dbs::summarize({3.0, 1.0, 2.0});
  assert_true(near(s.min, 1.0) && near(s.mean, 2.0) && near(s.p95, 2.9) && near(s.max, 3.0));
}

void test_errors(void**) {
  const std::vector<double> d{0.1, 0.2};
  assert_int_equal(error_code_of([&] { dbs::distance_statistics(d, {0}, 1, 0.1); }), dbs::ErrorCode::InvalidArgument);
  assert_int_equal(error_code_of([&] { dbs::distance_statistics(d, {0, 1}, 1, 0.1); }), dbs::ErrorCode::OutOfRange);
  assert_int_equal(error_code_of([&] { dbs::distance_statistics(d, {0, -1}, 1, 0.1); }), dbs::ErrorCode::OutOfRange);
  assert_int_equal(error_code_of([&] { dbs::distance_statistics(d, {0, 0}, 1, -0.1); }), dbs::ErrorCode::OutOfRange);
  assert_int_equal(error_code_of([&] { dbs::distance_statistics(d, {0, 0}, 1, std::nan("")); }), dbs::ErrorCode::NonFinite);
  assert_int_equal(error_code_of([&] { dbs::distance_statistics({0.1, INFINITY}, {0, 0}, 1, 0.1); }), dbs::ErrorCode::NonFinite);
}

}  // namespace

int main() {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(test_known_values),
      cmocka_unit_test(test_percentile),
      cmocka_unit_test(test_errors),
  };
  return cmocka_run_group_tests(tests, nullptr, nullptr);
}
