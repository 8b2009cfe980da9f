#include "departure_guard.hpp"

#include <string>

#include "error.hpp"

namespace dbs {

namespace {

/// Rounds of holding and solving again: each round holds the nodes the last solve sent off
/// the cloud; their neighbours, pulled along before, rarely depart once they are held.
constexpr int kMaxRounds = 4;

double distance_to_cloud(const CloudIndex& index, const Vec3& q) { return (index.points()[index.nearest(q)] - q).norm(); }

/// hold_departing_nodes with each node's distance to the cloud before the move given (the
/// nodes do not move between the rounds of solve_curve_near).
std::size_t hold_departing(const CloudIndex& index, CurveProjectionInput& input, const std::vector<double>& offsets, const std::vector<double>& start_distance, double tolerance) {
  std::vector<char> fixed(input.nodes.size(), 0);
  for (std::size_t f : input.fixed) fixed[f] = 1;
  std::size_t held = 0;
  for (std::size_t k = 1; k + 1 < input.nodes.size(); ++k) {
    if (fixed[k] || offsets[k] == 0.0) continue;
    if (distance_to_cloud(index, input.nodes[k] + offsets[k] * input.directions[k]) > start_distance[k] + tolerance) {
      input.fixed.push_back(k);
      ++held;
    }
  }
  return held;
}

std::vector<double> start_distances(const CloudIndex& index, const CurveProjectionInput& input) {
  std::vector<double> d(input.nodes.size(), 0.0);
  for (std::size_t k = 1; k + 1 < input.nodes.size(); ++k) d[k] = distance_to_cloud(index, input.nodes[k]);
  return d;
}

}  // namespace

bool departs(const DirectedProjector& projector, const Vec3& from, const Vec3& to) {
  const CloudIndex& index = projector.index();
  if (index.size() == 0) return false;
  return distance_to_cloud(index, to) > distance_to_cloud(index, from) + kDepartureTolerance * projector.length_scale();
}

std::size_t hold_departing_nodes(const DirectedProjector& projector, CurveProjectionInput& input, const std::vector<double>& offsets, double tolerance) {
  const std::size_t k = input.nodes.size();
  if (offsets.size() != k || input.directions.size() != k)
    fail(ErrorCode::InvalidArgument, "hold_departing_nodes: " + std::to_string(offsets.size()) + " offsets and " + std::to_string(input.directions.size()) + " directions for " +
                                         std::to_string(k) + " nodes");
  for (std::size_t f : input.fixed)
    if (f >= k) fail(ErrorCode::OutOfRange, "hold_departing_nodes: fixed node " + std::to_string(f) + " is not below the node count " + std::to_string(k));
  const CloudIndex& index = projector.index();
  if (index.size() == 0) return 0;
  return hold_departing(index, input, offsets, start_distances(index, input), tolerance);
}

std::vector<double> solve_curve_near(const DirectedProjector& projector, CurveProjectionInput& input, double gamma, const RefinementSettings& settings, RefinementCounts* counts,
                                     std::size_t* out_held) {
  std::vector<double> offsets = solve_curve(projector, input, gamma, settings, counts);
  const CloudIndex& index = projector.index();
  if (index.size() == 0) return offsets;
  const std::vector<double> before = start_distances(index, input);
  const double tolerance = kDepartureTolerance * projector.length_scale();
  for (int round = 0; round < kMaxRounds; ++round) {
    const std::size_t held = hold_departing(index, input, offsets, before, tolerance);
    if (held == 0) break;
    if (out_held) *out_held += held;
    offsets = solve_curve(projector, input, gamma, settings, counts);
  }
  return offsets;
}

}  // namespace dbs
