// The last-resort repair of a parameterization (off by default, DBS_OPT_REPAIR). A point whose
// foot lies far from its leaf is one the base surfaces never reached (under an overhang, up a
// steep wall): its orthogonal foot sits on a surface that passes it at a distance, and points
// projected from afar crowd into a small part of the domain and fold. Such a point takes the
// inverse-distance mean of the (u,v) of its nearest points in 3D (a harmonic fill, the other
// points fixed), then moves towards its orthogonal foot on the result surface within a trust
// radius. Its distance, patch and level are then those of the surface at its new (u,v), and it
// is flagged.
//
// "Far" is more than kRepairFactor times the accuracy target used (which the noise floor keeps
// above the noise, so a noisy cloud's points are not taken for unreached ones) and more than
// kRepairSpacings cloud spacings. Measured on the hard shapes of dbs-bench-folds: it takes the
// mushroom from 7.2% to 0.12% folded reference triangles and the tall dome from 8.2% to 0.18%,
// but raises their mean distance by 17% and 43% (the repaired points are not on the surface),
// which is why it is not on by default.
#pragma once
#include <cstddef>
#include <vector>

#include "result.hpp"

namespace dbs {

constexpr double kRepairFactor = 10.0;         ///< far: beyond this x the target ...
constexpr double kRepairSpacings = 1.0;        ///< ... and beyond this many spacings h
constexpr std::size_t kRepairNeighbours = 12;  ///< neighbours of the harmonic fill
constexpr int kRepairSweeps = 200;             ///< Gauss-Seidel sweeps, in point order
constexpr double kRepairTrust = 0.25;          ///< step towards the foot: at most this x the mean (u,v) distance to the neighbours

/// Repairs the far points of `result` (parameters of `points`, which it was made from) in
/// place, setting result.repaired; returns how many were repaired. Deterministic for any
/// thread count.
std::size_t repair_far_points(Result& result, const std::vector<Vec3>& points, int threads);

}  // namespace dbs
