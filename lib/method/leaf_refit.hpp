// Points moved in (u,v) after the projection (the repair, the smoothing of turned sheets):
// placing a point at new parameters (its leaf, level and distance there), putting it back,
// and refitting the leaves that received moved points to all their points at their (u,v),
// so that the surface comes to the points instead of the points leaving the surface.
#pragma once
#include <cstdint>
#include <vector>

#include "result.hpp"

namespace dbs {

/// Where a point is in a result: its (u,v), distance, patch and level.
struct Placement {
  double u, v, distance;
  int patch;
  std::int8_t level;

  static Placement of(const Result& result, std::size_t i) { return {result.u[i], result.v[i], result.distance[i], result.patch[i], result.level[i]}; }
};

/// Point i given (u,v): its distance to the leaf there, that leaf and its level.
void place_on_leaf(Result& result, const std::vector<Vec3>& points, std::size_t i, const Vec2& uv);

/// Point i put back where it was (`before`); its distance measured again when the leaf
/// there has been refitted meanwhile (`refitted`, a flag per patch).
void put_back(Result& result, const std::vector<Vec3>& points, std::size_t i, const Placement& before, const std::vector<char>& refitted);

/// A flag per patch: 1 for the leaves in `ids`.
std::vector<char> patch_flags(const Result& result, const std::vector<int>& ids);

/// Refits every leaf holding a point flagged in `marked` (fit_grid_to_parameters) to the
/// (u,v) of its points not flagged in `outlier`, and recomputes the distance of every point of
/// those leaves at its (u,v). A refit that raises the median distance of the leaf's points is
/// undone. Returns the ids of the leaves refitted, in increasing order. Deterministic for any
/// thread count (each leaf writes only its own patch, each point only its own distance).
std::vector<int> refit_marked_leaves(Result& result, const std::vector<Vec3>& points, const std::vector<char>& outlier, const std::vector<char>& marked, int threads);

}  // namespace dbs
