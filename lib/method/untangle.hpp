// Untangling the (u,v) of repaired regions. Where the repair fills a steep wall or the
// underside of an overhang, the wall is squeezed into a narrow band of the domain and the
// (u,v) of single points jitter across it: the map is right at the scale of a neighbourhood
// (the fold measure passes it) but thin triangles between neighbours turn over (on the
// 10,000-point tall dome of dbs-bench-folds 95% of the folded reference triangles had a
// repaired corner). A point is moved to the (u,v) its neighbours predict (the affine map from
// their tangent coordinates to their (u,v), fitted by least squares and evaluated at the
// point) when that turns over fewer triangles of its umbrella: its kUntangleUmbrella nearest
// points ordered by angle in its tangent plane, each consecutive pair with it a triangle
// (pairs more than half a turn apart skipped), whose orientation must agree with the sign of
// the fitted map. Only flat neighbourhoods are judged (smallest PCA eigenvalue at most
// kUntangleFlatness of the middle one): across a crease, round a thin finger or in noise
// the tangent plane does not order the neighbours (there the step added folds).
#pragma once
#include <cstddef>
#include <vector>

#include "cloud_index.hpp"
#include "result.hpp"

namespace dbs {

constexpr std::size_t kUntangleNeighbours = 12;  ///< points of the affine fit
constexpr std::size_t kUntangleUmbrella = 8;     ///< nearest points of the umbrella
constexpr double kUntangleFlatness = 0.03;       ///< flat: lambda_min <= this x lambda_mid
constexpr int kUntangleMaxPasses = 16;  ///< passes until none moves a point, at most this many

/// Moves the points flagged in `candidate` (one flag per point of `points`, which `index`
/// indexes) as described above, in passes until one moves no point (at most
/// kUntangleMaxPasses; the tall dome at 10,201 and 12,321 points: 145 and 207 folded
/// reference triangles after one pass, 103 and 168 after four, 90 and 135 when none moves),
/// each judging every candidate next to a point the last pass moved (all in the first)
/// against the (u,v) the pass started from (so the result does not depend on the order or
/// the thread count). Writes result.u and result.v of the moved points only (clamped to
/// [0,1]^2) and returns them in increasing order.
std::vector<std::size_t> untangle(Result& result, const std::vector<Vec3>& points, const CloudIndex& index, const std::vector<char>& candidate, int threads);

}  // namespace dbs
