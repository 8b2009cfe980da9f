// parallel_for when the system refuses threads: this program interposes pthread_create (the
// executable's definition wins over libc's for libstdc++'s std::thread) and makes it fail
// after a given number of successes. Every index must still be processed exactly once, on
// the calling thread where no worker could start, and a worker's exception still reaches
// the caller. (Not built with the sanitizers, which interpose pthread_create themselves.)
#include <dlfcn.h>
#include <pthread.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <stdexcept>
#include <thread>
#include <vector>

#include "parallel.hpp"

#include "core_test_support.hpp"

namespace {

std::atomic<int> allowed_starts{-1};  // -1: no limit

using CreateFn = int (*)(pthread_t*, const pthread_attr_t*, void* (*)(void*), void*);

}  // namespace

// Default visibility: the build hides symbols, and a hidden one would not interpose.
extern "C" __attribute__((visibility("default"))) int pthread_create(pthread_t* thread, const pthread_attr_t* attr, void* (*start)(void*), void* arg) {
  static const CreateFn real = reinterpret_cast<CreateFn>(dlsym(RTLD_NEXT, "pthread_create"));
  if (allowed_starts.load() == 0) return EAGAIN;
  if (allowed_starts.load() > 0) --allowed_starts;
  return real(thread, attr, start, arg);
}

namespace {

/// Runs parallel_for over n indices with `threads` workers while only `starts` threads may
/// start; returns how often each index was visited and on how many distinct threads.
std::vector<int> visits(std::size_t n, int threads, int starts, std::size_t* out_threads) {
  std::vector<std::atomic<int>> count(n);
  std::vector<std::thread::id> where(n);
  allowed_starts = starts;
  dbs::parallel_for(n, threads, [&](std::size_t i) {
    ++count[i];
    where[i] = std::this_thread::get_id();
  });
  allowed_starts = -1;
  std::vector<std::thread::id> distinct;
  for (const auto& id : where)
    if (std::find(distinct.begin(), distinct.end(), id) == distinct.end()) distinct.push_back(id);
  *out_threads = distinct.size();
  std::vector<int> out;
  for (auto& c : count) out.push_back(c.load());
  return out;
}

void no_thread_can_start(void**) {
  std::size_t threads = 0;
  for (int c : visits(1000, 4, 0, &threads)) assert_int_equal(c, 1);
  assert_int_equal(threads, 1);  // all on the caller
}

void some_threads_start(void**) {
  for (int starts : {1, 2, 3}) {
    std::size_t threads = 0;
    for (int c : visits(1000, 4, starts, &threads)) assert_int_equal(c, 1);
    assert_int_equal(threads, static_cast<std::size_t>(starts) + 1);  // the started workers and the caller
  }
}

void all_threads_start(void**) {
  std::size_t threads = 0;
  for (int c : visits(1000, 4, -1, &threads)) assert_int_equal(c, 1);
  assert_int_equal(threads, 4);
}

void exceptions_still_reach_the_caller(void**) {
  allowed_starts = 1;
  bool caught = false;
  try {
    dbs::parallel_for(100, 4, [](std::size_t i) {
      if (i == 99) throw std::runtime_error("index 99");  // in the last chunk, run by the caller
    });
  } catch (const std::runtime_error&) {
    caught = true;
  }
  allowed_starts = -1;
  assert_true(caught);
}

}  // namespace

int main() {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(no_thread_can_start),
      cmocka_unit_test(some_threads_start),
      cmocka_unit_test(all_threads_start),
      cmocka_unit_test(exceptions_still_reach_the_caller),
  };
  return cmocka_run_group_tests(tests, nullptr, nullptr);
}
