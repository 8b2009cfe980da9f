// Coons patch, spline displacement and base surface: exact boundary interpolation, grid
// interpolation, derivatives, approximation of a known surface, scale invariance.
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <random>
#include <vector>

#include <Eigen/Geometry>

#include "base_surface.hpp"
#include "error.hpp"

// cmocka last (its fail() macro would hide dbs::fail), with C linkage (its header does
// not declare it).
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
extern "C" {
#include <cmocka.h>
}

using dbs::BaseSurface;
using dbs::Boundary;
using dbs::CoonsPatch;
using dbs::Grid;
using dbs::SplineDisplacement;
using dbs::SurfacePoint;
using dbs::Vec3;

namespace {

const double kPi = 3.14159265358979323846;

// A polyline along f(t), t in [0,1], through the given parameters (uneven on purpose).
template <class F>
std::vector<Vec3> trace(F f, const std::vector<double>& ts) {
  std::vector<Vec3> pts;
  for (double t : ts) pts.push_back(f(t));
  return pts;
}

std::vector<double> uneven_params(int n, double skew) {
  std::vector<double> ts;
  for (int i = 0; i < n; ++i) {
    const double t = static_cast<double>(i) / (n - 1);
    ts.push_back(std::pow(t, skew));
  }
  return ts;
}

// A curved, non-planar test surface over (x,y) in [0,3] x [0,2].
Vec3 wavy(double x, double y) { return Vec3(x + 0.1 * y * y, y - 0.05 * x * y, 0.4 * std::sin(1.3 * x) * std::cos(0.9 * y) + 0.1 * x * y); }

Boundary wavy_boundary(double scale) {
  auto s = [scale](Vec3 p) { return Vec3(scale * p); };
  return Boundary(trace([&](double t) { return s(wavy(3 * t, 0)); }, uneven_params(23, 1.4)),
                  trace([&](double t) { return s(wavy(3, 2 * t)); }, uneven_params(17, 0.8)),
                  trace([&](double t) { return s(wavy(3 * t, 2)); }, uneven_params(19, 1.0)),
                  trace([&](double t) { return s(wavy(0, 2 * t)); }, uneven_params(13, 1.7)));
}

Grid wavy_grid(int nu, int nv, double scale) {
  Grid g(nu, nv);
  for (int j = 0; j < nv; ++j)
    for (int i = 0; i < nu; ++i) g(i, j) = scale * wavy(3 * g.u(i), 2 * g.v(j));
  return g;
}

Boundary rectangle_boundary() {
  // Straight sides with unevenly spaced extra vertices: arc length keeps the map affine.
  return Boundary({Vec3(0, 0, 0), Vec3(0.3, 0, 0), Vec3(2.9, 0, 0), Vec3(4, 0, 0)}, {Vec3(4, 0, 0), Vec3(4, 1.7, 0), Vec3(4, 2, 0)},
                  {Vec3(0, 2, 0), Vec3(1, 2, 0), Vec3(1.1, 2, 0), Vec3(4, 2, 0)}, {Vec3(0, 0, 0), Vec3(0, 0.1, 0), Vec3(0, 2, 0)});
}

bool bitwise_equal(const Vec3& a, const Vec3& b) { return std::memcmp(a.data(), b.data(), 3 * sizeof(double)) == 0; }

void test_coons_rectangle_is_affine(void**) {
  const CoonsPatch coons(rectangle_boundary());
  double worst = 0, worst_d = 0;
  for (int j = 0; j <= 20; ++j)
    for (int i = 0; i <= 20; ++i) {
      const double u = i / 20.0 + (i % 3) * 1e-3 * (i < 20), v = j / 20.0 + (j % 2) * 1e-3 * (j < 20);
      worst = std::max(worst, (coons.eval(u, v) - Vec3(4 * u, 2 * v, 0)).norm());
      const SurfacePoint sp = coons.eval_derivs(u, v);
      worst_d = std::max({worst_d, (sp.du - Vec3(4, 0, 0)).norm(), (sp.dv - Vec3(0, 2, 0)).norm()});
      assert_true(bitwise_equal(sp.p, coons.eval(u, v)));
    }
  assert_true(worst < 1e-12 * 4.5);
  assert_true(worst_d < 1e-12 * 4.5);
}

void test_coons_reproduces_bilinear(void**) {
  // A hyperbolic paraboloid: straight sides between non-coplanar corners.
  const Vec3 p00(0, 0, 0), p10(2, 0, 1), p01(0, 3, 1), p11(2, 3, -0.5);
  auto bilinear = [&](double u, double v) { return Vec3((1 - u) * (1 - v) * p00 + u * (1 - v) * p10 + (1 - u) * v * p01 + u * v * p11); };
  const CoonsPatch coons(Boundary({p00, bilinear(0.25, 0), p10}, {p10, bilinear(1, 0.6), bilinear(1, 0.7), p11}, {p01, p11},
                                  {p00, bilinear(0, 0.9), p01}));
  double worst = 0, worst_d = 0;
  for (int j = 0; j <= 16; ++j)
    for (int i = 0; i <= 16; ++i) {
      const double u = i / 16.0, v = j / 16.0;
      worst = std::max(worst, (coons.eval(u, v) - bilinear(u, v)).norm());
      const SurfacePoint sp = coons.eval_derivs(u, v);
      const Vec3 du = (1 - v) * (p10 - p00) + v * (p11 - p01), dv = (1 - u) * (p01 - p00) + u * (p11 - p10);
      worst_d = std::max({worst_d, (sp.du - du).norm(), (sp.dv - dv).norm()});
    }
  assert_true(worst < 1e-12 * 4);
  assert_true(worst_d < 1e-12 * 4);
}

void test_spline_interpolates_and_vanishes_on_border(void**) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> val(-1, 1);
  for (int nu : {2, 3, 4, 9}) {
    const int nv = nu == 9 ? 6 : nu + 1;
    Grid g(nu, nv);
    for (int j = 1; j + 1 < nv; ++j)
      for (int i = 1; i + 1 < nu; ++i) g(i, j) = Vec3(val(rng), val(rng), val(rng));
    const SplineDisplacement d(g);
    for (int j = 0; j < nv; ++j)
      for (int i = 0; i < nu; ++i) assert_true((d.eval(g.u(i), g.v(j)) - g(i, j)).norm() < 1e-13);
    for (int k = 0; k <= 500; ++k) {
      const double t = std::uniform_real_distribution<double>(0, 1)(rng);
      for (const Vec3& x : {d.eval(t, 0), d.eval(t, 1), d.eval(0, t), d.eval(1, t)}) assert_true(x == Vec3::Zero());
      Vec3 p, du, dv;
      d.eval_derivs(t, 0, p, du, dv);
      assert_true(p == Vec3::Zero());
      assert_true(du.norm() < 1e-13);  // along the border
    }
  }
}

void test_spline_natural_reproduces_linear(void**) {
  // Natural cubic interpolation reproduces linear data exactly (up to rounding).
  Grid g(7, 5);
  for (int j = 0; j < 5; ++j)
    for (int i = 0; i < 7; ++i) g(i, j) = Vec3(1 + 2 * g.u(i) - g.v(j), 3 * g.v(j), g.u(i) + g.v(j));
  const SplineDisplacement d(g);
  for (int k = 0; k <= 50; ++k) {
    const double u = k / 50.0, v = std::fmod(k * 0.37, 1.0);
    Vec3 p, du, dv;
    d.eval_derivs(u, v, p, du, dv);
    assert_true((p - Vec3(1 + 2 * u - v, 3 * v, u + v)).norm() < 1e-13);
    assert_true((du - Vec3(2, 0, 1)).norm() < 1e-12);
    assert_true((dv - Vec3(-1, 3, 1)).norm() < 1e-12);
  }
}

void test_base_surface_interpolates_boundary_exactly(void**) {
  const Boundary boundary = wavy_boundary(1);
  const BaseSurface surface(boundary, wavy_grid(9, 7, 1));
  const double size = boundary.size();
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> unit(0, 1);
  double worst = 0;
  for (int k = 0; k <= 2000; ++k) {
    // Uniform samples, random ones and the sides' own vertex parameters all match.
    const double t = k <= 1000 ? k / 1000.0 : unit(rng);
    const Vec3 pts[4][2] = {{surface.eval(t, 0), boundary.bottom().at(t)},
                            {surface.eval(1, t), boundary.right().at(t)},
                            {surface.eval(t, 1), boundary.top().at(t)},
                            {surface.eval(0, t), boundary.left().at(t)}};
    for (const auto& pair : pts) {
      worst = std::max(worst, (pair[0] - pair[1]).norm());
      assert_true(bitwise_equal(pair[0], pair[1]));
    }
    assert_true(bitwise_equal(surface.eval_derivs(t, 0).p, boundary.bottom().at(t)));
    assert_true(bitwise_equal(surface.eval_derivs(1, t).p, boundary.right().at(t)));
  }
  assert_true(worst <= 1e-12 * size);
  for (int i = 0; i < 2; ++i)
    for (int j = 0; j < 2; ++j) assert_true(bitwise_equal(surface.eval(i, j), boundary.corner(i, j)));
}

void test_base_surface_interpolates_grid(void**) {
  const Boundary boundary = wavy_boundary(1);
  const Grid grid = wavy_grid(9, 7, 1);
  // Interior points moved off the wavy surface: the surface follows the grid, not the boundary.
  Grid moved = grid;
  for (int j = 1; j + 1 < grid.nv; ++j)
    for (int i = 1; i + 1 < grid.nu; ++i) moved(i, j) += Vec3(0.01 * i, -0.02 * j, 0.3 * ((i + j) % 3 - 1));
  const BaseSurface surface(boundary, moved);
  double worst = 0;
  for (int j = 1; j + 1 < grid.nv; ++j)
    for (int i = 1; i + 1 < grid.nu; ++i) worst = std::max(worst, (surface.eval(grid.u(i), grid.v(j)) - moved(i, j)).norm());
  assert_true(worst < 1e-10 * boundary.size());
  // Border points of the grid are ignored.
  Grid wild_border = moved;
  for (int i = 0; i < grid.nu; ++i) wild_border(i, 0) = Vec3(100, 100, 100);
  const BaseSurface same(boundary, wild_border);
  assert_true((same.eval(0.4, 0.3) - surface.eval(0.4, 0.3)).norm() == 0.0);
}

void test_derivatives_match_finite_differences(void**) {
  // Straight-sided saddle boundary (no polyline kinks) plus a displacement.
  const Vec3 p00(0, 0, 0), p10(2, 0, 1), p01(0, 3, 1), p11(2, 3, -0.5);
  const BaseSurface surface(Boundary({p00, p10}, {p10, p11}, {p01, p11}, {p00, p01}), [&] {
    Grid g(6, 5);
    for (int j = 0; j < 5; ++j)
      for (int i = 0; i < 6; ++i) {
        const double u = g.u(i), v = g.v(j);
        g(i, j) = (1 - u) * (1 - v) * p00 + u * (1 - v) * p10 + (1 - u) * v * p01 + u * v * p11 + Vec3(0.1 * u, 0.2 * v, std::sin(3 * u * v));
      }
    return g;
  }());
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> unit(0.01, 0.99);
  const double h = 1e-6;
  double worst = 0, scale = 0;
  for (int k = 0; k < 300; ++k) {
    const double u = unit(rng), v = unit(rng);
    const SurfacePoint sp = surface.eval_derivs(u, v);
    assert_true((sp.p - surface.eval(u, v)).norm() < 1e-15 * 4);
    const Vec3 fd_u = (surface.eval(u + h, v) - surface.eval(u - h, v)) / (2 * h);
    const Vec3 fd_v = (surface.eval(u, v + h) - surface.eval(u, v - h)) / (2 * h);
    worst = std::max({worst, (sp.du - fd_u).norm(), (sp.dv - fd_v).norm()});
    scale = std::max({scale, sp.du.norm(), sp.dv.norm()});
  }
  assert_true(scale > 1);
  assert_true(worst < 1e-8 * scale);
}

void test_derivatives_on_polyline_sides(void**) {
  // With polyline sides the derivatives are one-sided at vertex parameters; away from them
  // they still match finite differences.
  const BaseSurface surface(wavy_boundary(1), wavy_grid(9, 7, 1));
  const double h = 1e-7;
  double worst = 0;
  for (double u : {0.13, 0.41, 0.77}) {
    for (double v : {0.21, 0.52, 0.93}) {
      const SurfacePoint sp = surface.eval_derivs(u, v);
      const Vec3 fd_u = (surface.eval(u + h, v) - surface.eval(u, v)) / h;
      const Vec3 fd_v = (surface.eval(u, v + h) - surface.eval(u, v)) / h;
      worst = std::max({worst, (sp.du - fd_u).norm(), (sp.dv - fd_v).norm()});
    }
  }
  assert_true(worst < 1e-5);
}

// second_derivatives: central differences of the first derivatives (a displacement over
// polyline sides, at parameters away from the sides' vertices, where the Coons patch is
// bilinear in its sides' points).
void test_second_derivatives_match_finite_differences(void**) {
  const BaseSurface surface(wavy_boundary(1), wavy_grid(9, 7, 1));
  const double h = 1e-6;
  double worst = 0, scale = 0;
  for (double u : {0.13, 0.41, 0.77}) {
    for (double v : {0.21, 0.52, 0.93}) {
      const dbs::SecondDerivatives s = surface.second_derivatives(u, v);
      const SurfacePoint up = surface.eval_derivs(u + h, v), um = surface.eval_derivs(u - h, v);
      const SurfacePoint vp = surface.eval_derivs(u, v + h), vm = surface.eval_derivs(u, v - h);
      const Vec3 fd_uu = (up.du - um.du) / (2 * h), fd_vv = (vp.dv - vm.dv) / (2 * h);
      const Vec3 fd_uv = (vp.du - vm.du) / (2 * h), fd_vu = (up.dv - um.dv) / (2 * h);
      worst = std::max({worst, (s.uu - fd_uu).norm(), (s.vv - fd_vv).norm(), (s.uv - fd_uv).norm(), (s.uv - fd_vu).norm()});
      scale = std::max({scale, s.uu.norm(), s.vv.norm(), s.uv.norm()});
    }
  }
  assert_true(scale > 0.1);
  assert_true(worst < 1e-6 * scale);
}

void test_approximates_height_field(void**) {
  auto f = [](double x, double y) { return 0.2 * std::sin(kPi * x) * std::sin(kPi * y); };
  const Boundary square({Vec3(0, 0, 0), Vec3(1, 0, 0)}, {Vec3(1, 0, 0), Vec3(1, 1, 0)}, {Vec3(0, 1, 0), Vec3(1, 1, 0)},
                        {Vec3(0, 0, 0), Vec3(0, 1, 0)});
  Grid g(11, 11);
  for (int j = 0; j < 11; ++j)
    for (int i = 0; i < 11; ++i) g(i, j) = Vec3(g.u(i), g.v(j), f(g.u(i), g.v(j)));
  const BaseSurface surface(square, g);
  std::mt19937 rng(17);
  std::uniform_real_distribution<double> unit(0, 1);
  double worst = 0;
  for (int k = 0; k < 5000; ++k) {
    const Vec3 p = surface.eval(unit(rng), unit(rng));
    worst = std::max(worst, std::fabs(p.z() - f(p.x(), p.y())));
  }
  // Cubic interpolation with h = 0.1: the error is of order 1e-5.
  assert_true(worst < 1e-4);
  // The Coons patch alone (z = 0) is 0.2 off at the centre.
  assert_true(std::fabs(BaseSurface(square).eval(0.5, 0.5).z()) == 0.0);
}

void test_scaling_scales_surface(void**) {
  const BaseSurface a(wavy_boundary(1), wavy_grid(8, 6, 1));
  const BaseSurface b(wavy_boundary(1000), wavy_grid(8, 6, 1000));
  std::mt19937 rng(23);
  std::uniform_real_distribution<double> unit(0, 1);
  double worst = 0;
  for (int k = 0; k < 1000; ++k) {
    const double u = unit(rng), v = unit(rng);
    worst = std::max(worst, (b.eval(u, v) - 1000 * a.eval(u, v)).norm() / (1000 * a.boundary().size()));
    const SurfacePoint da = a.eval_derivs(u, v), db = b.eval_derivs(u, v);
    worst = std::max(worst, (db.du - 1000 * da.du).norm() / (1000 * da.du.norm()));
    worst = std::max(worst, (b.normal(u, v) - a.normal(u, v)).norm());
  }
  assert_true(worst < 1e-12);
}

void test_eval_clamps_and_rejects_nan(void**) {
  const BaseSurface surface(wavy_boundary(1), wavy_grid(5, 5, 1));
  assert_true(bitwise_equal(surface.eval(-0.5, 0.3), surface.eval(0, 0.3)));
  assert_true(bitwise_equal(surface.eval(0.3, 7), surface.eval(0.3, 1)));
  assert_true(bitwise_equal(surface.eval(2, -1), surface.boundary().corner(1, 0)));
  try {
    surface.eval(std::nan(""), 0.5);
    fail();
  } catch (const dbs::Error& e) {
    assert_int_equal(e.code(), dbs::ErrorCode::NonFinite);
  }
}

void test_sample(void**) {
  const BaseSurface surface(wavy_boundary(1), wavy_grid(6, 6, 1));
  const Grid s = surface.sample(5, 4);
  assert_int_equal(s.nu, 5);
  assert_int_equal(s.nv, 4);
  for (int j = 0; j < 4; ++j)
    for (int i = 0; i < 5; ++i) assert_true(bitwise_equal(s(i, j), surface.eval(i / 4.0, j / 3.0)));
  // sample() evaluates each side once per row or column and the spline's basis once per row
  // and column: still eval() bit for bit, at sizes off the spline's sites and without a grid.
  const BaseSurface coons_only(wavy_boundary(1));
  for (const BaseSurface* f : {&surface, &coons_only})
    for (const auto& size : {std::pair<int, int>{64, 64}, {17, 33}, {2, 2}}) {
      const Grid g = f->sample(size.first, size.second);
      for (int j = 0; j < g.nv; ++j)
        for (int i = 0; i < g.nu; ++i) assert_true(bitwise_equal(g(i, j), f->eval(g.u(i), g.v(j))));
    }
  try {
    surface.sample(1, 4);
    fail();
  } catch (const dbs::Error& e) {
    assert_int_equal(e.code(), dbs::ErrorCode::InvalidArgument);
  }
}

void test_grid_errors(void**) {
  const Boundary boundary = wavy_boundary(1);
  Grid g = wavy_grid(5, 4, 1);
  g(2, 1).y() = std::nan("");
  try {
    BaseSurface s(boundary, g);
    fail();
  } catch (const dbs::Error& e) {
    assert_int_equal(e.code(), dbs::ErrorCode::NonFinite);
    assert_non_null(std::strstr(e.what(), "(2,1)"));
  }
  try {
    BaseSurface s(boundary, Grid(1, 4));
    fail();
  } catch (const dbs::Error& e) {
    assert_int_equal(e.code(), dbs::ErrorCode::InvalidArgument);
  }
  // A grid with no interior points leaves the Coons patch.
  const BaseSurface coons_only(boundary, wavy_grid(2, 9, 1));
  assert_true(bitwise_equal(coons_only.eval(0.3, 0.6), CoonsPatch(boundary).eval(0.3, 0.6)));
}

void test_normal(void**) {
  const BaseSurface flat(rectangle_boundary());
  for (double u : {0.0, 0.3, 1.0})
    for (double v : {0.0, 0.6, 1.0}) assert_true((flat.normal(u, v) - Vec3(0, 0, 1)).norm() < 1e-14);
  // Bottom and left leave the corner (0,0) in opposite directions (a straight angle):
  // Su x Sv vanishes there and the normal is the limit from inside.
  const BaseSurface cusp(Boundary({Vec3(0, 0, 0), Vec3(2, 0, 0)}, {Vec3(2, 0, 0), Vec3(2, 2, 0)}, {Vec3(-1, 2, 0), Vec3(2, 2, 0)},
                                  {Vec3(0, 0, 0), Vec3(-1, 0, 0), Vec3(-1, 2, 0)}));
  const SurfacePoint sp = cusp.eval_derivs(0, 0);
  assert_true(sp.du.cross(sp.dv).norm() < 1e-12);
  const Vec3 n = cusp.normal(0, 0);
  assert_true(std::isfinite(n.norm()));
  assert_true((n - Vec3(0, 0, 1)).norm() < 1e-12);
  // Curved surface: unit length and orthogonal to both derivatives.
  const BaseSurface wavy(wavy_boundary(1), wavy_grid(7, 7, 1));
  for (double u : {0.1, 0.5, 0.9}) {
    const SurfacePoint w = wavy.eval_derivs(u, 1 - u);
    const Vec3 m = wavy.normal(u, 1 - u);
    assert_true(std::fabs(m.norm() - 1) < 1e-14);
    assert_true(std::fabs(m.dot(w.du)) < 1e-12 * w.du.norm());
    assert_true(std::fabs(m.dot(w.dv)) < 1e-12 * w.dv.norm());
  }
}

}  // namespace

int main() {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(test_coons_rectangle_is_affine),
      cmocka_unit_test(test_coons_reproduces_bilinear),
      cmocka_unit_test(test_spline_interpolates_and_vanishes_on_border),
      cmocka_unit_test(test_spline_natural_reproduces_linear),
      cmocka_unit_test(test_base_surface_interpolates_boundary_exactly),
      cmocka_unit_test(test_base_surface_interpolates_grid),
      cmocka_unit_test(test_derivatives_match_finite_differences),
      cmocka_unit_test(test_derivatives_on_polyline_sides),
      cmocka_unit_test(test_second_derivatives_match_finite_differences),
      cmocka_unit_test(test_approximates_height_field),
      cmocka_unit_test(test_scaling_scales_surface),
      cmocka_unit_test(test_eval_clamps_and_rejects_nan),
      cmocka_unit_test(test_sample),
      cmocka_unit_test(test_grid_errors),
      cmocka_unit_test(test_normal),
  };
  return cmocka_run_group_tests(tests, nullptr, nullptr);
}
