#include "base_surface.hpp"

#include <Eigen/Geometry>
#include <cmath>
#include <string>

#include "error.hpp"

namespace dbs {

namespace {

double clamp_unit(double x) { return x > 0.0 ? (x < 1.0 ? x : 1.0) : 0.0; }

/// Refuses non-finite parameters and clamps finite ones to [0,1].
void check_and_clamp(double& u, double& v) {
  if (!std::isfinite(u) || !std::isfinite(v))
    fail(ErrorCode::NonFinite, "surface evaluated at a non-finite parameter (u=" + std::to_string(u) + ", v=" + std::to_string(v) + ")");
  u = clamp_unit(u);
  v = clamp_unit(v);
}

bool on_border(double u, double v) { return u == 0.0 || u == 1.0 || v == 0.0 || v == 1.0; }

// Grid interior minus the Coons patch at the grid's parameters; zero on the grid border.
Grid displacement_values(const CoonsPatch& coons, const Grid& grid) {
  if (grid.nu < 2 || grid.nv < 2)
    fail(ErrorCode::InvalidArgument, "base surface grid must be at least 2 x 2, got " + std::to_string(grid.nu) + " x " + std::to_string(grid.nv));
  if (grid.points.size() != static_cast<std::size_t>(grid.nu) * grid.nv)
    fail(ErrorCode::InvalidArgument, "base surface grid holds " + std::to_string(grid.points.size()) + " points, not " +
                                         std::to_string(grid.nu) + " x " + std::to_string(grid.nv));
  Grid d(grid.nu, grid.nv);
  for (int j = 1; j + 1 < grid.nv; ++j)
    for (int i = 1; i + 1 < grid.nu; ++i) {
      if (!is_finite(grid(i, j)))
        fail(ErrorCode::NonFinite, "base surface grid point (" + std::to_string(i) + "," + std::to_string(j) + ") is not finite");
      d(i, j) = grid(i, j) - coons.eval(grid.u(i), grid.v(j));
    }
  return d;
}

}  // namespace

BaseSurface::BaseSurface(Boundary boundary) : coons_(std::move(boundary)) {}

BaseSurface::BaseSurface(Boundary boundary, const Grid& grid) : coons_(std::move(boundary)) {
  const Grid d = displacement_values(coons_, grid);
  // A grid without interior points leaves the Coons patch as it is.
  if (grid.nu > 2 && grid.nv > 2) displacement_ = SplineDisplacement(d);
}

Vec3 BaseSurface::eval(double u, double v) const {
  check_and_clamp(u, v);
  // On the border the displacement vanishes: the point is the boundary polyline's, as is.
  if (on_border(u, v) || displacement_.is_zero()) return coons_.eval(u, v);
  return coons_.eval(u, v) + displacement_.eval(u, v);
}

SurfacePoint BaseSurface::eval_derivs(double u, double v) const {
  check_and_clamp(u, v);
  SurfacePoint sp = coons_.eval_derivs(u, v);
  if (displacement_.is_zero()) return sp;
  Vec3 d, du, dv;
  displacement_.eval_derivs(u, v, d, du, dv);
  if (!on_border(u, v)) sp.p += d;
  sp.du += du;
  sp.dv += dv;
  return sp;
}

SecondDerivatives BaseSurface::second_derivatives(double u, double v) const {
  check_and_clamp(u, v);
  const SecondDerivatives c = coons_.second_derivatives(u, v);
  if (displacement_.is_zero()) return c;
  const SecondDerivatives d = displacement_.second_derivatives(u, v);
  return {c.uu + d.uu, c.uv + d.uv, c.vv + d.vv};
}

Vec3 BaseSurface::normal(double u, double v) const {
  check_and_clamp(u, v);
  // Where Su x Sv vanishes (a collapsed corner, tangent sides) the normal is the limit
  // from inside the patch: sample ever further towards the centre until it is defined.
  const double du_sign = u < 0.5 ? 1.0 : -1.0, dv_sign = v < 0.5 ? 1.0 : -1.0;
  for (double step : {0.0, 1e-7, 1e-5, 1e-3, 1e-2, 1e-1}) {
    const SurfacePoint sp = eval_derivs(u + du_sign * step, v + dv_sign * step);
    // Of the unit derivatives: the cross product of derivatives of a patch 1e100 across
    // would overflow (and of one 1e-100 across underflow).
    const double lu = sp.du.norm(), lv = sp.dv.norm();
    if (!(lu > 0.0) || !(lv > 0.0)) continue;
    const Vec3 n = (sp.du / lu).cross(sp.dv / lv);
    const double len = n.norm();
    if (len > 1e-10) return n / len;
  }
  fail(ErrorCode::Numerical, "surface normal undefined near (u=" + std::to_string(u) + ", v=" + std::to_string(v) + ")");
}

Grid BaseSurface::sample(int nu, int nv) const {
  if (nu < 2 || nv < 2)
    fail(ErrorCode::InvalidArgument, "surface sample grid must be at least 2 x 2, got " + std::to_string(nu) + " x " + std::to_string(nv));
  // eval() at every node, bit for bit: the Coons patch plus the displacement off the border.
  Grid g = coons_.sample(nu, nv);
  displacement_.add_to_interior(g);
  return g;
}

}  // namespace dbs
