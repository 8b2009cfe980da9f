// A tensor-product cubic B-spline field d(u,v) in R^3 on [0,1]^2 that interpolates values
// given on a uniform nu x nv grid. Used as the displacement of a base surface from its
// Coons patch: the values on the grid's border are zero, so d vanishes on the boundary.
#pragma once
#include "grid.hpp"
#include "surface_point.hpp"

namespace dbs {

class SplineDisplacement {
 public:
  SplineDisplacement() = default;  // d == 0
  /// Interpolates `values` at (i/(nu-1), j/(nv-1)); natural end conditions. nu, nv >= 2.
  explicit SplineDisplacement(const Grid& values);

  bool is_zero() const { return nu_ == 0; }
  /// Data sites per direction (0 for d == 0).
  int sites_u() const { return nu_; }
  int sites_v() const { return nv_; }
  Vec3 eval(double u, double v) const;
  /// Adds eval() at the parameters of `grid` (a uniform grid) to its points, except on its
  /// border (where d vanishes), bit for bit as eval(); the basis of each row and column is
  /// computed once.
  void add_to_interior(Grid& grid) const;
  /// Value and first partial derivatives.
  void eval_derivs(double u, double v, Vec3& d, Vec3& du, Vec3& dv) const;
  /// Second partial derivatives.
  SecondDerivatives second_derivatives(double u, double v) const;

 private:
  int nu_ = 0, nv_ = 0;              // data sites per direction
  std::vector<Vec3> coeffs_;         // (nu_+2) x (nv_+2) control values, u fastest
};

}  // namespace dbs
