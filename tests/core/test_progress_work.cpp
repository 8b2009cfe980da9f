// Progress by work, not by clock: on a cloud that needs the quadtree, every stage that does
// counted work (points projected, grid nodes solved) reports at most a bounded number of work
// units apart, with one thread and with two; the number of reports does not depend on the
// thread count; a cancel asked at any report during the levels stops the run.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "analytic_clouds.hpp"
#include "error.hpp"
#include "parameterize.hpp"
#include "work_meter.hpp"

// cmocka last: its fail() macro would hide dbs::fail.
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
extern "C" {
#include <cmocka.h>
}

using namespace dbs;
using namespace dbs_test;

namespace {

/// Ripples an 11 x 11 grid cannot follow: the root subdivides, the run has every stage.
Surface rippled() {
  return [](double x, double y) { return Vec3(x, y, 0.2 * std::sin(M_PI * x) * std::sin(M_PI * y) + 0.03 * std::sin(8 * M_PI * x) * std::sin(8 * M_PI * y)); };
}

struct Report {
  std::string stage;
  unsigned long long units;
};

struct Run {
  std::vector<Report> reports;
  int levels = 0;
};

Run run_with_probe(int threads, std::size_t cancel_at = 0, bool* cancelled = nullptr) {
  static const PointCloud cloud(random_points(rippled(), 40000, 17));
  static const Boundary boundary = boundary_of(rippled(), 200);
  Options o;
  o.relative_accuracy = 2e-4;
  o.max_level = 3;
  o.threads = threads;
  Run run;
  o.work_probe = [&](const char* stage, unsigned long long units) { run.reports.push_back({stage, units}); };
  o.progress = [&](double, const char*) { return cancel_at > 0 && run.reports.size() == cancel_at; };
  try {
    run.levels = parameterize(cloud, boundary, o).levels;
  } catch (const Error& e) {
    assert_int_equal(static_cast<int>(e.code()), static_cast<int>(ErrorCode::Cancelled));
    if (cancelled) *cancelled = true;
  }
  return run;
}

/// Largest number of units between two reports of the same stage.
unsigned long long largest_gap(const Run& run) {
  unsigned long long gap = 0;
  for (std::size_t k = 1; k < run.reports.size(); ++k)
    if (run.reports[k].stage == run.reports[k - 1].stage) gap = std::max(gap, run.reports[k].units - run.reports[k - 1].units);
  return gap;
}

void reports_come_after_bounded_work(void**) {
  // One report per WorkMeter::kDefaultReportEvery units; between two reports at most that
  // plus the largest single count (a grid section of at most 512 densified nodes) with one thread. With two, a
  // report comes when the waiting caller is scheduled (later on a loaded machine), so only
  // the number and stages of the reports are compared.
  const unsigned long long every = WorkMeter::kDefaultReportEvery, largest_count = 512;
  const Run one = run_with_probe(1), two = run_with_probe(2);
  assert_true(one.levels >= 3);
  std::printf("reports: %zu (1 thread), %zu (2 threads); units %llu; largest gap %llu / %llu units\n", one.reports.size(), two.reports.size(), one.reports.back().units, largest_gap(one), largest_gap(two));
  assert_true(one.reports.back().units > 50 * every);  // enough work that reports matter
  assert_true(largest_gap(one) <= every + largest_count);
  // The same work in the same stages whatever the thread count.
  assert_int_equal(one.reports.size(), two.reports.size());
  for (std::size_t k = 0; k < one.reports.size(); ++k) assert_string_equal(one.reports[k].stage.c_str(), two.reports[k].stage.c_str());
  assert_true(one.reports.back().units == two.reports.back().units);
  // Every working stage reports along the way, not only at its start.
  for (const char* stage : {"evolve", "subdivide", "parameterize"}) {
    const auto n = std::count_if(one.reports.begin(), one.reports.end(), [&](const Report& r) { return r.stage == stage; });
    assert_true(n >= 3);
  }
}

void a_cancel_at_any_report_stops_the_run(void**) {
  const Run full = run_with_probe(2);
  for (std::size_t at : {std::size_t{2}, full.reports.size() / 4, full.reports.size() / 2, full.reports.size() - 2}) {
    bool cancelled = false;
    const Run run = run_with_probe(2, at, &cancelled);
    assert_true(cancelled);
    assert_int_equal(run.reports.size(), at);  // no report after the one that cancelled
  }
}

}  // namespace

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(reports_come_after_bounded_work),
      cmocka_unit_test(a_cancel_at_any_report_stops_the_run),
  };
  return cmocka_run_group_tests(tests, nullptr, nullptr);
}
