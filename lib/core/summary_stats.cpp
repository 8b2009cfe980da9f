#include "summary_stats.hpp"

#include <algorithm>
#include <cmath>

namespace dbs {

double percentile_of_sorted(const std::vector<double>& sorted, double p) {
  if (sorted.empty()) return 0.0;
  double position = std::clamp(p, 0.0, 100.0) / 100.0 * static_cast<double>(sorted.size() - 1);
  std::size_t below = static_cast<std::size_t>(std::floor(position));
  std::size_t above = std::min(below + 1, sorted.size() - 1);
  double weight = position - static_cast<double>(below);
  return sorted[below] + weight * (sorted[above] - sorted[below]);
}

MeasureSummary summarize(std::vector<double> values) {
  MeasureSummary s;
  if (values.empty()) return s;
  std::sort(values.begin(), values.end());
  double sum = 0.0;
  for (double x : values) sum += x;
  s.min = values.front();
  s.mean = sum / static_cast<double>(values.size());
  s.p95 = percentile_of_sorted(values, 95.0);
  s.max = values.back();
  return s;
}

}  // namespace dbs
