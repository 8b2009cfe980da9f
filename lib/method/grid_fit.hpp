// The least-squares fit of a patch's grid to points at known (u,v): the repair refits the
// leaves it moved points onto (fold_repair.hpp), the root may start from a fit to a
// meshless parameterization of its cloud (meshless_seed.hpp), and a patch whose largest grid
// misses the target is fitted to its sample at their feet (evolve.hpp).
#pragma once
#include <cstddef>
#include <map>
#include <utility>
#include <vector>

#include "patch.hpp"
#include "spline_displacement.hpp"

namespace dbs {

constexpr double kRefitRegularization = 1e-2;   ///< Tikhonov weight of the refit, times the mean diagonal of its normal matrix
constexpr int kMaxRefitNodes = 441;             ///< leaves with more interior grid nodes (a grid above 23 x 23) are not refitted (the fit costs m^2 per point)

/// The cardinal functions of the spline of nu x nv grids: the spline is a tensor product of
/// linear 1D interpolations, so the displacement of a unit value at node (i,j) is
/// phi_i(s) psi_j(t), both 1 at their own site and 0 at the others; phi_i is read along the
/// grid line t = v(1) of a unit at (i,1), psi_j along s = u(1) of a unit at (1,j). They are
/// the same for every leaf of one size, and interpolating them took half of a refit (the
/// repair refits hundreds of leaves of a few sizes): a caller refitting many leaves adds
/// their sizes first and then shares the basis read-only between threads.
class GridFitBasis {
 public:
  struct Cardinals {
    std::vector<SplineDisplacement> phi, psi;
  };
  /// Makes the cardinal functions of nu x nv grids unless made already or the fit refuses
  /// such grids (nu or nv below 3, more than kMaxRefitNodes interior nodes).
  void add(int nu, int nv);
  /// Those of nu x nv grids, null when not added.
  const Cardinals* find(int nu, int nv) const;

 private:
  std::map<std::pair<int, int>, Cardinals> made_;
};

/// Refits `leaf`'s grid so that its surface at each data point's (u,v) comes close to the
/// point: least squares over `ids` (points whose (u,v) lie on the leaf), the interior nodes
/// drawn towards where they are by a Tikhonov term of kRefitRegularization times the mean
/// diagonal of the normal matrix, so that nodes with little data stay. The surface is its
/// boundary's Coons patch plus a spline displacement linear in the grid's interior values,
/// so the fit is one small dense solve; the boundary, hence every seam, is unchanged. False
/// (the leaf untouched) when the grid is too large, no data reaches it or the solve fails.
/// `basis` (may be null) holds the cardinal functions of the leaf's grid size, or they are
/// made for this fit alone.
bool fit_grid_to_parameters(Patch& leaf, const std::vector<std::size_t>& ids, const std::vector<Vec3>& points, const std::vector<double>& u, const std::vector<double>& v,
                            const GridFitBasis* basis = nullptr);

/// The grid of the fit above without a patch: `grid` (of `surface`, whose boundary it keeps)
/// fitted to points[ids[k]] at the local parameters st[k] of the surface (clamped to
/// [0,1]^2), into `out`. False (`out` untouched) when the fit refuses, as above, or the sizes
/// of ids and st differ.
bool fit_grid_to_feet(const BaseSurface& surface, const Grid& grid, const std::vector<std::size_t>& ids, const std::vector<Vec2>& st, const std::vector<Vec3>& points,
                      const GridFitBasis* basis, Grid& out);

}  // namespace dbs
