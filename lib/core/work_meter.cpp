#include "work_meter.hpp"

#include <algorithm>
#include <exception>
#include <system_error>
#include <thread>
#include <vector>

#include "error.hpp"
#include "parallel.hpp"

namespace dbs {

namespace {

/// Blocks per worker in run(): small enough to even out uneven items, large enough that
/// handing them out costs nothing.
constexpr std::size_t kBlocksPerWorker = 16;

/// The units a worker of run() gathered for `meter` and not yet added (WorkMeter::kWorkerBatch).
/// Set only while that worker drains its blocks, so the adds of any other thread (a nested
/// parallel_for's) go straight to the shared count, and none is left behind after run().
struct WorkerBatch {
  const WorkMeter* meter = nullptr;
  std::uint64_t pending = 0;
};
thread_local WorkerBatch worker_batch;

}  // namespace

WorkMeter::WorkMeter(std::uint64_t report_every) : report_every_(std::max<std::uint64_t>(report_every, 1)), caller_(std::this_thread::get_id()) {}

void WorkMeter::add(std::uint64_t units) {
  if (cancelled()) fail(ErrorCode::Cancelled, "cancelled while working");
  if (worker_batch.meter == this) {
    worker_batch.pending += units;
    if (worker_batch.pending < kWorkerBatch) return;
    units = worker_batch.pending;
    worker_batch.pending = 0;
  }
  add_now(units);
}

void WorkMeter::add_now(std::uint64_t units) {
  const std::uint64_t before = done_.fetch_add(units, std::memory_order_relaxed);
  if ((before + units) / report_every_ == before / report_every_) return;
  if (std::this_thread::get_id() == caller_) {
    if (running_) report_if_due();
    return;
  }
  // Taking the lock orders the notification after a waiter's check of the count.
  std::lock_guard<std::mutex> lock(mutex_);
  wake_.notify_one();
}

bool WorkMeter::take_due() {
  const std::uint64_t reported = reported_.load(std::memory_order_relaxed);
  if (done() / report_every_ <= reported) return false;
  reported_.store(reported + 1, std::memory_order_relaxed);
  return true;
}

void WorkMeter::report_if_due() {
  while (take_due())
    if (report_) report_();
}

void WorkMeter::run(std::size_t n, int threads, const std::function<void(std::size_t)>& body) {
  const std::size_t workers = std::min<std::size_t>(static_cast<std::size_t>(std::max(threads, 1)), n);
  // The caller's own add() reports while this loop runs (and only then).
  struct Running {
    bool& flag;
    bool before;
    ~Running() { flag = before; }
  } running{running_, running_};
  running_ = true;
  auto inline_range = [&](std::size_t begin, std::size_t end) {
    for (std::size_t i = begin; i < end; ++i) {
      body(i);
      report_if_due();
    }
  };
  if (workers <= 1) {
    try {
      inline_range(0, n);
    } catch (...) {
      cancel();
      throw;
    }
    return;
  }
  std::exception_ptr error;
  std::size_t finished = 0;
  std::vector<std::thread> pool;
  pool.reserve(workers);
  // Blocks handed out in order to whichever worker is free (a patch or a point may take much
  // longer than another); each index still runs once and writes only its own outputs, so the
  // result does not depend on which thread ran it.
  const std::size_t block = std::max<std::size_t>(1, n / (workers * kBlocksPerWorker));
  std::atomic<std::size_t> next{0};
  auto drain = [&] {
    struct Batching {
      WorkerBatch saved = worker_batch;
      explicit Batching(const WorkMeter* meter) { worker_batch = {meter, 0}; }
      ~Batching() { worker_batch = saved; }
    } batching(this);
    for (std::size_t begin; (begin = next.fetch_add(block)) < n;) {
      for (std::size_t i = begin; i < std::min(n, begin + block); ++i) body(i);
      const std::uint64_t pending = worker_batch.pending;
      worker_batch.pending = 0;
      if (pending > 0) add_now(pending);
    }
  };
  auto worker = [&] {
    std::exception_ptr failure;
    try {
      drain();
    } catch (...) {
      failure = std::current_exception();
      next.store(n);  // the others stop at their next block
    }
    std::lock_guard<std::mutex> lock(mutex_);
    if (failure && !error) error = failure;
    ++finished;
    wake_.notify_one();
  };
  auto join_all = [&] {
    for (std::thread& t : pool) t.join();
  };
  for (std::size_t w = 0; w < workers; ++w) {
    try {
      pool.emplace_back(worker);
    } catch (const std::system_error&) {
      break;  // no more threads: those that started take all blocks
    }
  }
  try {
    if (pool.empty()) inline_range(0, n);
    std::unique_lock<std::mutex> lock(mutex_);
    while (finished < pool.size()) {
      wake_.wait(lock, [&] { return finished == pool.size() || done() / report_every_ > reported_.load(std::memory_order_relaxed); });
      lock.unlock();
      report_if_due();
      lock.lock();
    }
    lock.unlock();
    // One report per multiple, all within this loop: the number of reports does not depend
    // on the thread count or on when the caller woke up.
    report_if_due();
  } catch (...) {
    cancel();
    join_all();
    throw;
  }
  join_all();
  if (error) std::rethrow_exception(error);
}

void metered_for(WorkMeter* meter, std::size_t n, int threads, const std::function<void(std::size_t)>& body) {
  if (meter && meter->on_caller_thread()) meter->run(n, threads, body);
  else parallel_for(n, threads, body);
}

}  // namespace dbs
