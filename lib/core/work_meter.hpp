// The work of one run, counted in units (a point projected, a grid node solved), so that
// progress is reported after a bounded amount of work in every stage and a cancel stops
// the workers soon after it is asked, whatever the thread count.
//
// Workers call add() as they go; the calling thread (the one that made the meter, the only
// one allowed to call the host's progress callback) runs a parallel loop through run(),
// which wakes it after every `report_every` units to call the meter's report function;
// where the caller does the work itself (one thread), its own add() calls it. When `report` throws (the host
// cancelled), the meter is cancelled: each worker's next add() throws Error(Cancelled), the
// loop is joined and the caller's exception goes on. run() hands out blocks of indices to
// whichever worker is free; as with parallel_for, each index runs once and must write only its
// own outputs, so a loop gives the same results either way.
#pragma once
#include <atomic>
#include <condition_variable>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <mutex>
#include <thread>

namespace dbs {

class WorkMeter {
 public:
  /// Work between two reports; at most a few milliseconds of one thread per unit.
  static constexpr std::uint64_t kDefaultReportEvery = 2048;
  /// A worker of run() counts its units locally and adds them to the shared count once this
  /// many have gathered (and at the end of each block): one shared add a point made two
  /// threads contend for its cache line (9% of a 1M-point run's time). A report then comes
  /// at most this many units per worker late; the caller's own loop counts every unit.
  static constexpr std::uint64_t kWorkerBatch = 64;

  explicit WorkMeter(std::uint64_t report_every = kDefaultReportEvery);
  WorkMeter(const WorkMeter&) = delete;
  WorkMeter& operator=(const WorkMeter&) = delete;

  /// What a due report does (called on the caller's thread only, inside run()); may throw.
  void set_report(std::function<void()> report) { report_ = std::move(report); }

  /// Counts `units` of work (any thread); on the caller's thread inside run(), makes a due
  /// report. Throws Error(Cancelled) once cancel() was called (or what the report throws).
  void add(std::uint64_t units = 1);
  /// Units counted so far.
  std::uint64_t done() const { return done_.load(std::memory_order_relaxed); }
  /// Makes every later add() throw Error(Cancelled).
  void cancel() { cancelled_.store(true, std::memory_order_relaxed); }
  bool cancelled() const { return cancelled_.load(std::memory_order_relaxed); }
  bool on_caller_thread() const { return std::this_thread::get_id() == caller_; }

  /// body(i) for i in [0, n) on up to `threads` threads (blocks to whichever is free), reporting
  /// on the caller's thread after every report_every units the bodies add. With one thread
  /// (or one item) the bodies run on the caller's thread, and a body may run a loop of its
  /// own through the meter. Called on the caller's thread only (see metered_for).
  void run(std::size_t n, int threads, const std::function<void(std::size_t)>& body);

 private:
  /// add() without a batch: the shared count.
  void add_now(std::uint64_t units);
  /// True once for each multiple of report_every the count crossed.
  bool take_due();
  /// One report for each multiple crossed since the last one.
  void report_if_due();

  const std::uint64_t report_every_;
  const std::thread::id caller_;
  std::function<void()> report_;
  bool running_ = false;  // inside run(); read and written by the caller's thread only
  std::atomic<std::uint64_t> done_{0};
  std::atomic<std::uint64_t> reported_{0};  // multiples of report_every_ already reported
  std::atomic<bool> cancelled_{false};
  std::mutex mutex_;
  std::condition_variable wake_;
};

/// Loops that may run with or without a meter: through it on the caller's thread, a plain
/// parallel_for on a worker thread or without a meter (the bodies count their work).
void metered_for(WorkMeter* meter, std::size_t n, int threads, const std::function<void(std::size_t)>& body);
inline void count_work(WorkMeter* meter, std::uint64_t units = 1) {
  if (meter) meter->add(units);
}

}  // namespace dbs
