// End-to-end tests of the single-patch method (maximum level 0) on analytic surfaces:
// exactness on a plane, accuracy on a height field, exact boundary interpolation, invariance
// to scale and rigid motion, and nearest-arm parameterization of a U-shaped surface.
#include <algorithm>
#include <cmath>

#include "analytic_clouds.hpp"
#include "parameterize.hpp"

// cmocka last: its fail() macro would hide dbs::fail.
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
extern "C" {
#include <cmocka.h>
}

using namespace dbs;
using namespace dbs_test;

namespace {

Options single_patch() {
  Options o;
  o.max_level = 0;
  o.threads = 2;
  return o;
}

void plane_gets_the_affine_map(void**) {
  // A 3 x 2 rectangle in a tilted plane: (u,v) must be (x/3, y/2) in the plane's frame.
  const Vec3 origin(1, 2, 3), ex = Vec3(1, 1, 0).normalized(), ey = Vec3(-1, 1, 1).normalized();  // orthogonal to ex
  const Surface plane = [&](double a, double b) { return Vec3(origin + 3.0 * a * ex + 2.0 * b * ey); };
  std::vector<Vec2> ab;
  PointCloud cloud(random_points(plane, 5000, 1, &ab));
  Result r = parameterize(cloud, boundary_of(plane, 4), single_patch());
  double worst = 0.0;
  for (std::size_t i = 0; i < ab.size(); ++i) worst = std::max({worst, std::abs(r.u[i] - ab[i].x()), std::abs(r.v[i] - ab[i].y())});
  assert_true(worst < 1e-9);
  assert_true(r.max_distance < 1e-9);
}

void height_field_meets_accuracy(void**) {
  const Surface s = height_field();
  std::vector<Vec3> pts = random_points(s, 20000, 2);
  // Points exactly on each side, to check they land on that side.
  const std::size_t first_side = pts.size();
  for (int k = 1; k < 50; ++k) {
    const double t = k / 50.0;
    pts.push_back(s(t, 0));  // bottom: v = 0
    pts.push_back(s(1, t));  // right: u = 1
    pts.push_back(s(t, 1));  // top: v = 1
    pts.push_back(s(0, t));  // left: u = 0
  }
  PointCloud cloud(pts);
  Options o = single_patch();
  o.relative_accuracy = 5e-5;  // met on a grid larger than the first (7 x 7)
  Result r = parameterize(cloud, boundary_of(s, 40), o);
  std::printf("height field: grid %d x %d after %d iterations, mean distance %.3g, target %.3g\n", r.patches[0].grid.nu, r.patches[0].grid.nv, r.iterations, r.mean_distance, r.accuracy);
  assert_true(r.mean_distance <= r.accuracy);
  assert_true(r.accuracy > 0.0 && r.accuracy < 1e-3);
  // After one warm-up projection at initial_grid - 1 (no node damped here), the grid grew
  // one row and column per iteration and stopped at the first size that met the accuracy:
  // one size smaller misses it.
  const Grid& grid = r.patches[0].grid;
  assert_int_equal(r.patches[0].damped_nodes, 0);
  assert_true(r.iterations >= 3);
  assert_int_equal(grid.nu, o.initial_grid + r.iterations - 2);
  assert_int_equal(grid.nv, grid.nu);
  Options smaller = o;
  smaller.max_grid = grid.nu - 1;
  smaller.fit_to_target = 0;
  const Result missed = parameterize(cloud, boundary_of(s, 40), smaller);
  assert_true(missed.mean_distance > missed.accuracy);
  assert_int_equal(missed.patches[0].grid.nu, smaller.max_grid);
  // That grid fitted to its points at their feet (fit_to_target.hpp, on by default) meets it.
  smaller.fit_to_target = 1;
  const Result fitted = parameterize(cloud, boundary_of(s, 40), smaller);
  std::printf("height field: the %d x %d grid projected %.3g, fitted %.3g\n", smaller.max_grid, smaller.max_grid, missed.mean_distance, fitted.mean_distance);
  assert_int_equal(fitted.patches[0].grid.nu, smaller.max_grid);
  assert_true(fitted.mean_distance <= fitted.accuracy);
  assert_true(fitted.mean_distance < 0.8 * missed.mean_distance);
  for (std::size_t i = 0; i < pts.size(); ++i) {
    assert_true(r.u[i] >= 0.0 && r.u[i] <= 1.0 && r.v[i] >= 0.0 && r.v[i] <= 1.0);
  }
  for (std::size_t i = first_side; i < pts.size(); i += 4) {
    assert_true(std::abs(r.v[i]) < 1e-9);
    assert_true(std::abs(r.u[i + 1] - 1.0) < 1e-9);
    assert_true(std::abs(r.v[i + 2] - 1.0) < 1e-9);
    assert_true(std::abs(r.u[i + 3]) < 1e-9);
  }
  // The bump is symmetric and the boundary is the flat unit square: parameters stay close
  // to (x, y) (arc length along the bump stretches them by at most a few percent).
  double worst = 0.0;
  for (std::size_t i = 0; i < first_side; ++i) worst = std::max({worst, std::abs(r.u[i] - pts[i].x()), std::abs(r.v[i] - pts[i].y())});
  assert_true(worst < 0.05);
}

void surface_interpolates_boundary(void**) {
  const Surface s = height_field();
  const Boundary boundary = boundary_of([&](double a, double b) { return Vec3(s(a, b) + Vec3(0, 0, 0.3 * a * b)); }, 17);
  PointCloud cloud(random_points(s, 3000, 3));
  Result r = parameterize(cloud, boundary, single_patch());
  const double size = boundary.size();
  double worst = 0.0;
  for (int k = 0; k <= 200; ++k) {
    const double t = k / 200.0;
    worst = std::max(worst, (r.evaluate(t, 0) - boundary.bottom().at(t)).norm());
    worst = std::max(worst, (r.evaluate(t, 1) - boundary.top().at(t)).norm());
    worst = std::max(worst, (r.evaluate(0, t) - boundary.left().at(t)).norm());
    worst = std::max(worst, (r.evaluate(1, t) - boundary.right().at(t)).norm());
  }
  assert_true(worst <= 1e-12 * size);
}

void invariant_to_scale_and_rigid_motion(void**) {
  const Surface s = height_field();
  const Surface moved = [&](double a, double b) { return move_and_scale(s(a, b), 1000.0); };
  PointCloud c1(random_points(s, 4000, 4)), c2(random_points(moved, 4000, 4));
  Result r1 = parameterize(c1, boundary_of(s, 30), single_patch());
  Result r2 = parameterize(c2, boundary_of(moved, 30), single_patch());
  double worst = 0.0;
  for (std::size_t i = 0; i < r1.u.size(); ++i) worst = std::max({worst, std::abs(r1.u[i] - r2.u[i]), std::abs(r1.v[i] - r2.v[i])});
  assert_true(worst < 1e-9);
  assert_true(std::abs(r2.length_scale / r1.length_scale - 1000.0) < 1e-6);
  assert_int_equal(r1.iterations, r2.iterations);
}

void u_shape_points_go_to_nearer_arm(void**) {
  // A U-shaped profile in the xz-plane extruded along y: arm A (x = 0) down, a half circle
  // of radius 0.2, arm B (x = 0.4) up. Arms face each other 0.4 apart.
  const double arm = 1.0, radius = 0.2, length = 2 * arm + M_PI * radius;
  const Surface u_shape = [=](double a, double b) {
    double s = a * length;
    if (s <= arm) return Vec3(0, b, arm - s);
    s -= arm;
    if (s <= M_PI * radius) {
      const double phi = M_PI - s / radius;  // from the left end of the half circle
      return Vec3(radius + radius * std::cos(phi), b, -radius * std::sin(phi));
    }
    s -= M_PI * radius;
    return Vec3(2 * radius, b, s);
  };
  std::vector<Vec3> pts = random_points(u_shape, 8000, 5);
  const std::size_t first_probe = pts.size();
  for (int k = 0; k < 20; ++k) {
    const double y = 0.05 + 0.9 * k / 19.0, z = 0.2 + 0.6 * (k % 5) / 4.0;
    pts.emplace_back(0.12, y, z);  // 0.12 from arm A, 0.28 from arm B
    pts.emplace_back(0.29, y, z);  // 0.11 from arm B
  }
  PointCloud cloud(pts);
  Result r = parameterize(cloud, boundary_of(u_shape, 60), single_patch());
  const double arm_end = arm / length;
  // The probes pull the grid nodes whose rays pass near them (eq. 5 weighs a point on the
  // ray fully at any distance), so the arms bend towards them by up to about 0.01; the far
  // arm would be 0.28 / 0.29 away.
  for (std::size_t i = first_probe; i < pts.size(); i += 2) {
    assert_true(r.u[i] < arm_end);            // on arm A
    assert_true(std::abs(r.distance[i] - 0.12) < 0.02);
    assert_true(r.u[i + 1] > 1.0 - arm_end);  // on arm B
    assert_true(std::abs(r.distance[i + 1] - 0.11) < 0.02);
  }
}

}  // namespace

int main() {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(plane_gets_the_affine_map),
      cmocka_unit_test(height_field_meets_accuracy),
      cmocka_unit_test(surface_interpolates_boundary),
      cmocka_unit_test(invariant_to_scale_and_rigid_motion),
      cmocka_unit_test(u_shape_points_go_to_nearer_arm),
  };
  return cmocka_run_group_tests(tests, nullptr, nullptr);
}
