// A dynamic base surface: the Coons patch of its boundary plus a cubic B-spline
// displacement that is zero on the boundary and makes the surface interpolate the
// interior points of a grid (DESIGN.md decision 1). It interpolates its boundary exactly.
#pragma once

#include <algorithm>
#include "boundary.hpp"
#include "coons_patch.hpp"
#include "grid.hpp"
#include "spline_displacement.hpp"

namespace dbs {

class BaseSurface {
 public:
  /// The Coons patch of `boundary` (no displacement).
  explicit BaseSurface(Boundary boundary);
  /// Interpolates the interior points of `grid` (nu, nv >= 2; border points are ignored:
  /// the boundary rules there).
  BaseSurface(Boundary boundary, const Grid& grid);

  const Boundary& boundary() const { return coons_.boundary(); }
  /// S(u,v), (u,v) clamped to [0,1]^2; exactly the boundary polylines on the sides.
  Vec3 eval(double u, double v) const;
  SurfacePoint eval_derivs(double u, double v) const;
  /// The second partial derivatives, (u,v) clamped (one-sided across the creases the
  /// boundary's vertices draw through the Coons patch).
  SecondDerivatives second_derivatives(double u, double v) const;
  /// Unit normal Su x Sv (falls back to a neighbouring sample where it vanishes).
  Vec3 normal(double u, double v) const;
  /// The most data sites of the displacement along either direction (0 for the plain Coons
  /// patch): the finest detail of the interior is about 1 / (that - 1) of the domain.
  int displacement_sites() const { return std::max(displacement_.sites_u(), displacement_.sites_v()); }
  /// S sampled on a uniform nu x nv grid.
  Grid sample(int nu, int nv) const;

 private:
  CoonsPatch coons_;
  SplineDisplacement displacement_;
};

}  // namespace dbs
