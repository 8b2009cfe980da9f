#include "departure_guard.hpp"

namespace dbs {

namespace {

/// Rounds of holding and solving again: each round holds the nodes the last solve sent off
/// the cloud; their neighbours, pulled along before, rarely depart once they are held.
constexpr int kMaxRounds = 4;

double distance_to_cloud(const CloudIndex& index, const Vec3& q) { return (index.points()[index.nearest(q)] - q).norm(); }

}  // namespace

std::size_t hold_departing_nodes(const DirectedProjector& projector, CurveProjectionInput& input, const std::vector<double>& offsets, double tolerance) {
  const CloudIndex& index = projector.index();
  if (index.size() == 0) return 0;
  std::vector<char> fixed(input.nodes.size(), 0);
  for (std::size_t f : input.fixed) fixed[f] = 1;
  std::size_t held = 0;
  for (std::size_t k = 1; k + 1 < input.nodes.size(); ++k) {
    if (fixed[k] || offsets[k] == 0.0) continue;
    const Vec3 moved = input.nodes[k] + offsets[k] * input.directions[k];
    if (distance_to_cloud(index, moved) > distance_to_cloud(index, input.nodes[k]) + tolerance) {
      input.fixed.push_back(k);
      ++held;
    }
  }
  return held;
}

std::vector<double> solve_curve_near(const DirectedProjector& projector, CurveProjectionInput& input, double gamma, const RefinementSettings& settings, RefinementCounts* counts,
                                     std::size_t* out_held) {
  std::vector<double> offsets = solve_curve(projector, input, gamma, settings, counts);
  const double tolerance = kDepartureTolerance * projector.length_scale();
  for (int round = 0; round < kMaxRounds; ++round) {
    const std::size_t held = hold_departing_nodes(projector, input, offsets, tolerance);
    if (held == 0) break;
    if (out_held) *out_held += held;
    offsets = solve_curve(projector, input, gamma, settings, counts);
  }
  return offsets;
}

}  // namespace dbs
