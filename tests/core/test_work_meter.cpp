// WorkMeter: every index once, one report per multiple of the report interval whatever the
// thread count, reports only on the calling thread, and a report that throws (a cancel)
// stops the workers at their next count.
#include <atomic>
#include <stdexcept>
#include <thread>
#include <vector>

#include "error.hpp"
#include "work_meter.hpp"
#include "core_test_support.hpp"  // last of the dbs headers

using dbs::WorkMeter;

namespace {

void every_index_once_and_reports_by_work(void**) {
  for (int threads : {1, 2, 3}) {
    WorkMeter meter(100);
    const std::thread::id caller = std::this_thread::get_id();
    int reports = 0;
    bool off_thread = false;
    meter.set_report([&] {
      ++reports;
      off_thread |= std::this_thread::get_id() != caller;
    });
    std::vector<std::atomic<int>> seen(10007);
    meter.run(seen.size(), threads, [&](std::size_t i) {
      seen[i].fetch_add(1);
      meter.add(3);
    });
    for (const auto& s : seen) assert_int_equal(s.load(), 1);
    assert_int_equal(reports, 10007 * 3 / 100);
    assert_false(off_thread);
  }
}

void a_nested_loop_reports_too(void**) {
  // One outer item on the caller's thread running an inner loop on two threads.
  WorkMeter meter(10);
  int reports = 0;
  meter.set_report([&] { ++reports; });
  meter.run(1, 2, [&](std::size_t) { dbs::metered_for(&meter, 1000, 2, [&](std::size_t) { meter.add(); }); });
  assert_int_equal(reports, 100);
}

void a_throwing_report_cancels_the_workers(void**) {
  for (int threads : {1, 2}) {
    WorkMeter meter(50);
    meter.set_report([] { throw dbs::Error(dbs::ErrorCode::Cancelled, "asked"); });
    std::atomic<std::size_t> bodies{0};
    // With two threads a worker adds its units to the shared count a batch at a time, so the report at 50
    // comes once at most 50 + (kWorkerBatch - 1) units a worker were counted.
    const std::size_t waits_from = threads > 1 ? 50 + static_cast<std::size_t>(threads) * WorkMeter::kWorkerBatch : 60;
    const dbs::ErrorCode code = core_test::error_code_of([&] {
      meter.run(100000, threads, [&](std::size_t) {
        meter.add();
        // Past that a worker waits for the cancel the report brings, so the count below does
        // not depend on how fast the caller wakes up.
        if (bodies.fetch_add(1) >= waits_from && threads > 1)
          while (!meter.cancelled()) std::this_thread::yield();
      });
    });
    assert_true(code == dbs::ErrorCode::Cancelled);
    assert_true(meter.cancelled());
    // Each worker stops at its next count after the cancel.
    assert_true(bodies.load() <= waits_from + 2 * static_cast<std::size_t>(threads));
    assert_true(core_test::error_code_of([&] { meter.add(); }) == dbs::ErrorCode::Cancelled);
  }
}

void a_worker_error_reaches_the_caller(void**) {
  WorkMeter meter;
  bool caught = false;
  try {
    meter.run(1000, 2, [&](std::size_t i) {
      if (i == 700) throw std::runtime_error("worker");
      meter.add();
    });
  } catch (const std::runtime_error&) {
    caught = true;
  }
  assert_true(caught);
}

}  // namespace

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(every_index_once_and_reports_by_work),
      cmocka_unit_test(a_nested_loop_reports_too),
      cmocka_unit_test(a_throwing_report_cancels_the_workers),
      cmocka_unit_test(a_worker_error_reaches_the_caller),
  };
  return cmocka_run_group_tests(tests, nullptr, nullptr);
}
