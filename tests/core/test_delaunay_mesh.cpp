// Delaunay triangulation of the parameters and suspicious (bridging) triangles: coverage,
// orientation, the empty-circle property, duplicates, degenerate input, and the suspicious
// count of a good against a scrambled parameterization.
#include <algorithm>
#include <cmath>
#include <numeric>
#include <random>
#include <set>
#include <vector>

#include "cloud_index.hpp"
#include "delaunay_mesh.hpp"
#include "error.hpp"
#include "suspicious_triangles.hpp"
#include "core_test_support.hpp"  // last of the dbs headers

using dbs::Triangle;
using dbs::Vec3;

namespace {

using core_test::error_code_of;

double signed_area(const std::vector<double>& u, const std::vector<double>& v, const Triangle& t) {
  return 0.5 * ((u[t[1]] - u[t[0]]) * (v[t[2]] - v[t[0]]) - (v[t[1]] - v[t[0]]) * (u[t[2]] - u[t[0]]));
}

// Random (u,v) in the unit square plus its four corners, so the hull is the square.
void random_square(std::size_t n, unsigned seed, std::vector<double>& u, std::vector<double>& v) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  u = {0, 1, 0, 1};
  v = {0, 0, 1, 1};
  for (std::size_t i = 0; i < n; ++i) {
    u.push_back(unit(rng));
    v.push_back(unit(rng));
  }
}

void test_grid_exact(void**) {
  // A regular grid: every cell's four corners are cocircular, the worst case for Delaunay.
  const int nx = 21, ny = 13;
  std::vector<double> u, v;
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      u.push_back(static_cast<double>(i) / (nx - 1));
      v.push_back(static_cast<double>(j) / (ny - 1));
    }
  const std::vector<Triangle> tris = dbs::delaunay_triangulate(u, v);
  assert_int_equal(tris.size(), 2 * (nx - 1) * (ny - 1));
  double area = 0.0;
  const double cell = 1.0 / ((nx - 1) * (ny - 1));
  std::set<std::int32_t> used;
  for (const Triangle& t : tris) {
    const double a = signed_area(u, v, t);
    assert_true(std::abs(a - 0.5 * cell) < 1e-12);  // half a cell each, counter-clockwise
    area += a;
    used.insert(t.begin(), t.end());
  }
  assert_true(std::abs(area - 1.0) < 1e-12);
  assert_int_equal(used.size(), u.size());
}

void test_random_is_delaunay(void**) {
  std::vector<double> u, v;
  random_square(400, 7, u, v);
  const std::vector<Triangle> tris = dbs::delaunay_triangulate(u, v);
  // Euler: 2n - 2 - hull vertices (the 4 corners; random points are never on the sides)
  assert_int_equal(tris.size(), 2 * u.size() - 2 - 4);
  double area = 0.0;
  for (const Triangle& t : tris) {
    assert_true(signed_area(u, v, t) > 0.0);
    area += signed_area(u, v, t);
    // empty circumcircle: no point strictly inside (in-circle determinant, scaled tolerance)
    for (std::size_t p = 0; p < u.size(); ++p) {
      if (static_cast<std::int32_t>(p) == t[0] || static_cast<std::int32_t>(p) == t[1] || static_cast<std::int32_t>(p) == t[2]) continue;
      double m[3][3];
      for (int k = 0; k < 3; ++k) {
        const double du = u[t[k]] - u[p], dv = v[t[k]] - v[p];
        m[k][0] = du;
        m[k][1] = dv;
        m[k][2] = du * du + dv * dv;
      }
      const double det = m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) + m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
      assert_true(det < 1e-12);
    }
  }
  assert_true(std::abs(area - 1.0) < 1e-12);
}

void test_duplicates_are_left_out(void**) {
  std::vector<double> u, v;
  random_square(200, 11, u, v);
  const std::size_t distinct = u.size();
  for (std::size_t i = 0; i < 30; ++i) {  // 30 exact copies of existing points
    u.push_back(u[i * 5]);
    v.push_back(v[i * 5]);
  }
  const std::vector<Triangle> tris = dbs::delaunay_triangulate(u, v);
  assert_int_equal(tris.size(), 2 * distinct - 2 - 4);
  std::set<std::int32_t> used;
  double area = 0.0;
  for (const Triangle& t : tris) {
    used.insert(t.begin(), t.end());
    area += signed_area(u, v, t);
  }
  assert_int_equal(used.size(), distinct);  // one index per distinct (u,v)
  assert_true(std::abs(area - 1.0) < 1e-12);
}

void test_degenerate_input(void**) {
  std::vector<double> u{0, 0.25, 0.5, 1.0}, v{0, 0.5, 1.0, 2.0};  // one line
  assert_int_equal(error_code_of([&] { dbs::delaunay_triangulate(u, v); }), dbs::ErrorCode::Degenerate);
  std::vector<double> two_u{0, 1, 1, 0}, two_v{0, 1, 1, 0};  // two distinct points
  assert_int_equal(error_code_of([&] { dbs::delaunay_triangulate(two_u, two_v); }), dbs::ErrorCode::Degenerate);
  std::vector<double> few{0, 1};
  assert_int_equal(error_code_of([&] { dbs::delaunay_triangulate(few, few); }), dbs::ErrorCode::Degenerate);
  std::vector<double> three_u{0, 1, 0}, three_v{0, 0, 1};
  assert_int_equal(dbs::delaunay_triangulate(three_u, three_v).size(), 1);
  std::vector<double> nan_u{0, 1, 0, std::nan("")}, ok_v{0, 0, 1, 1};
  assert_int_equal(error_code_of([&] { dbs::delaunay_triangulate(nan_u, ok_v); }), dbs::ErrorCode::NonFinite);
  assert_int_equal(error_code_of([&] { dbs::delaunay_triangulate(three_u, ok_v); }), dbs::ErrorCode::InvalidArgument);
}

// Points of a curved sheet z = 0.3 sin(3x) cos(2y) over random (x,y) and over its four
// sides at about the same spacing (as a scan reaches its boundary curves); its true
// parameters. Without the side points the hull would be the four corners and the triangles
// along the sides long slivers, rightly suspicious.
void curved_sheet(std::size_t n, std::vector<Vec3>& points, std::vector<double>& u, std::vector<double>& v) {
  random_square(n, 3, u, v);
  const int per_side = static_cast<int>(std::sqrt(static_cast<double>(n)));
  for (int k = 1; k < per_side; ++k) {
    const double s = static_cast<double>(k) / per_side;
    const double side_u[4] = {s, 1.0, s, 0.0}, side_v[4] = {0.0, s, 1.0, s};
    for (int side = 0; side < 4; ++side) {
      u.push_back(side_u[side]);
      v.push_back(side_v[side]);
    }
  }
  points.clear();
  for (std::size_t i = 0; i < u.size(); ++i) points.emplace_back(u[i], v[i], 0.3 * std::sin(3 * u[i]) * std::cos(2 * v[i]));
}

void test_good_mesh_has_no_suspicious_triangles(void**) {
  std::vector<Vec3> points;
  std::vector<double> u, v;
  curved_sheet(5000, points, u, v);
  const dbs::CloudIndex index(points);
  const std::vector<double> spacing = dbs::local_spacing(index, 2);
  for (double s : spacing) assert_true(s > 0.0);
  const std::vector<Triangle> tris = dbs::delaunay_triangulate(u, v);
  assert_int_equal(dbs::find_suspicious_triangles(points, tris, spacing).size(), 0);
  // a regular grid too: its spacing is exact, its diagonals sqrt(2) cells long
  std::vector<Vec3> grid;
  std::vector<double> gu, gv;
  for (int j = 0; j < 30; ++j)
    for (int i = 0; i < 30; ++i) {
      gu.push_back(i / 29.0);
      gv.push_back(j / 29.0);
      grid.emplace_back(2.0 * gu.back(), 2.0 * gv.back(), 0.0);
    }
  const dbs::CloudIndex grid_index(grid);
  const std::vector<double> grid_spacing = dbs::local_spacing(grid_index, 1);
  // the 6th nearest neighbour of an interior grid point is a diagonal one
  assert_true(std::abs(grid_spacing[15 * 30 + 15] - std::sqrt(2.0) * 2.0 / 29.0) < 1e-12);
  assert_int_equal(dbs::find_suspicious_triangles(grid, dbs::delaunay_triangulate(gu, gv), grid_spacing).size(), 0);
}

void test_scrambled_mesh_is_mostly_suspicious(void**) {
  std::vector<Vec3> points;
  std::vector<double> u, v;
  curved_sheet(5000, points, u, v);
  // give every point the parameters of another: the triangulation then bridges the sheet
  std::vector<std::size_t> perm(u.size());
  std::iota(perm.begin(), perm.end(), 0);
  std::shuffle(perm.begin(), perm.end(), std::mt19937_64(5));
  std::vector<double> su(u.size()), sv(v.size());
  for (std::size_t i = 0; i < u.size(); ++i) {
    su[i] = u[perm[i]];
    sv[i] = v[perm[i]];
  }
  const dbs::CloudIndex index(points);
  const std::vector<Triangle> tris = dbs::delaunay_triangulate(su, sv);
  const std::vector<std::size_t> suspicious = dbs::find_suspicious_triangles(points, tris, dbs::local_spacing(index, 2));
  assert_true(suspicious.size() > 0.3 * tris.size());
  assert_true(std::is_sorted(suspicious.begin(), suspicious.end()));
  // one bridge made by hand in the good mesh: exactly the triangles using the moved point
  std::vector<double> bu = u, bv = v;
  const std::vector<Triangle> good = dbs::delaunay_triangulate(u, v);
  bu[100] = u[200];
  bv[100] = v[200] + 1e-4;  // point 100 now sits, in (u,v), right next to point 200
  const std::vector<Triangle> bridged = dbs::delaunay_triangulate(bu, bv);
  const std::vector<std::size_t> found = dbs::find_suspicious_triangles(points, bridged, dbs::local_spacing(index, 2));
  assert_true(!found.empty());
  for (std::size_t t : found) {
    const Triangle& tri = bridged[t];
    assert_true(tri[0] == 100 || tri[1] == 100 || tri[2] == 100);
  }
}

void test_suspicious_errors(void**) {
  const std::vector<Vec3> points{Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)};
  const std::vector<double> spacing{1, 1, 1};
  const std::vector<Triangle> bad{{0, 1, 3}};
  assert_int_equal(error_code_of([&] { dbs::find_suspicious_triangles(points, bad, spacing); }), dbs::ErrorCode::OutOfRange);
  const std::vector<double> short_spacing{1, 1};
  assert_int_equal(error_code_of([&] { dbs::find_suspicious_triangles(points, {{0, 1, 2}}, short_spacing); }), dbs::ErrorCode::InvalidArgument);
}

}  // namespace

int main() {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(test_grid_exact),
      cmocka_unit_test(test_random_is_delaunay),
      cmocka_unit_test(test_duplicates_are_left_out),
      cmocka_unit_test(test_degenerate_input),
      cmocka_unit_test(test_good_mesh_has_no_suspicious_triangles),
      cmocka_unit_test(test_scrambled_mesh_is_mostly_suspicious),
      cmocka_unit_test(test_suspicious_errors),
  };
  return cmocka_run_group_tests(tests, nullptr, nullptr);
}
