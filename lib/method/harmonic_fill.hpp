// The fill of the last-resort repair (fold_repair.hpp): the points to repair take (u,v) from
// their nearest points in 3D, the other points fixed.
//
// A harmonic fill (each point the inverse-distance mean of its neighbours' (u,v)) embeds a
// region without folding it, but it crushes a region that is long compared with its rim: up
// a finger, a tube whose height is several times its width, the (u,v) of a harmonic map
// shrink exponentially with the height, and the tip's points end up at one (u,v) (below 1e-3
// of the median area: collapsed). The stretch balance reweights such a region's fill so that
// no neighbour pulls harder than its share: each weight divided by the neighbour's stretch
// (its 3D distances over its (u,v) distances; after Yoshizawa, Belyaev and Seidel, "A fast
// and simple stretch-minimizing mesh parameterization", 2004), a few rounds. It is applied to
// a connected region of the fill only where points were crushed, and kept only where the
// fold measure then finds fewer collapsed points and no more folded ones: on a region that
// is not crushed, unequal weights of a k-nearest graph can also invert a few neighbourhoods.
// Measured on dbs-bench-folds (4,000 points): the fingers go from 2.76% to 0.3% folded
// reference triangles, their mean distance from 0.0060 to 0.004.
#pragma once
#include <cstddef>
#include <vector>

#include "cloud_index.hpp"
#include "result.hpp"

namespace dbs {

constexpr std::size_t kStretchNeighbours = 12;  ///< a point's stretch is measured over this many nearest points
constexpr int kFillSweeps = 200;             ///< Gauss-Seidel sweeps of a fill, in point order
constexpr int kStretchRounds = 3;            ///< reweightings of a crushed region
constexpr double kCrushedStretch = 10.0;     ///< crushed: stretch above this x the median of the fill's fixed points
constexpr double kCrushedShare = 0.3;        ///< a region is balanced when at least this share of its points are crushed

/// The rows of a fill: points `ids` (indices into the result's points), each with its
/// neighbours and normalized weights (the neighbours' (u,v) are read, fixed or filled).
struct FillRows {
  std::vector<std::size_t> ids;
  std::vector<std::vector<std::size_t>> neighbours;
  std::vector<std::vector<double>> weights;
};

/// `sweeps` Gauss-Seidel sweeps of the fill over result.u/result.v, rows in order (so the
/// result does not depend on the number of threads).
void fill_sweeps(Result& result, const FillRows& rows, int sweeps);

/// After the harmonic fill of `rows`: the stretch balance of its crushed regions (above),
/// each kept only where the fold measure judges it better. `points` are the cloud the result
/// parameterizes, `index` over them. Returns the number of points whose (u,v) it changed.
std::size_t balance_stretch(Result& result, const std::vector<Vec3>& points, const CloudIndex& index, const FillRows& rows, int threads);

}  // namespace dbs
