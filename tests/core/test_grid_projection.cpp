// Grid projection (section 5.2): a grid on the flat Coons patch of a height field's boundary
// moves onto the cloud along its normals (closer with each evolution), its border stays
// bitwise on the boundary, the result is invariant to scaling by 1000 plus a rigid motion, and
// it is bit for bit that of every section projected alone (the shared rays change nothing).
#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <functional>
#include <random>

#include "cloud_index.hpp"
#include "error.hpp"
#include "grid_projection.hpp"

// cmocka last (its fail() macro would hide dbs::fail), with C linkage (its header does
// not declare it).
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
extern "C" {
#include <cmocka.h>
}

using namespace dbs;

namespace {

constexpr double kGamma = 0.5;

double height(double x, double y) { return 0.2 * std::sin(M_PI * x) * std::sin(M_PI * y); }

/// A jittered 150 x 150 sampling of the height field over the unit square.
std::vector<Vec3> height_cloud() {
  std::mt19937_64 rng(9);
  std::uniform_real_distribution<double> jitter(-0.3, 0.3);
  std::vector<Vec3> pts;
  const int n = 150;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const double x = std::clamp((i + 0.5 + jitter(rng)) / n, 0.0, 1.0), y = std::clamp((j + 0.5 + jitter(rng)) / n, 0.0, 1.0);
      pts.emplace_back(x, y, height(x, y));
    }
  return pts;
}

std::vector<Vec3> side(const Vec3& a, const Vec3& b) {
  std::vector<Vec3> pts;
  for (int k = 0; k <= 8; ++k) pts.push_back(a + (k / 8.0) * (b - a));
  return pts;
}

/// The unit square at z = 0: the height field's boundary (it vanishes there).
Boundary square(const std::function<Vec3(const Vec3&)>& map) {
  auto mapped = [&](std::vector<Vec3> pts) {
    for (Vec3& p : pts) p = map(p);
    return pts;
  };
  return Boundary(mapped(side({0, 0, 0}, {1, 0, 0})), mapped(side({1, 0, 0}, {1, 1, 0})), mapped(side({0, 1, 0}, {1, 1, 0})), mapped(side({0, 0, 0}, {0, 1, 0})));
}

bool same_bits(const Vec3& a, const Vec3& b) { return std::memcmp(a.data(), b.data(), sizeof(double) * 3) == 0; }

double worst_height_error(const Grid& g) {
  double worst = 0.0;
  for (int j = 1; j + 1 < g.nv; ++j)
    for (int i = 1; i + 1 < g.nu; ++i) worst = std::max(worst, std::abs(g(i, j).z() - height(g(i, j).x(), g(i, j).y())));
  return worst;
}

void grid_moves_onto_height_field(void**) {
  const std::vector<Vec3> pts = height_cloud();
  CloudIndex index(pts);
  const DirectedProjector projector(index, cloud_spacing(index));
  const double h = projector.length_scale();
  const Boundary boundary = square([](const Vec3& p) { return p; });
  const BaseSurface flat(boundary);
  const Grid before = flat.sample(9, 9);
  const Grid after = project_grid(flat, 9, 9, projector, kGamma);
  assert_int_equal(after.nu, 9);
  assert_int_equal(after.nv, 9);
  for (int j = 0; j < 9; ++j)
    for (int i = 0; i < 9; ++i) {
      if (i == 0 || j == 0 || i == 8 || j == 8) {
        assert_true(same_bits(after(i, j), before(i, j)));
      } else {
        // The flat patch's normals are vertical: only z changes.
        assert_true(after(i, j).x() == before(i, j).x() && after(i, j).y() == before(i, j).y());
      }
    }
  // The flat start is up to 0.2 (about 30 h) away from the cloud; one projection brings the
  // grid close, a second one from the surface through the first grid closer still.
  const double first = worst_height_error(after);
  const BaseSurface evolved(boundary, after);
  const double second = worst_height_error(project_grid(evolved, 9, 9, projector, kGamma));
  std::printf("height field (peak %.1f h): grid off the cloud by %.3f h after one projection, %.3f h after two\n", 0.2 / h, first / h, second / h);
  assert_true(first <= 3.0 * h);
  assert_true(second <= 0.5 * h);
}

void grid_is_invariant_to_scale_and_rigid_motion(void**) {
  const Eigen::Matrix3d rotation = Eigen::AngleAxisd(0.9, Vec3(-1, 2, 2).normalized()).toRotationMatrix();
  auto move = [&](const Vec3& p) { return Vec3(1000.0 * (rotation * p + Vec3(3, 1, -2))); };
  const std::vector<Vec3> pts = height_cloud();
  std::vector<Vec3> moved_pts;
  for (const Vec3& p : pts) moved_pts.push_back(move(p));
  CloudIndex index(pts), moved_index(moved_pts);
  const DirectedProjector projector(index, cloud_spacing(index)), moved_projector(moved_index, cloud_spacing(moved_index));
  const Grid g = project_grid(BaseSurface(square([](const Vec3& p) { return p; })), 7, 6, projector, kGamma);
  const Grid moved = project_grid(BaseSurface(square(move)), 7, 6, moved_projector, kGamma);
  const double h = projector.length_scale();
  for (std::size_t k = 0; k < g.points.size(); ++k) assert_true((moved.points[k] - move(g.points[k])).norm() <= 1e-9 * 1000.0 * h);
}

/// The offsets of one section projected alone (densified, every node's ray its own), at its
/// own points.
std::vector<double> section_alone(const std::vector<Vec3>& points, const std::vector<Vec3>& normals, const DirectedProjector& projector) {
  double length = 0.0;
  for (std::size_t k = 0; k + 1 < points.size(); ++k) length += (points[k + 1] - points[k]).norm();
  const double spacing = std::max(kNodeSpacing * projector.length_scale(), length / static_cast<double>(kMaxSectionNodes));
  std::vector<std::size_t> original;
  const CurveProjectionInput input = densify_polygon(points, normals, spacing, original, kMaxSectionNodes);
  const std::vector<double> t = project_curve(projector, input, kGamma);
  std::vector<double> out;
  for (std::size_t k : original) out.push_back(t[k]);
  return out;
}

/// The rows and columns share the rays at the grid points where they cross: the grid is bit for
/// bit the one of every section projected alone (a 7 x 5 grid on the evolved height field, so
/// that a row and a column index a grid point differently and its normals are tilted).
void grid_is_that_of_its_sections_alone(void**) {
  const std::vector<Vec3> pts = height_cloud();
  CloudIndex index(pts);
  const DirectedProjector projector(index, cloud_spacing(index));
  const Boundary boundary = square([](const Vec3& p) { return p; });
  const BaseSurface surface(boundary, project_grid(BaseSurface(boundary), 9, 9, projector, kGamma));
  const int nu = 7, nv = 5;
  std::size_t damped = 1;
  const Grid g = project_grid(surface, nu, nv, projector, kGamma, &damped);
  assert_int_equal(damped, 0);  // no node held back: the move is the offsets' mean
  const Grid start = surface.sample(nu, nv);
  Grid normals(nu, nv);
  for (int j = 0; j < nv; ++j)
    for (int i = 0; i < nu; ++i) normals(i, j) = surface.normal(start.u(i), start.v(j));
  std::vector<double> row(start.points.size()), column(start.points.size());
  for (int j = 1; j + 1 < nv; ++j) {
    std::vector<Vec3> p, n;
    for (int i = 0; i < nu; ++i) p.push_back(start(i, j)), n.push_back(normals(i, j));
    const std::vector<double> t = section_alone(p, n, projector);
    for (int i = 0; i < nu; ++i) row[static_cast<std::size_t>(j * nu + i)] = t[static_cast<std::size_t>(i)];
  }
  for (int i = 1; i + 1 < nu; ++i) {
    std::vector<Vec3> p, n;
    for (int j = 0; j < nv; ++j) p.push_back(start(i, j)), n.push_back(normals(i, j));
    const std::vector<double> t = section_alone(p, n, projector);
    for (int j = 0; j < nv; ++j) column[static_cast<std::size_t>(j * nu + i)] = t[static_cast<std::size_t>(j)];
  }
  double moved = 0.0;
  for (int j = 1; j + 1 < nv; ++j)
    for (int i = 1; i + 1 < nu; ++i) {
      const std::size_t k = static_cast<std::size_t>(j * nu + i);
      const Vec3 expected = start.points[k] + 0.5 * (row[k] + column[k]) * normals.points[k];
      assert_true(same_bits(g.points[k], expected));
      moved = std::max(moved, (g.points[k] - start.points[k]).norm());
    }
  assert_true(moved > 0.0);
}

void grid_without_interior_is_the_sample(void**) {
  const std::vector<Vec3> pts = height_cloud();
  CloudIndex index(pts);
  const DirectedProjector projector(index, cloud_spacing(index));
  const BaseSurface flat(square([](const Vec3& p) { return p; }));
  const Grid g = project_grid(flat, 2, 5, projector, kGamma), s = flat.sample(2, 5);
  for (std::size_t k = 0; k < g.points.size(); ++k) assert_true(same_bits(g.points[k], s.points[k]));
  bool thrown = false;
  try {
    project_grid(flat, 1, 5, projector, kGamma);
  } catch (const Error& e) {
    thrown = e.code() == ErrorCode::InvalidArgument;
  }
  assert_true(thrown);
}

}  // namespace

int main() {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(grid_moves_onto_height_field),
      cmocka_unit_test(grid_is_invariant_to_scale_and_rigid_motion),
      cmocka_unit_test(grid_is_that_of_its_sections_alone),
      cmocka_unit_test(grid_without_interior_is_the_sample),
  };
  return cmocka_run_group_tests(tests, nullptr, nullptr);
}
