// Distortion between 3D triangles and their (u,v) images: exact values for affine maps of a
// planar grid, the domain scalings, folded and degenerate triangles, argument errors.
#include <cmath>
#include <utility>
#include <vector>

#include <Eigen/Geometry>

#include "distortion.hpp"
#include "error.hpp"
#include "core_test_support.hpp"  // last of the dbs headers

using dbs::DomainScaling;
using dbs::Triangle;
using dbs::Vec3;

namespace {

using core_test::error_code_of;

// An nx x ny grid of the rectangle [0, 3] x [0, 2] tilted out of the plane z = 0 by a
// rotation (distortion does not depend on the 3D placement), two triangles per cell,
// counter-clockwise seen from +normal. Cell (0,0) is cut along (1,0)-(0,1), so corner point 0
// is the vertex of triangle 0 only.
struct PlanarGrid {
  int nx = 9, ny = 7;
  std::vector<double> x, y;  // in-plane coordinates
  std::vector<Vec3> points;
  std::vector<Triangle> triangles;
  Vec3 normal;

  PlanarGrid() {
    const Vec3 ex = Vec3(1, 2, 2).normalized();
    const Vec3 ey = ex.cross(Vec3(0, 0, 1)).normalized();
    normal = ex.cross(ey);
    for (int j = 0; j < ny; ++j) {
      for (int i = 0; i < nx; ++i) {
        x.push_back(3.0 * i / (nx - 1));
        y.push_back(2.0 * j / (ny - 1));
        points.push_back(Vec3(1, -2, 5) + x.back() * ex + y.back() * ey);
      }
    }
    for (int j = 0; j + 1 < ny; ++j) {
      for (int i = 0; i + 1 < nx; ++i) {
        int a = j * nx + i, b = a + 1, c = a + nx, d = c + 1;
        triangles.push_back({a, b, c});
        triangles.push_back({b, d, c});
      }
    }
  }
  // (u,v) = M (x,y) + offset.
  void affine(double m00, double m01, double m10, double m11, std::vector<double>& u, std::vector<double>& v) const {
    u.clear();
    v.clear();
    for (std::size_t i = 0; i < x.size(); ++i) {
      u.push_back(m00 * x[i] + m01 * y[i] + 0.25);
      v.push_back(m10 * x[i] + m11 * y[i] - 0.5);
    }
  }
};

void expect_uniform(const dbs::Distortion& d, double sigma1, double sigma2) {
  for (const dbs::TriangleDistortion& t : d.triangles) {
    assert_false(t.degenerate);
    assert_false(t.folded);
    assert_true(std::abs(t.sigma1 - sigma1) < 1e-12);
    assert_true(std::abs(t.sigma2 - sigma2) < 1e-12);
  }
}

void test_similarity_is_conformal(void**) {
  const PlanarGrid g;
  std::vector<double> u, v;
  const double c = 0.3 * std::cos(0.6), s = 0.3 * std::sin(0.6);
  g.affine(c, -s, s, c, u, v);
  for (DomainScaling scaling : {DomainScaling::Uniform, DomainScaling::PerAxis}) {
    const dbs::Distortion d = dbs::measure_distortion(g.points, u, v, g.triangles, scaling);
    const dbs::DistortionSummary& sum = d.summary;
    assert_int_equal(sum.triangles, g.triangles.size());
    assert_int_equal(sum.folded, 0);
    assert_int_equal(sum.degenerate, 0);
    // the domain is scaled back by 1/0.3 on both axes: the map is an isometry
    assert_true(std::abs(sum.scale_u - 1.0 / 0.3) < 1e-12);
    assert_true(std::abs(sum.scale_v - 1.0 / 0.3) < 1e-12);
    expect_uniform(d, 1.0, 1.0);
    assert_true(std::abs(sum.conformal.max - 1.0) < 1e-12);
    assert_true(std::abs(sum.area.min - 1.0) < 1e-12 && std::abs(sum.area.max - 1.0) < 1e-12);
    assert_true(std::abs(sum.stretch_l2.max - 1.0) < 1e-12);
    assert_true(std::abs(sum.mesh_stretch_l2 - 1.0) < 1e-12);
    assert_true(sum.edge_difference.max < 1e-12);
  }
}

void test_axis_stretch_uniform_scaling(void**) {
  // u = 2x, v = y: areas double, so the domain is scaled by 1/sqrt(2) on both axes and every
  // triangle has singular values sqrt(2) and 1/sqrt(2).
  const PlanarGrid g;
  std::vector<double> u, v;
  g.affine(2, 0, 0, 1, u, v);
  const dbs::Distortion d = dbs::measure_distortion(g.points, u, v, g.triangles, DomainScaling::Uniform);
  const dbs::DistortionSummary& s = d.summary;
  assert_true(std::abs(s.scale_u - std::sqrt(0.5)) < 1e-12);
  assert_true(std::abs(s.scale_v - std::sqrt(0.5)) < 1e-12);
  expect_uniform(d, std::sqrt(2.0), std::sqrt(0.5));
  assert_true(std::abs(s.conformal.mean - 2.0) < 1e-12);
  assert_true(std::abs(s.conformal.p95 - 2.0) < 1e-12);
  assert_true(std::abs(s.area.mean - 1.0) < 1e-12);
  assert_true(std::abs(s.stretch_l2.max - std::sqrt(1.25)) < 1e-12);  // sqrt((1/2 + 2) / 2)
  assert_true(std::abs(s.stretch_linf.max - std::sqrt(2.0)) < 1e-12);
  assert_true(std::abs(s.mesh_stretch_l2 - std::sqrt(1.25)) < 1e-12);
  // x edges grow by sqrt(2), y edges shrink by 1/sqrt(2): the x edges differ most
  assert_true(std::abs(s.edge_difference.max - (std::sqrt(2.0) - 1.0)) < 1e-12);
}

void test_axis_stretch_per_axis_scaling(void**) {
  // The same map: per-axis scaling takes the factor 2 out of u exactly.
  const PlanarGrid g;
  std::vector<double> u, v;
  g.affine(2, 0, 0, 1, u, v);
  const dbs::Distortion d = dbs::measure_distortion(g.points, u, v, g.triangles, DomainScaling::PerAxis);
  assert_true(std::abs(d.summary.scale_u - 0.5) < 1e-12);
  assert_true(std::abs(d.summary.scale_v - 1.0) < 1e-12);
  expect_uniform(d, 1.0, 1.0);
  // A stretch by 2 along the diagonal is no axis scaling: it stays, sigma ratio exactly 2.
  g.affine(1.5, 0.5, 0.5, 1.5, u, v);
  const dbs::Distortion diag = dbs::measure_distortion(g.points, u, v, g.triangles, DomainScaling::PerAxis);
  assert_true(std::abs(diag.summary.scale_u - diag.summary.scale_v) < 1e-12);
  assert_true(std::abs(diag.summary.conformal.min - 2.0) < 1e-12);
  assert_true(std::abs(diag.summary.conformal.max - 2.0) < 1e-12);
  assert_true(std::abs(diag.summary.area.mean - 1.0) < 1e-12);
}

void test_one_flipped_triangle(void**) {
  // Corner point 0 belongs to triangle 0 only; moving its (u,v) across the opposite edge
  // (the line x + y = h of the first cell, in the scaled domain) flips exactly that triangle.
  const PlanarGrid g;
  std::vector<double> u, v;
  g.affine(1, 0, 0, 1, u, v);
  const double hx = 3.0 / (g.nx - 1), hy = 2.0 / (g.ny - 1);
  u[0] = 0.25 + 0.8 * hx;
  v[0] = -0.5 + 0.8 * hy;
  for (int with_normals = 0; with_normals < 2; ++with_normals) {
    std::vector<Vec3> normals;
    if (with_normals) normals.assign(g.triangles.size(), g.normal);
    const dbs::Distortion d = dbs::measure_distortion(g.points, u, v, g.triangles, DomainScaling::Uniform, normals);
    assert_int_equal(d.summary.folded, 1);
    assert_true(d.triangles[0].folded);
    for (std::size_t t = 1; t < d.triangles.size(); ++t) assert_false(d.triangles[t].folded);
    assert_int_equal(d.summary.degenerate, 0);
  }
}

void test_reversed_triangle_and_reference_normals(void**) {
  // Reversing a triangle's vertex order reverses its (u,v) orientation and its 3D normal:
  // by (u,v) alone it looks folded, against reference normals it is not.
  PlanarGrid g;
  std::swap(g.triangles[10][1], g.triangles[10][2]);
  std::vector<double> u, v;
  g.affine(1, 0.2, -0.1, 1, u, v);
  const dbs::Distortion plain = dbs::measure_distortion(g.points, u, v, g.triangles, DomainScaling::Uniform);
  assert_int_equal(plain.summary.folded, 1);
  assert_true(plain.triangles[10].folded);
  const std::vector<Vec3> normals(g.triangles.size(), g.normal);
  const dbs::Distortion judged = dbs::measure_distortion(g.points, u, v, g.triangles, DomainScaling::Uniform, normals);
  assert_int_equal(judged.summary.folded, 0);
  // The whole mesh reversed: the majority decides, nothing is folded.
  for (Triangle& t : g.triangles) std::swap(t[1], t[2]);
  const dbs::Distortion reversed = dbs::measure_distortion(g.points, u, v, g.triangles, DomainScaling::Uniform);
  assert_int_equal(reversed.summary.folded, 1);  // triangle 10, now the odd one out
  assert_true(reversed.triangles[10].folded);
}

void test_degenerate_triangles(void**) {
  PlanarGrid g;
  std::vector<double> u, v;
  g.affine(1, 0, 0, 1, u, v);
  // triangle 0 = (0, 1, nx): put point 0's (u,v) on the line through points 1 and nx
  u[0] = 0.5 * (u[1] + u[g.nx]);
  v[0] = 0.5 * (v[1] + v[g.nx]);
  // and a triangle that is flat in 3D: three points of the first row
  g.triangles.push_back({2, 3, 4});
  const dbs::Distortion d = dbs::measure_distortion(g.points, u, v, g.triangles, DomainScaling::Uniform);
  assert_int_equal(d.summary.degenerate, 2);
  assert_true(d.triangles[0].degenerate);
  assert_true(d.triangles.back().degenerate);
  assert_int_equal(d.summary.folded, 0);
  // the other triangles are untouched isometries; the degenerate ones are in no summary
  assert_true(std::abs(d.summary.conformal.max - 1.0) < 1e-12);
}

void test_errors(void**) {
  const PlanarGrid g;
  std::vector<double> u, v;
  g.affine(1, 0, 0, 1, u, v);
  std::vector<Triangle> bad = g.triangles;
  bad[3][2] = static_cast<std::int32_t>(g.points.size());
  assert_int_equal(error_code_of([&] { dbs::measure_distortion(g.points, u, v, bad, DomainScaling::Uniform); }), dbs::ErrorCode::OutOfRange);
  bad[3][2] = -1;
  assert_int_equal(error_code_of([&] { dbs::measure_distortion(g.points, u, v, bad, DomainScaling::Uniform); }), dbs::ErrorCode::OutOfRange);
  std::vector<double> short_u(u.begin(), u.end() - 1);
  assert_int_equal(error_code_of([&] { dbs::measure_distortion(g.points, short_u, v, g.triangles, DomainScaling::Uniform); }), dbs::ErrorCode::InvalidArgument);
  const std::vector<Vec3> normals(2, g.normal);
  assert_int_equal(error_code_of([&] { dbs::measure_distortion(g.points, u, v, g.triangles, DomainScaling::Uniform, normals); }), dbs::ErrorCode::InvalidArgument);
  std::vector<double> nan_u = u;
  nan_u[5] = std::nan("");
  assert_int_equal(error_code_of([&] { dbs::measure_distortion(g.points, nan_u, v, g.triangles, DomainScaling::Uniform); }), dbs::ErrorCode::NonFinite);
  // no triangles: an empty, all-zero summary
  const dbs::Distortion none = dbs::measure_distortion(g.points, u, v, {}, DomainScaling::PerAxis);
  assert_int_equal(none.summary.triangles, 0);
  assert_true(none.summary.conformal.max == 0.0);
}

}  // namespace

int main() {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(test_similarity_is_conformal),
      cmocka_unit_test(test_axis_stretch_uniform_scaling),
      cmocka_unit_test(test_axis_stretch_per_axis_scaling),
      cmocka_unit_test(test_one_flipped_triangle),
      cmocka_unit_test(test_reversed_triangle_and_reference_normals),
      cmocka_unit_test(test_degenerate_triangles),
      cmocka_unit_test(test_errors),
  };
  return cmocka_run_group_tests(tests, nullptr, nullptr);
}
