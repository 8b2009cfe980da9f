#include "cancel_latency.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <vector>

namespace bench {

namespace {

using Clock = std::chrono::steady_clock;

double seconds_between(Clock::time_point a, Clock::time_point b) { return std::chrono::duration<double>(b - a).count(); }

struct Watch {
  Clock::time_point last;
  double longest = 0.0;
  Clock::time_point cancel_after;  // cancels at the first call past this moment
  bool cancels = false;
  bool cancelled = false;
  Clock::time_point cancelled_at;
};

int on_progress(double, const char*, void* payload) {
  Watch& watch = *static_cast<Watch*>(payload);
  const Clock::time_point now = Clock::now();
  watch.longest = std::max(watch.longest, seconds_between(watch.last, now));
  watch.last = now;
  if (watch.cancels && !watch.cancelled && now >= watch.cancel_after) {
    watch.cancelled = true;
    watch.cancelled_at = Clock::now();
    return 1;
  }
  return 0;
}

}  // namespace

Responsiveness measure_responsiveness(const dbs_cloud* cloud, const dbs_boundary* boundary, dbs_options* options, int trials) {
  Responsiveness r;
  Watch watch;
  dbs_options_set_progress(options, on_progress, &watch);
  dbs_result* result = nullptr;
  const Clock::time_point start = Clock::now();
  watch.last = start;
  if (dbs_parameterize(cloud, boundary, options, &result) != DBS_OK) {
    std::fprintf(stderr, "dbs-bench: dbs_parameterize failed: %s\n", dbs_last_error_message());
    std::exit(EXIT_FAILURE);
  }
  const double duration = seconds_between(start, Clock::now());
  r.longest_silence = std::max(watch.longest, seconds_between(watch.last, Clock::now()));
  dbs_result_destroy(result);

  std::vector<double> latency;
  for (int t = 0; t < trials; ++t) {
    Watch cancel;
    cancel.cancels = true;
    const Clock::time_point begin = Clock::now();
    cancel.last = begin;
    cancel.cancel_after = begin + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(duration * (t + 0.5) / trials));
    dbs_options_set_progress(options, on_progress, &cancel);
    result = nullptr;
    const int status = dbs_parameterize(cloud, boundary, options, &result);
    const Clock::time_point end = Clock::now();
    if (status == DBS_OK) dbs_result_destroy(result);  // finished before the moment came
    if (cancel.cancelled) latency.push_back(seconds_between(cancel.cancelled_at, end));
  }
  dbs_options_set_progress(options, nullptr, nullptr);
  if (!latency.empty()) {
    std::sort(latency.begin(), latency.end());
    r.median_latency = latency[latency.size() / 2];
    r.max_latency = latency.back();
  }
  return r;
}

}  // namespace bench
