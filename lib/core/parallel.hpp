// A minimal deterministic parallel loop: [0, n) cut into contiguous chunks, one per thread.
// Each index is processed exactly once and writes only its own outputs, so results never
// depend on the thread count. The first exception thrown by a worker is rethrown. When the
// system cannot start a thread (std::system_error, e.g. a process at its thread limit), the
// chunks that did not get one run on the calling thread: the result is the same, only slower.
#pragma once
#include <algorithm>
#include <cstddef>
#include <exception>
#include <mutex>
#include <system_error>
#include <thread>
#include <vector>

namespace dbs {

/// Thread count for an option value (0 = hardware concurrency, at least 1).
inline int resolve_threads(int requested) {
  if (requested > 0) return requested;
  unsigned hw = std::thread::hardware_concurrency();
  return hw == 0 ? 1 : static_cast<int>(hw);
}

template <class F>
void parallel_for(std::size_t n, int threads, F&& body) {
  std::size_t workers = std::min<std::size_t>(static_cast<std::size_t>(std::max(threads, 1)), n);
  if (workers <= 1) {
    for (std::size_t i = 0; i < n; ++i) body(i);
    return;
  }
  std::exception_ptr error;
  std::mutex error_mutex;
  std::vector<std::thread> pool;
  pool.reserve(workers);
  auto chunk = [&](std::size_t begin, std::size_t end) {
    try {
      for (std::size_t i = begin; i < end; ++i) body(i);
    } catch (...) {
      std::lock_guard<std::mutex> lock(error_mutex);
      if (!error) error = std::current_exception();
    }
  };
  std::size_t started = 0;
  for (; started < workers; ++started) {
    const std::size_t begin = n * started / workers, end = n * (started + 1) / workers;
    try {
      pool.emplace_back(chunk, begin, end);
    } catch (const std::system_error&) {
      break;  // no more threads: the rest runs here
    }
  }
  for (std::size_t w = started; w < workers; ++w) chunk(n * w / workers, n * (w + 1) / workers);
  for (std::thread& t : pool) t.join();
  if (error) std::rethrow_exception(error);
}

}  // namespace dbs
