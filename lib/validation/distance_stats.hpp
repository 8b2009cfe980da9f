// Method (d) of the paper's section 7: statistics of the distances between the cloud's
// points and the base surface, over all points and per leaf patch, with the share of points
// within a tolerance ("98.7 % of N points within 0.1 mm").
#pragma once
#include <cstddef>
#include <cstdint>
#include <vector>

#include "result.hpp"

namespace dbs {

struct DistanceStats {
  std::size_t count = 0;
  double mean = 0.0, rms = 0.0, max = 0.0;
  double p50 = 0.0, p90 = 0.0, p95 = 0.0, p99 = 0.0;  // percentiles (percentile_of_sorted)
  double within = 0.0;  // share of the points with distance <= tolerance, in [0, 1]; 0 for none
};

struct DistanceReport {
  double tolerance = 0.0;
  DistanceStats overall;
  std::vector<DistanceStats> per_patch;  // indexed by patch id; count 0 for a patch without points
};

/// Statistics of `distances` (>= 0, finite) grouped by `patch` (one id in [0, patch_count)
/// per distance). Throws Error(InvalidArgument) when the sizes differ, Error(OutOfRange)
/// naming the first point with a patch id outside [0, patch_count) or a negative tolerance,
/// Error(NonFinite) naming the first non-finite distance or tolerance.
DistanceReport distance_statistics(const std::vector<double>& distances, const std::vector<std::int32_t>& patch, std::size_t patch_count, double tolerance);

/// The same of a result's points, those far outside the cloud's body and those cropped
/// (Result::left_out) left out, as in the result's own mean and max distance.
DistanceReport distance_statistics(const Result& result, double tolerance);

}  // namespace dbs
