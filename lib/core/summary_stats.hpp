// Order statistics shared by the validation measures.
#pragma once
#include <vector>

namespace dbs {

/// Percentile p in [0, 100] of ascending `sorted` values, interpolated linearly between
/// neighbouring order statistics (position p/100 * (n-1)); 0 for no values.
double percentile_of_sorted(const std::vector<double>& sorted, double p);

/// Smallest, mean, 95th percentile and largest of a set of values; all 0 for none.
struct MeasureSummary {
  double min = 0.0;
  double mean = 0.0;
  double p95 = 0.0;
  double max = 0.0;
};

/// Summary of `values` (taken by value: they are sorted).
MeasureSummary summarize(std::vector<double> values);

}  // namespace dbs
