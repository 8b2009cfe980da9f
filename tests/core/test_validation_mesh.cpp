// The validation mesh's reference normals (validation_mesh.hpp): a triangle's orientation is
// judged against the cloud's own oriented normal, not the base surface's. A flat cloud with
// (u,v) = (x,y) is mapped without a fold; under a surface pleated over a band of u (its grid's
// middle column pulled back past its neighbour, so Su x Sv turns against the cloud there) the
// mesh must still count no folded triangle, where judging by the surface's normals counted
// every triangle over the band. A real fold of the (u,v) must still count, with the surface
// agreeing or not; triangles without a cloud normal fall back to the surface's; and judged on a
// sample (a large cloud), the other points take their nearest judged point's normal.
#include <cmath>
#include <cstdint>
#include <vector>

#include "analytic_clouds.hpp"
#include "base_surface.hpp"
#include "distortion.hpp"
#include "parameterize.hpp"
#include "point_cloud.hpp"
#include "validation_mesh.hpp"

#include "core_test_support.hpp"

using namespace dbs;

namespace {

dbs_test::Surface plane() {
  return [](double a, double b) { return Vec3(a, b, 0.0); };
}

struct Fixture {
  std::vector<Vec3> points;
  Result result;  // (u,v) = (x,y) exactly: no fold
};

/// 2,500 random points of the unit square, parameterized, then given (u,v) = (x,y).
const Fixture& fixture() {
  static const Fixture f = [] {
    Fixture out;
    out.points = dbs_test::random_points(plane(), 2500, 5);
    out.result = parameterize(PointCloud(out.points), dbs_test::boundary_of(plane(), 20), Options());
    for (std::size_t i = 0; i < out.points.size(); ++i) {
      out.result.u[i] = out.points[i].x();
      out.result.v[i] = out.points[i].y();
    }
    return out;
  }();
  return f;
}

/// The result with its root surface pleated: the 7 x 7 grid's column at u = 0.5 pulled back
/// to x = 0.2, behind the column at u = 1/3, so between them the surface runs backwards in x
/// and its Su x Sv points down.
Result pleated(const Result& r) {
  Result out = r;
  Grid grid(7, 7);
  for (int j = 0; j < 7; ++j)
    for (int i = 0; i < 7; ++i) grid(i, j) = Vec3(grid.u(i), grid.v(j), 0.0);
  for (int j = 1; j < 6; ++j) grid(3, j).x() = 0.2;
  out.patches.erase(out.patches.begin() + 1, out.patches.end());
  out.patches[0].children = {{-1, -1, -1, -1}};
  out.patches[0].surface = BaseSurface(r.patches[0].surface.boundary(), grid);
  return out;
}

std::size_t folded_triangles(const Result& r, const Fixture& f, const std::vector<Triangle>& triangles) {
  return measure_result_distortion(r, PointCloud(f.points), triangles, DomainScaling::PerAxis, 2).summary.folded;
}

/// Triangles under which the surface's normal at the centroid points down.
std::size_t triangles_on_turned_surface(const Result& r, const std::vector<Triangle>& triangles) {
  std::size_t turned = 0;
  for (const Triangle& t : triangles) {
    Vec3 n;
    r.evaluate((r.u[t[0]] + r.u[t[1]] + r.u[t[2]]) / 3.0, (r.v[t[0]] + r.v[t[1]] + r.v[t[2]]) / 3.0, &n);
    if (n.z() < 0.0) ++turned;
  }
  return turned;
}

void a_flat_map_folds_nothing(void**) {
  const Fixture& f = fixture();
  const ValidationMesh mesh = build_validation_mesh(f.result, PointCloud(f.points), 2);
  assert_true(mesh.triangles.size() > 4000);
  assert_int_equal(triangles_on_turned_surface(f.result, mesh.triangles), 0);
  assert_int_equal(measure_distortion(f.points, f.result.u, f.result.v, mesh.triangles, DomainScaling::PerAxis, mesh.reference_normals).summary.folded, 0);
  assert_int_equal(folded_triangles(f.result, f, mesh.triangles), 0);
  // Every reference normal is the cloud's (+z here, the orientation of the (u,v)): the sum of
  // its three vertices' unit normals, about 3 long, where the surface's fallback is 1 long.
  std::size_t from_cloud = 0;
  for (const Vec3& n : mesh.reference_normals)
    if (n.z() > 0.99 * n.norm() && n.norm() > 2.9) ++from_cloud;
  assert_true(from_cloud == mesh.triangles.size());
}

void a_pleated_surface_folds_no_triangle_of_an_ordered_map(void**) {
  const Fixture& f = fixture();
  const Result r = pleated(f.result);
  const ValidationMesh mesh = build_validation_mesh(r, PointCloud(f.points), 2);
  // The pleat is real: the surface turns over under at least a tenth of the triangles
  // (judged by its normals, each of them would count as folded).
  const std::size_t turned = triangles_on_turned_surface(r, mesh.triangles);
  assert_true(turned > mesh.triangles.size() / 10);
  assert_true(turned < mesh.triangles.size() / 2);
  assert_int_equal(measure_distortion(f.points, r.u, r.v, mesh.triangles, DomainScaling::PerAxis, mesh.reference_normals).summary.folded, 0);
  assert_int_equal(folded_triangles(r, f, mesh.triangles), 0);
}

/// A band of the (u,v) mirrored across u = 0.5 (0.4 < x < 0.6): the triangles whose vertices
/// it reversed are folded whatever the surface does there.
void a_real_fold_counts_under_either_surface(void**) {
  const Fixture& f = fixture();
  for (bool pleat : {false, true}) {
    Result r = pleat ? pleated(f.result) : f.result;
    std::size_t moved = 0;
    for (std::size_t i = 0; i < f.points.size(); ++i)
      if (f.points[i].x() > 0.4 && f.points[i].x() < 0.6) r.u[i] = 1.0 - r.u[i], ++moved;
    const ValidationMesh mesh = build_validation_mesh(r, PointCloud(f.points), 2);
    const std::size_t folded = folded_triangles(r, f, mesh.triangles);
    // The mirrored band holds about a fifth of the points, and most of its triangles fold.
    assert_true(moved > 400);
    assert_true(folded > moved / 2);
    assert_true(folded < mesh.triangles.size() / 2);
  }
}

void normals_of_a_point_without_one_come_from_the_surface(void**) {
  const Fixture& f = fixture();
  const Result r = pleated(f.result);
  const std::vector<Vec3> none(f.points.size(), Vec3::Zero());
  const std::vector<Triangle> triangles = {{0, 1, 2}};
  const std::vector<Vec3> n = reference_normals_at(r, none, triangles, 1);
  Vec3 expected;
  r.evaluate((r.u[0] + r.u[1] + r.u[2]) / 3.0, (r.v[0] + r.v[1] + r.v[2]) / 3.0, &expected);
  assert_true((n[0] - expected).norm() < 1e-15);
  const std::vector<Vec3> cloud = oriented_cloud_normals(r, PointCloud(f.points), 2);
  assert_int_equal(cloud.size(), f.points.size());
  const std::vector<Vec3> given = reference_normals_at(r, cloud, triangles, 1);
  assert_true((given[0] - (cloud[0] + cloud[1] + cloud[2])).norm() == 0.0);
  core_test::expect_error([&] { reference_normals_at(r, std::vector<Vec3>(3), triangles, 1); }, ErrorCode::InvalidArgument, {"3 cloud normals", "2500 points"});
}

/// Judged on an even sample (as a cloud above kMaxNormalPoints is), every other point takes
/// the normal of its nearest judged point: on a curved height field, whose normals differ from
/// point to point, so that the wrong neighbour's would show; the map still folds nothing.
void a_sample_of_judged_points_gives_the_others_their_normals(void**) {
  const std::vector<Vec3> points = dbs_test::random_points(dbs_test::height_field(), 2500, 11);
  const PointCloud cloud(points);
  const Result r = parameterize(cloud, dbs_test::boundary_of(dbs_test::height_field(), 40), Options());
  const std::vector<Vec3> all = oriented_cloud_normals(r, cloud, 2);
  const std::vector<Vec3> sampled = oriented_cloud_normals(r, cloud, 2, 500);
  assert_int_equal(sampled.size(), points.size());
  // The judged ones: every fifth point (2,500 / 500), each with the normal of a whole judgement
  // of its sample's own.
  std::vector<std::size_t> judged;
  for (std::size_t i = 0; i < points.size(); i += 5) judged.push_back(i);
  std::size_t differ = 0;
  for (std::size_t i = 0; i < points.size(); ++i) {
    std::size_t nearest = judged[0];
    for (std::size_t j : judged)
      if ((points[j] - points[i]).squaredNorm() < (points[nearest] - points[i]).squaredNorm()) nearest = j;
    assert_true(sampled[i] == sampled[nearest]);
    assert_true(sampled[i].norm() > 0.99 && sampled[i].dot(all[i]) > 0.9);  // near its own normal, the same way round
    if (i % 5 != 0 && sampled[i] != all[i]) ++differ;
  }
  assert_true(differ > points.size() / 2);  // the others' normals are borrowed, not their own
  const ValidationMesh mesh = build_validation_mesh(r, cloud, 2);
  assert_int_equal(measure_distortion(points, r.u, r.v, mesh.triangles, DomainScaling::PerAxis, reference_normals_at(r, sampled, mesh.triangles, 2)).summary.folded, 0);
}

}  // namespace

int main() {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(a_flat_map_folds_nothing),
      cmocka_unit_test(a_pleated_surface_folds_no_triangle_of_an_ordered_map),
      cmocka_unit_test(a_real_fold_counts_under_either_surface),
      cmocka_unit_test(normals_of_a_point_without_one_come_from_the_surface),
      cmocka_unit_test(a_sample_of_judged_points_gives_the_others_their_normals),
  };
  return cmocka_run_group_tests(tests, nullptr, nullptr);
}
