// Subdivision of a patch into four (algorithm A1.1-A1.4): straight middle curves on a plane,
// exact tiling of the parameter rectangle, bitwise shared corners and seams, equal surfaces
// along the seams, children that start as the parent's surface, middle curves that follow a
// curved cloud, and a centre over a hole that keeps the parent's shape.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>

#include "analytic_clouds.hpp"
#include "cloud_index.hpp"
#include "error.hpp"
#include "subdivide.hpp"

// cmocka last: its fail() macro would clash with dbs::fail and <ios>. It is a C library.
extern "C" {
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>
}

using namespace dbs;
using namespace dbs_test;

namespace {

bool same_bits(const Vec3& a, const Vec3& b) { return std::memcmp(a.data(), b.data(), 3 * sizeof(double)) == 0; }

bool same_polyline(const Polyline& a, const Polyline& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t k = 0; k < a.size(); ++k) {
    if (!same_bits(a.points()[k], b.points()[k])) return false;
  }
  return true;
}

/// A 2 x 1 rectangle in the plane z = 0 whose sides have unevenly spaced vertices.
Boundary flat_rectangle() {
  return Boundary({{0, 0, 0}, {0.3, 0, 0}, {1.1, 0, 0}, {2, 0, 0}},  // bottom
                  {{2, 0, 0}, {2, 0.7, 0}, {2, 1, 0}},                // right
                  {{0, 1, 0}, {0.9, 1, 0}, {1.6, 1, 0}, {2, 1, 0}},  // top
                  {{0, 0, 0}, {0, 0.2, 0}, {0, 0.45, 0}, {0, 1, 0}}); // left
}

/// Jittered grid of points on the rectangle [0,w] x [0,1], z = f(x,y).
std::vector<Vec3> jittered_cloud(double w, int nx, int ny, const std::function<double(double, double)>& f) {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> jitter(-0.3, 0.3);
  std::vector<Vec3> pts;
  for (int j = 0; j < ny; ++j) {
    for (int i = 0; i < nx; ++i) {
      const double x = std::clamp((i + 0.5 + jitter(rng)) * w / nx, 0.0, w);
      const double y = std::clamp((j + 0.5 + jitter(rng)) / ny, 0.0, 1.0);
      pts.emplace_back(x, y, f(x, y));
    }
  }
  return pts;
}

Patch flat_parent() {
  Patch parent{BaseSurface(flat_rectangle())};
  parent.id = 7;
  parent.level = 2;
  parent.rect = Rect{0.5, 0.25, 1.0, 0.5};
  return parent;
}

void flat_patch_splits_on_its_midlines(void**) {
  const std::vector<Vec3> pts = jittered_cloud(2.0, 100, 50, [](double, double) { return 0.0; });
  CloudIndex index(pts);
  DirectedProjector projector(index, cloud_spacing(index));
  const Patch parent = flat_parent();
  const std::array<Patch, 4> c = subdivide_patch(parent, projector, 0.5, 5);
  const double size = parent.surface.boundary().size();

  // The u = 1/2 seams lie on x = 1 and the v = 1/2 seams on y = 1/2, all in the plane.
  double worst = 0.0;
  for (const Vec3& p : c[0].surface.boundary().right().points()) worst = std::max({worst, std::abs(p.x() - 1.0), std::abs(p.z())});
  for (const Vec3& p : c[2].surface.boundary().right().points()) worst = std::max({worst, std::abs(p.x() - 1.0), std::abs(p.z())});
  for (const Vec3& p : c[0].surface.boundary().top().points()) worst = std::max({worst, std::abs(p.y() - 0.5), std::abs(p.z())});
  for (const Vec3& p : c[1].surface.boundary().top().points()) worst = std::max({worst, std::abs(p.y() - 0.5), std::abs(p.z())});
  std::printf("flat: midline deviation %.3g (relative %.3g), seam nodes %zu + %zu\n", worst, worst / size, c[0].surface.boundary().right().size(), c[2].surface.boundary().right().size());
  assert_true(worst <= 1e-9 * size);
  assert_true((c[3].surface.boundary().corner(0, 0) - Vec3(1.0, 0.5, 0.0)).norm() <= 1e-9 * size);
  // The densified seams are at least as fine as the cloud.
  assert_true(c[0].surface.boundary().right().size() >= 20);

  // Quadtree bookkeeping and exact tiling of the parent's rectangle.
  for (const Patch& child : c) {
    assert_int_equal(child.level, 3);
    assert_int_equal(child.parent, 7);
    assert_int_equal(child.grid.nu, 5);
    assert_int_equal(child.grid.nv, 5);
  }
  const Rect expected[4] = {{0.5, 0.25, 0.75, 0.375}, {0.75, 0.25, 1.0, 0.375}, {0.5, 0.375, 0.75, 0.5}, {0.75, 0.375, 1.0, 0.5}};
  for (int i = 0; i < 4; ++i) {
    assert_true(c[i].rect.u0 == expected[i].u0 && c[i].rect.v0 == expected[i].v0);
    assert_true(c[i].rect.u1 == expected[i].u1 && c[i].rect.v1 == expected[i].v1);
  }

  // Corners shared bitwise: outer ones with the parent, inner ones with the neighbours.
  const Boundary& pb = parent.surface.boundary();
  const Boundary* b[4] = {&c[0].surface.boundary(), &c[1].surface.boundary(), &c[2].surface.boundary(), &c[3].surface.boundary()};
  assert_true(same_bits(b[0]->corner(0, 0), pb.corner(0, 0)));
  assert_true(same_bits(b[1]->corner(1, 0), pb.corner(1, 0)));
  assert_true(same_bits(b[2]->corner(0, 1), pb.corner(0, 1)));
  assert_true(same_bits(b[3]->corner(1, 1), pb.corner(1, 1)));
  assert_true(same_bits(b[0]->corner(1, 0), b[1]->corner(0, 0)));
  assert_true(same_bits(b[0]->corner(0, 1), b[2]->corner(0, 0)));
  assert_true(same_bits(b[1]->corner(1, 1), b[3]->corner(1, 0)));
  assert_true(same_bits(b[2]->corner(1, 1), b[3]->corner(0, 1)));
  const Vec3 centre = b[0]->corner(1, 1);
  assert_true(same_bits(b[1]->corner(0, 1), centre) && same_bits(b[2]->corner(1, 0), centre) && same_bits(b[3]->corner(0, 0), centre));
  // The sides' midpoints are exact: arc-length midpoints of the parent's sides.
  assert_true(same_bits(b[0]->corner(1, 0), pb.bottom().split(0.5).first.back()));
  assert_true(std::abs(b[0]->corner(1, 0).x() - 1.0) <= 1e-15 && std::abs(b[0]->corner(0, 1).y() - 0.5) <= 1e-15);

  // Seams identical vertex for vertex; outer halves are the parent's halves.
  assert_true(same_polyline(b[0]->right(), b[1]->left()));
  assert_true(same_polyline(b[2]->right(), b[3]->left()));
  assert_true(same_polyline(b[0]->top(), b[2]->bottom()));
  assert_true(same_polyline(b[1]->top(), b[3]->bottom()));
  assert_true(same_polyline(b[0]->bottom(), pb.bottom().split(0.5).first));
  assert_true(same_polyline(b[3]->right(), pb.right().split(0.5).second));

  // Neighbouring surfaces agree along the seams; on a plane each child is the parent's
  // affine map over its quarter (this checks the grid is taken from the right quarter).
  double seam_gap = 0.0, quarter_gap = 0.0;
  for (int k = 0; k <= 200; ++k) {
    const double t = k / 200.0;
    seam_gap = std::max(seam_gap, (c[0].surface.eval(1.0, t) - c[1].surface.eval(0.0, t)).norm());
    seam_gap = std::max(seam_gap, (c[2].surface.eval(1.0, t) - c[3].surface.eval(0.0, t)).norm());
    seam_gap = std::max(seam_gap, (c[0].surface.eval(t, 1.0) - c[2].surface.eval(t, 0.0)).norm());
    seam_gap = std::max(seam_gap, (c[1].surface.eval(t, 1.0) - c[3].surface.eval(t, 0.0)).norm());
    for (int q = 0; q < 4; ++q) {
      const double s = std::fmod(0.37 * k, 1.0);
      const double u0 = (q % 2) * 0.5, v0 = (q / 2) * 0.5;
      quarter_gap = std::max(quarter_gap, (c[q].surface.eval(s, t) - parent.surface.eval(u0 + 0.5 * s, v0 + 0.5 * t)).norm());
    }
  }
  std::printf("flat: seam gap %.3g, child vs parent quarter %.3g\n", seam_gap, quarter_gap);
  assert_true(seam_gap <= 1e-12 * size);
  assert_true(quarter_gap <= 1e-9 * size);
}

/// Vertical distance of p to the height field z = 0.2 sin(pi x) sin(pi y) (an upper bound of
/// its distance to that surface).
double height_gap(const Vec3& p) { return std::abs(p.z() - 0.2 * std::sin(M_PI * p.x()) * std::sin(M_PI * p.y())); }

void middle_curves_follow_a_curved_cloud(void**) {
  const Surface s = height_field();
  const std::vector<Vec3> pts = jittered_cloud(1.0, 80, 80, [&](double x, double y) { return s(x, y).z(); });
  CloudIndex index(pts);
  const double h = cloud_spacing(index);
  DirectedProjector projector(index, h);
  // The parent is the flat Coons patch of the boundary: the bump (height 0.2) is all to find.
  Patch parent{BaseSurface(boundary_of(s, 9))};
  const std::array<Patch, 4> c = subdivide_patch(parent, projector, 0.5, 6);

  const Vec3 centre = c[0].surface.boundary().corner(1, 1);
  const double centre_gap = height_gap(centre);
  double curve_gap = 0.0;
  const Polyline* seams[4] = {&c[0].surface.boundary().right(), &c[2].surface.boundary().right(), &c[0].surface.boundary().top(), &c[1].surface.boundary().top()};
  for (const Polyline* seam : seams) {
    for (const Vec3& p : seam->points()) curve_gap = std::max(curve_gap, height_gap(p));
  }
  // The u = 1/2 curve stays in the plane x = 1/2 (normals of the flat parent are vertical).
  double drift = 0.0;
  for (const Vec3& p : c[0].surface.boundary().right().points()) drift = std::max(drift, std::abs(p.x() - 0.5));
  std::printf("curved: h %.4g, centre (%.4f %.4f %.4f) gap %.3g = %.2f h, middle curves max gap %.3g = %.2f h, drift %.3g\n", h, centre.x(), centre.y(), centre.z(), centre_gap, centre_gap / h, curve_gap, curve_gap / h, drift);
  assert_true(std::abs(centre.x() - 0.5) <= 1e-12 && std::abs(centre.y() - 0.5) <= 1e-12);
  assert_true(centre_gap <= 0.1 * h);
  // A single projection pass leaves the curves about 1 h below the bump's flanks.
  assert_true(curve_gap <= 0.25 * h);
  assert_true(drift <= 1e-12);

  // Each child starts as the parent surface (flat here) corrected by the Coons blend of its
  // seams' offsets from the parent: its interior follows the lifted seams smoothly instead of
  // jumping from the seam to the parent within one cell. Here the parent is z = 0 and the
  // seams lie on the bump, so every interior node is lifted by the blend of the heights of
  // the four sides, and never above the highest seam point nor below the parent.
  double blend_gap = 0.0, highest_seam = 0.0, lowest_node = 1.0, highest_node = 0.0;
  for (int q = 0; q < 4; ++q) {
    const dbs::Boundary& b = c[q].surface.boundary();
    for (int s = 0; s < 4; ++s)
      for (const Vec3& p : b.side(static_cast<dbs::Side>(s)).points()) highest_seam = std::max(highest_seam, p.z());
    const Grid& g = c[q].grid;
    for (int j = 1; j + 1 < g.nv; ++j) {
      for (int i = 1; i + 1 < g.nu; ++i) {
        const double a = g.u(i), t = g.v(j);
        const double lift = (1 - t) * b.bottom().at(a).z() + t * b.top().at(a).z() + (1 - a) * b.left().at(t).z() + a * b.right().at(t).z() -
                            ((1 - a) * (1 - t) * b.bottom().at(0).z() + a * (1 - t) * b.bottom().at(1).z() + (1 - a) * t * b.top().at(0).z() + a * t * b.top().at(1).z());
        blend_gap = std::max(blend_gap, std::abs(g(i, j).z() - lift));
        lowest_node = std::min(lowest_node, g(i, j).z());
        highest_node = std::max(highest_node, g(i, j).z());
      }
    }
  }
  std::printf("curved: child grids vs parent + seam blend %.3g, node heights [%.3g, %.3g], highest seam %.3g\n", blend_gap, lowest_node, highest_node, highest_seam);
  assert_true(blend_gap <= 1e-12);
  assert_true(lowest_node > 0.0);
  assert_true(highest_node <= highest_seam);
}

void centre_over_a_hole_keeps_the_parent_shape(void**) {
  // The cloud floats 0.05 above the flat parent and has a hole of radius 0.3 around the
  // patch centre: no point carries weight on the centre's ray, so the centre stays S(1/2,1/2)
  // bit for bit, while the middle curves reach the cloud away from the hole.
  std::vector<Vec3> pts;
  for (const Vec3& p : jittered_cloud(2.0, 100, 50, [](double, double) { return 0.05; })) {
    if ((p - Vec3(1.0, 0.5, 0.05)).norm() > 0.3) pts.push_back(p);
  }
  CloudIndex index(pts);
  const double h = cloud_spacing(index);
  DirectedProjector projector(index, h);
  const Patch parent = flat_parent();
  const std::array<Patch, 4> c = subdivide_patch(parent, projector, 0.5, 5);
  assert_true(same_bits(c[0].surface.boundary().corner(1, 1), parent.surface.eval(0.5, 0.5)));
  double worst = 0.0;
  for (const Vec3& p : c[0].surface.boundary().top().points()) {
    if (p.x() > 0.25 && p.x() < 0.55) worst = std::max(worst, std::abs(p.z() - 0.05));
  }
  std::printf("hole: v = 1/2 curve at 0.25 < x < 0.55 off the cloud by %.3g = %.2f h\n", worst, worst / h);
  assert_true(worst <= 0.05 * h);
}

void centre_is_not_pulled_off_the_cloud(void**) {
  // Two dense clumps 0.6 above the flat cloud, half a spacing either side of the normal ray
  // of the patch centre: the ray's weighted mean lies between the sheet and the clumps, in
  // empty space, and a centre moved there would leave the cloud (taking the four children's
  // shared corner with it). It stays on the sheet.
  std::vector<Vec3> pts = jittered_cloud(2.0, 100, 50, [](double, double) { return 0.0; });
  const double h0 = cloud_spacing(CloudIndex(pts));
  for (int k = 0; k < 400; ++k)
    for (double side : {-0.5, 0.5}) pts.emplace_back(1.0 + side * h0, 0.5 + 1e-5 * (k % 11), 0.6 + 1e-5 * (k % 13));
  CloudIndex index(pts);
  const double h = cloud_spacing(index);
  DirectedProjector projector(index, h);
  double t = 0.0;
  assert_true(projector.project(Vec3(1.0, 0.5, 0.0), Vec3(0.0, 0.0, 1.0), t));
  const std::array<Patch, 4> c = subdivide_patch(flat_parent(), projector, 0.5, 5);
  const Vec3 centre = c[0].surface.boundary().corner(1, 1);
  std::printf("clumps by the centre's ray: one projection would lift it %.2f h; the centre is %.3f h off the sheet\n", t / h, std::abs(centre.z()) / h);
  assert_true(t > 3.0 * h);  // the failure the guard is for
  assert_true(std::abs(centre.z()) < 0.5 * h);
}

void grid_below_two_is_rejected(void**) {
  const std::vector<Vec3> pts = jittered_cloud(2.0, 20, 10, [](double, double) { return 0.0; });
  CloudIndex index(pts);
  DirectedProjector projector(index, cloud_spacing(index));
  try {
    subdivide_patch(flat_parent(), projector, 0.5, 1);
    fail_msg("grid 1 accepted");
  } catch (const Error& e) {
    assert_int_equal(static_cast<int>(e.code()), static_cast<int>(ErrorCode::InvalidArgument));
    assert_non_null(std::strstr(e.what(), "grid"));
  }
}

}  // namespace

int main() {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(flat_patch_splits_on_its_midlines),
      cmocka_unit_test(middle_curves_follow_a_curved_cloud),
      cmocka_unit_test(centre_over_a_hole_keeps_the_parent_shape),
      cmocka_unit_test(centre_is_not_pulled_off_the_cloud),
      cmocka_unit_test(grid_below_two_is_rejected),
  };
  return cmocka_run_group_tests(tests, nullptr, nullptr);
}
