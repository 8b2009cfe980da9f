// The least-squares fit of a patch's grid to points at known (u,v): the repair refits the
// leaves it moved points onto (fold_repair.hpp), and the root may start from a fit to a
// meshless parameterization of its cloud (meshless_seed.hpp).
#pragma once
#include <cstddef>
#include <vector>

#include "patch.hpp"

namespace dbs {

constexpr double kRefitRegularization = 1e-2;   ///< Tikhonov weight of the refit, times the mean diagonal of its normal matrix
constexpr int kMaxRefitNodes = 441;             ///< leaves with more interior grid nodes (a grid above 23 x 23) are not refitted (the fit costs m^2 per point)

/// Refits `leaf`'s grid so that its surface at each data point's (u,v) comes close to the
/// point: least squares over `ids` (points whose (u,v) lie on the leaf), the interior nodes
/// drawn towards where they are by a Tikhonov term of kRefitRegularization times the mean
/// diagonal of the normal matrix, so that nodes with little data stay. The surface is its
/// boundary's Coons patch plus a spline displacement linear in the grid's interior values,
/// so the fit is one small dense solve; the boundary, hence every seam, is unchanged. False
/// (the leaf untouched) when the grid is too large, no data reaches it or the solve fails.
bool fit_grid_to_parameters(Patch& leaf, const std::vector<std::size_t>& ids, const std::vector<Vec3>& points, const std::vector<double>& u, const std::vector<double>& v);

}  // namespace dbs
