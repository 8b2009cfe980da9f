// How soon libdbs answers its progress callback: the longest silence between two calls of a
// run, and the latency of a cancel asked at random moments (from the callback's non-zero
// return to dbs_parameterize's return), for the bench table.
#pragma once
#include <cstddef>

#include "dbs.h"

namespace bench {

struct Responsiveness {
  double longest_silence = 0.0;  // seconds between two progress calls (or start/end and a call)
  double median_latency = 0.0;   // seconds from the cancel to the return, over the trials
  double max_latency = 0.0;
};

/// Runs dbs_parameterize once to find its duration and longest silence, then `trials` times
/// cancelling at a moment drawn evenly from that duration (a fixed sequence); `options` is
/// restored (its progress callback cleared) afterwards.
Responsiveness measure_responsiveness(const dbs_cloud* cloud, const dbs_boundary* boundary, dbs_options* options, int trials);

}  // namespace bench
