// Bilinearly blended Coons patch of a four-sided boundary, sides by arc length.
#pragma once
#include "boundary.hpp"
#include "grid.hpp"
#include "surface_point.hpp"

namespace dbs {

class CoonsPatch {
 public:
  explicit CoonsPatch(Boundary boundary);
  const Boundary& boundary() const { return boundary_; }
  /// C(u,v); equals the boundary exactly on the four sides (corners coincide exactly).
  Vec3 eval(double u, double v) const;
  /// C and its partial derivatives (one-sided at polyline vertices).
  SurfacePoint eval_derivs(double u, double v) const;
  /// The second derivatives (one-sided as eval_derivs' first ones): inside the sides'
  /// segments C is bilinear in the sides' points, so Cuu = Cvv = 0 and Cuv is constant per cell.
  SecondDerivatives second_derivatives(double u, double v) const;
  /// eval() on a uniform nu x nv grid (the Grid's parameters), bit for bit, each side
  /// evaluated once per row or column instead of once per point.
  Grid sample(int nu, int nv) const;

 private:
  Boundary boundary_;
  Vec3 c00_, c10_, c01_, c11_;
};

}  // namespace dbs
