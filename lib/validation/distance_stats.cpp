#include "distance_stats.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "error.hpp"
#include "number_text.hpp"
#include "summary_stats.hpp"

namespace dbs {
namespace {

DistanceStats stats_of(std::vector<double> values, double tolerance) {
  DistanceStats s;
  s.count = values.size();
  if (values.empty()) return s;
  std::sort(values.begin(), values.end());
  double sum = 0.0, sum2 = 0.0;
  for (double d : values) {
    sum += d;
    sum2 += d * d;
  }
  double n = static_cast<double>(values.size());
  s.mean = sum / n;
  s.rms = std::sqrt(sum2 / n);
  s.max = values.back();
  s.p50 = percentile_of_sorted(values, 50.0);
  s.p90 = percentile_of_sorted(values, 90.0);
  s.p95 = percentile_of_sorted(values, 95.0);
  s.p99 = percentile_of_sorted(values, 99.0);
  std::size_t within = static_cast<std::size_t>(std::upper_bound(values.begin(), values.end(), tolerance) - values.begin());
  s.within = static_cast<double>(within) / n;
  return s;
}

}  // namespace

DistanceReport distance_statistics(const std::vector<double>& distances, const std::vector<std::int32_t>& patch, std::size_t patch_count, double tolerance) {
  if (distances.size() != patch.size()) fail(ErrorCode::InvalidArgument, "distance_statistics: " + std::to_string(distances.size()) + " distances but " + std::to_string(patch.size()) + " patch ids");
  if (!std::isfinite(tolerance)) fail(ErrorCode::NonFinite, "distance_statistics: the tolerance is not finite");
  if (tolerance < 0.0) fail(ErrorCode::OutOfRange, "distance_statistics: tolerance " + significant_text(tolerance, 6) + " is negative");
  std::vector<std::vector<double>> grouped(patch_count);
  for (std::size_t i = 0; i < distances.size(); ++i) {
    if (!std::isfinite(distances[i])) fail(ErrorCode::NonFinite, "distance_statistics: distance of point " + std::to_string(i) + " is not finite");
    if (patch[i] < 0 || static_cast<std::size_t>(patch[i]) >= patch_count) fail(ErrorCode::OutOfRange, "distance_statistics: point " + std::to_string(i) + " has patch id " + std::to_string(patch[i]) + " outside [0, " + std::to_string(patch_count) + ")");
    grouped[patch[i]].push_back(distances[i]);
  }
  DistanceReport report;
  report.tolerance = tolerance;
  report.overall = stats_of(distances, tolerance);
  report.per_patch.reserve(patch_count);
  for (std::vector<double>& values : grouped) report.per_patch.push_back(stats_of(std::move(values), tolerance));
  return report;
}

DistanceReport distance_statistics(const Result& result, double tolerance) {
  if (result.far_points == 0 && result.cropped_points == 0) return distance_statistics(result.distance, result.patch, result.patches.size(), tolerance);
  std::vector<double> distances;
  std::vector<std::int32_t> patch;
  for (std::size_t i = 0; i < result.distance.size(); ++i) {
    if (result.left_out(i)) continue;
    distances.push_back(result.distance[i]);
    patch.push_back(result.patch[i]);
  }
  return distance_statistics(distances, patch, result.patches.size(), tolerance);
}

}  // namespace dbs
