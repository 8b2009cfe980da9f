// The meshless seed of the root surface (meshless_seed.hpp): on a sphere cap of 330 degrees,
// which no evolution from the Coons patch of its small rim wraps, the seeded surface lies on
// the cloud; the boundary stays exactly; too few points or a boundary off the cloud leave the
// patch untouched; the seed
// does not depend on anything but its input.
#include <cmath>
#include <cstdio>
#include <vector>

#include "boundary.hpp"
#include "fold_shapes.hpp"
#include "meshless_seed.hpp"
#include "patch.hpp"
#include "surface_projection.hpp"
#include "work_meter.hpp"
#include "core_test_support.hpp"  // last of the dbs headers

using namespace dbs;

namespace {

std::vector<Vec3> points_of(const std::vector<double>& xyz) {
  std::vector<Vec3> p;
  for (std::size_t i = 0; i + 2 < xyz.size(); i += 3) p.emplace_back(xyz[i], xyz[i + 1], xyz[i + 2]);
  return p;
}

struct Cap {
  std::vector<Vec3> points;
  Patch root;
};

Cap cap_of(const dbs_folds::FoldShape& shape) {
  Cap c{points_of(shape.xyz), Patch{BaseSurface(Boundary(points_of(shape.bottom), points_of(shape.right), points_of(shape.top), points_of(shape.left)))}};
  c.root.rect = Rect{0.0, 0.0, 1.0, 1.0};
  for (std::size_t i = 0; i < c.points.size(); ++i) c.root.subcloud.push_back(i);
  return c;
}

Cap cap(double degrees) { return cap_of(dbs_folds::sphere_cap(0.0, degrees)); }

double mean_distance(const BaseSurface& surface, const std::vector<Vec3>& points) {
  const SurfaceProjector projector(surface);
  double sum = 0.0;
  for (const Vec3& q : points) sum += projector.project(q).distance;
  return sum / static_cast<double>(points.size());
}

void seed_wraps_a_cap_closing_over_a_small_rim(void**) {
  // The driver seeds the root's first grid (5 x 5), which follows a sphere only coarsely; an
  // 11 x 11 seed lies on it.
  Cap c = cap(330.0), fine = cap(330.0);
  const double coons = mean_distance(c.root.surface, c.points);
  assert_true(seed_from_meshless_map(c.root, c.points, 5));
  assert_true(seed_from_meshless_map(fine.root, fine.points, 11));
  const double seeded = mean_distance(c.root.surface, c.points), seeded_fine = mean_distance(fine.root.surface, fine.points);
  std::printf("330-degree cap: mean distance %.3g from the Coons patch, %.3g from the seed (5 x 5), %.3g (11 x 11)\n", coons, seeded, seeded_fine);
  assert_true(coons > 0.5);
  assert_true(seeded < 0.1);
  assert_true(seeded_fine < 0.01);
  assert_int_equal(c.root.grid.nu, 5);
  assert_int_equal(c.root.grid.nv, 5);
  // The boundary is the patch's: the surface interpolates it exactly.
  const Boundary& b = c.root.surface.boundary();
  for (double s : {0.0, 0.3, 1.0}) {
    assert_true(c.root.surface.eval(s, 0.0) == b.bottom().at(s));
    assert_true(c.root.surface.eval(0.0, s) == b.left().at(s));
  }
}

void seed_wraps_a_noisy_cap(void**) {
  // The 330-degree cap at 8,281 points with noise along the normal of 0.5% of its diagonal
  // (sigma 0.017, half the sample's spacing): the plane the border test fits to the points
  // near the rim must stand above the noise. Fitted to the 12 nearest, a median third of
  // them fell beyond the rim and the seed was refused as if the boundary crossed the cloud;
  // the root then never wrapped the cap (the run's mean distance 0.153, 234 folded reference
  // triangles, against 0.0158 and 14 seeded).
  const dbs_folds::FoldShape shape = dbs_folds::fold_shape("sphere-cap-330", 2.0, 0.005);
  Cap c = cap_of(shape);
  assert_true(seed_from_meshless_map(c.root, c.points, 11));
  const double seeded = mean_distance(c.root.surface, c.points);
  std::printf("noisy 330-degree cap (sigma %.3g): mean distance %.3g from the 11 x 11 seed\n", shape.noise_sigma, seeded);
  assert_true(seeded < 2.0 * shape.noise_sigma);
}

void detached_clump_and_duplicates_are_left_out(void**) {
  // A clump of 40 coincident points far inside the cap, each only the others' neighbour: no
  // path to the boundary, so no (u,v) for it; its points must neither fail the seed nor pull
  // the surface (a singular block solved anyway would put them all at one (u,v)). Every
  // cloud point doubled as well: coincident neighbours weigh as near ones. (The doubled cloud
  // is sampled, about one point in two: 0.0073 against 0.0046 from every point. With a stride
  // of 2 over the points stored row by row, the sample took every other point of each row
  // and the seed fitted 5 times worse, 0.025.)
  Cap plain = cap(300.0), odd = cap(300.0);
  const std::size_t n = odd.points.size();
  for (std::size_t i = 0; i < n; ++i) odd.points.push_back(odd.points[i]);
  for (int k = 0; k < 40; ++k) odd.points.emplace_back(0.0, 0.0, 0.2);  // inside the sphere
  odd.root.subcloud.clear();
  for (std::size_t i = 0; i < odd.points.size(); ++i) odd.root.subcloud.push_back(i);
  assert_true(seed_from_meshless_map(plain.root, plain.points, 11));
  assert_true(seed_from_meshless_map(odd.root, odd.points, 11));
  const double a = mean_distance(plain.root.surface, plain.points), b = mean_distance(odd.root.surface, plain.points);
  std::printf("300-degree cap seed: mean distance %.3g, with every point doubled and a detached clump %.3g\n", a, b);
  assert_true(a < 0.01);
  assert_true(b < 2.0 * a);
}

/// A jittered 0.02-pitch grid over [lo, hi]^2 in z = 0, and the patch of the unit square.
Cap square_cloud(double lo, double hi) {
  std::vector<Vec3> sides[4];
  for (int k = 0; k <= 10; ++k) {
    const double t = k / 10.0;
    sides[0].emplace_back(t, 0.0, 0.0);
    sides[1].emplace_back(1.0, t, 0.0);
    sides[2].emplace_back(t, 1.0, 0.0);
    sides[3].emplace_back(0.0, t, 0.0);
  }
  Cap c{{}, Patch{BaseSurface(Boundary(sides[0], sides[1], sides[2], sides[3]))}};
  c.root.rect = Rect{0.0, 0.0, 1.0, 1.0};
  const int count = static_cast<int>(std::lround((hi - lo) / 0.02));
  for (int j = 0; j <= count; ++j)
    for (int i = 0; i <= count; ++i) c.points.emplace_back(lo + 0.02 * i + 0.003 * std::sin(7.0 * j + i), lo + 0.02 * j + 0.003 * std::cos(5.0 * i + j), 0.0);
  for (std::size_t i = 0; i < c.points.size(); ++i) c.root.subcloud.push_back(i);
  return c;
}

void boundary_must_be_the_cloud_border(void**) {
  // The unit square's sides on a plane cloud that ends there: seeded (on the plane). The
  // same sides inside a cloud twice as wide: about half of the points near each side lie
  // beyond it, which a map fixed on the boundary cannot place: refused.
  Cap border = square_cloud(0.0, 1.0), across = square_cloud(-0.5, 1.5);
  assert_true(seed_from_meshless_map(border.root, border.points, 5));
  assert_true(mean_distance(border.root.surface, border.points) < 1e-3);  // jittered up to 0.003 beyond the sides
  const Vec3 middle = across.root.surface.eval(0.5, 0.5);
  assert_false(seed_from_meshless_map(across.root, across.points, 5));
  assert_true(across.root.surface.eval(0.5, 0.5) == middle);
}

void seed_reports_its_work_and_can_be_cancelled(void**) {
  // Every sample point and boundary position counts a unit; a report that cancels (the
  // host's progress callback returned true) stops the seed, the patch untouched.
  Cap c = cap(330.0);
  WorkMeter counting(1u << 30);
  assert_true(seed_from_meshless_map(c.root, c.points, 5, &counting));
  assert_true(counting.done() >= c.points.size());
  Cap d = cap(330.0);
  const Vec3 middle = d.root.surface.eval(0.5, 0.5);
  WorkMeter cancelling(256);
  cancelling.set_report([] { throw Error(ErrorCode::Cancelled, "cancelled by the test"); });
  // Reports are made inside the meter's loop (as the driver's evolution runs the root).
  assert_true(core_test::throws(ErrorCode::Cancelled, [&] { cancelling.run(1, 1, [&](std::size_t) { seed_from_meshless_map(d.root, d.points, 5, &cancelling); }); }));
  assert_true(d.root.surface.eval(0.5, 0.5) == middle);
}

void coincident_points_give_no_seed(void**) {
  Cap c = cap(270.0);
  const Vec3 one = c.points[100];
  for (Vec3& q : c.points) q = one;
  const Vec3 middle = c.root.surface.eval(0.5, 0.5);
  assert_false(seed_from_meshless_map(c.root, c.points, 5));
  assert_true(c.root.surface.eval(0.5, 0.5) == middle);
}

void too_few_points_leave_the_patch_untouched(void**) {
  Cap c = cap(270.0);
  c.root.subcloud.resize(20);
  c.root.grid = c.root.surface.sample(4, 4);
  const Grid before = c.root.grid;
  const Vec3 middle = c.root.surface.eval(0.5, 0.5);
  assert_false(seed_from_meshless_map(c.root, c.points, 5));
  assert_int_equal(c.root.grid.nu, 4);
  for (int j = 0; j < 4; ++j)
    for (int i = 0; i < 4; ++i) assert_true(c.root.grid(i, j) == before(i, j));
  assert_true(c.root.surface.eval(0.5, 0.5) == middle);
  // A boundary off its cloud gives the map no boundary points to fix: refused (a cloud moved
  // 3 units, 100 spacings, away from its rim).
  Cap moved = cap(270.0);
  for (Vec3& q : moved.points) q.z() += 3.0;
  assert_false(seed_from_meshless_map(moved.root, moved.points, 5));
  // A grid below 3 x 3 has no interior node to fit.
  Cap d = cap(270.0);
  assert_false(seed_from_meshless_map(d.root, d.points, 2));
}

}  // namespace

int main() {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(seed_wraps_a_cap_closing_over_a_small_rim),
      cmocka_unit_test(seed_wraps_a_noisy_cap),
      cmocka_unit_test(detached_clump_and_duplicates_are_left_out),
      cmocka_unit_test(boundary_must_be_the_cloud_border),
      cmocka_unit_test(seed_reports_its_work_and_can_be_cancelled),
      cmocka_unit_test(coincident_points_give_no_seed),
      cmocka_unit_test(too_few_points_leave_the_patch_untouched),
  };
  return cmocka_run_group_tests_name("meshless_seed", tests, nullptr, nullptr);
}
