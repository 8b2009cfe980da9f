#include "input_checks.hpp"

#include <algorithm>
#include <cmath>

#include "number_text.hpp"

namespace dbs {

namespace {

std::string number(double x) { return significant_text(x, 3); }

/// The distance from cloud point j to its kSpacingNeighbour-th nearest point.
double local_spacing(const CloudIndex& index, std::size_t j, std::vector<std::size_t>& ids, std::vector<double>& d2) {
  index.knn(index.points()[j], input::kSpacingNeighbour + 1, ids, d2);  // the point itself comes first
  return d2.empty() ? 0.0 : std::sqrt(d2.back());
}

}  // namespace

void check_boundary_against_cloud(const CloudIndex& index, const Boundary& boundary, double h, InputChecks& checks) {
  Box3 cloud_box;
  for (std::size_t k = 0; k < index.size(); ++k) cloud_box.extend(index.points()[index.point_index(k)]);
  const double size = boundary.size();
  checks.scale_ratio = size > 0.0 ? cloud_box.diagonal() / size : 1.0;
  if (index.size() == 0 || !(h > 0.0)) return;
  // Each side sample's distance to its nearest point j, against the local spacing at j
  // relative to the median of those at all samples' nearest points (all of them points at
  // the cloud's edge, whose neighbourhoods are half-empty: measured against interior
  // points, every gap would shrink by about 1.4), in units of h.
  std::vector<std::size_t> ids, nearest;
  std::vector<double> d2, distance, local;
  for (int s = 0; s < 4; ++s) {
    const Polyline& side = boundary.side(static_cast<Side>(s));
    for (int k = 0; k < input::kSidesSamples; ++k) {
      const Vec3 p = side.at(static_cast<double>(k) / input::kSidesSamples);
      const std::size_t j = index.nearest(p);
      distance.push_back((index.points()[j] - p).norm());
      local.push_back(local_spacing(index, j, ids, d2));
    }
  }
  std::vector<double> sorted = local;
  const auto middle = sorted.begin() + static_cast<std::ptrdiff_t>(sorted.size() / 2);
  std::nth_element(sorted.begin(), middle, sorted.end());
  const double median = *middle;
  std::vector<double> gaps;
  for (std::size_t k = 0; k < distance.size(); ++k) {
    // Where the points coincide (no spacing), the typical one.
    const double ratio = local[k] > 0.0 && median > 0.0 ? std::clamp(local[k] / median, 1.0 / input::kMaxSpacingRatio, input::kMaxSpacingRatio) : 1.0;
    gaps.push_back(distance[k] / (h * ratio));
  }
  const auto at = gaps.begin() + static_cast<std::ptrdiff_t>(input::kGapQuantile * static_cast<double>(gaps.size() - 1));
  std::nth_element(gaps.begin(), at, gaps.end());
  checks.boundary_gap = *at;
}

void check_parameters(Result& result, InputChecks& checks) {
  const std::size_t n = result.u.size();
  result.clamped.assign(n, 0);
  if (n == 0) return;
  const std::size_t g = std::clamp<std::size_t>(static_cast<std::size_t>(std::sqrt(static_cast<double>(n) / input::kPointsPerCell)), 2, 256);
  std::vector<char> occupied(g * g, 0);
  checks.clamped = 0;
  for (std::size_t i = 0; i < n; ++i) {
    if (i < result.outside_body.size() && result.outside_body[i]) continue;  // not placed yet, and not the body
    const double u = result.u[i], v = result.v[i];
    const std::size_t cu = std::min(g - 1, static_cast<std::size_t>(u * static_cast<double>(g)));
    const std::size_t cv = std::min(g - 1, static_cast<std::size_t>(v * static_cast<double>(g)));
    occupied[cv * g + cu] = 1;
    const bool on_edge = u == 0.0 || u == 1.0 || v == 0.0 || v == 1.0;
    if (on_edge && result.distance[i] > result.length_scale) {
      result.clamped[i] = 1;
      ++checks.clamped;
    }
  }
  checks.coverage = static_cast<double>(std::count(occupied.begin(), occupied.end(), 1)) / static_cast<double>(g * g);
}

std::vector<std::string> boundary_warnings(const InputChecks& checks) {
  std::vector<std::string> out;
  if (checks.scale_ratio > input::kMaxScaleRatio || checks.scale_ratio < 1.0 / input::kMaxScaleRatio)
    out.push_back("the cloud is " + number(checks.scale_ratio) + " times the size of the boundary (bounding-box diagonals): are they in the same units?");
  if (checks.boundary_gap > input::kMaxGap)
    out.push_back("the boundary lies " + number(checks.boundary_gap) + " point spacings from the cloud (" + number(100.0 * input::kGapQuantile) +
                  "% of it within that): does it belong to this cloud?");
  else if (checks.boundary_gap > input::kMaxSideGap)
    out.push_back("the boundary runs up to " + number(checks.boundary_gap) + " point spacings from the cloud (" + number(100.0 * input::kGapQuantile) +
                  "% of it within that): do its sides follow the edges of the scan, not straight lines between the corners of a curved part?");
  return out;
}

std::vector<std::string> parameter_warnings(const InputChecks& checks, std::size_t points, bool cropped) {
  std::vector<std::string> out;
  if (checks.coverage < input::kMinCoverage)
    out.push_back("the points cover " + number(100.0 * checks.coverage) + "% of the domain [0,1]^2: the cloud covers only part of the boundary");
  if (!cropped && checks.clamped >= input::kMinClamped && static_cast<double>(checks.clamped) > input::kMaxClampedShare * static_cast<double>(points))
    out.push_back(std::to_string(checks.clamped) + " of " + std::to_string(points) +
                  " points lie outside the boundary by more than a point spacing and were clamped onto the domain's edge: is the scan larger than its boundary?");
  return out;
}

}  // namespace dbs
