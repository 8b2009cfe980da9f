// The nearest point of a structured grid: the same index as brute force (least squared
// distance, the lowest index among equals) on wavy and folded grids of many sizes, odd ones
// and single rows included, for queries near, far and exactly between points; refuses a size
// that does not match its points.
#include <algorithm>
#include <cmath>
#include <random>
#include <string>

#include "error.hpp"
#include "grid_nearest.hpp"

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

/// Brute force: least squared distance, the lowest index among equals.
std::size_t brute_nearest(const std::vector<Vec3>& pts, const Vec3& q) {
  std::size_t best = 0;
  double best2 = (pts[0] - q).squaredNorm();
  for (std::size_t k = 1; k < pts.size(); ++k) {
    const double d2 = (pts[k] - q).squaredNorm();
    if (d2 < best2) best2 = d2, best = k;
  }
  return best;
}

/// A nu x nv grid (u fastest) of a surface that waves and, with `fold`, turns back over
/// itself (a sheet lying over another: points far apart in the grid are near in space).
std::vector<Vec3> surface_grid(int nu, int nv, bool fold) {
  std::vector<Vec3> pts;
  for (int j = 0; j < nv; ++j)
    for (int i = 0; i < nu; ++i) {
      const double u = nu > 1 ? static_cast<double>(i) / (nu - 1) : 0.5, v = nv > 1 ? static_cast<double>(j) / (nv - 1) : 0.5;
      if (fold) pts.emplace_back(std::cos(5.0 * u), std::sin(5.0 * u) * 0.3 + 0.05 * v, v);
      else pts.emplace_back(u, v, 0.1 * std::sin(7.0 * u) * std::cos(5.0 * v));
    }
  return pts;
}

void matches_brute_force_on_many_grids(void**) {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> unit(-1.5, 1.5);
  std::size_t queries = 0;
  for (int nu : {1, 2, 3, 5, 8, 17, 64})
    for (int nv : {1, 4, 7, 33, 64})
      for (bool fold : {false, true}) {
        const std::vector<Vec3> pts = surface_grid(nu, nv, fold);
        const GridNearest tree(pts, nu, nv);
        for (int t = 0; t < 200; ++t) {
          // Far, near the surface, and exactly on a point.
          Vec3 q(unit(rng), unit(rng), unit(rng));
          if (t % 3 == 1) q = pts[static_cast<std::size_t>(rng() % pts.size())] + 0.01 * Vec3(unit(rng), unit(rng), unit(rng));
          if (t % 3 == 2) q = pts[static_cast<std::size_t>(rng() % pts.size())];
          assert_int_equal(tree.nearest(q), brute_nearest(pts, q));
          ++queries;
        }
      }
  assert_int_equal(queries, 7 * 5 * 2 * 200);
}

void ties_go_to_the_lowest_index(void**) {
  // A flat grid and queries exactly between points: 2 and 4 points at one distance.
  const int n = 64;
  std::vector<Vec3> pts;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) pts.emplace_back(i, j, 0.0);
  const GridNearest tree(pts, n, n);
  for (int j = 0; j + 1 < n; j += 5)
    for (int i = 0; i + 1 < n; i += 3) {
      assert_int_equal(tree.nearest(Vec3(i + 0.5, j + 0.5, 1.0)), static_cast<std::size_t>(j) * n + i);
      assert_int_equal(tree.nearest(Vec3(i + 0.5, j, 2.0)), static_cast<std::size_t>(j) * n + i);
      assert_int_equal(tree.nearest(Vec3(i, j + 0.5, 0.0)), static_cast<std::size_t>(j) * n + i);
    }
  // The lower index in a block whose box touches the answer's sphere only at that point,
  // searched after the block holding the query (and the higher index): it is still taken.
  const std::vector<Vec3> row{{0, 0, 0}, {-1, 0, 0}, {-2, 0, 0}, {1, 0, 0}, {3, 0, 0}, {2, 5, 0}, {2, -5, 0}, {2.5, 4, 0}};
  assert_int_equal(GridNearest(row, 8, 1).nearest(Vec3(2, 0, 0)), 3u);
  // Every point in one place: the first.
  const std::vector<Vec3> same(12, Vec3(1.0, 2.0, 3.0));
  assert_int_equal(GridNearest(same, 3, 4).nearest(Vec3::Zero()), 0u);
}

void refuses_a_size_that_does_not_match(void**) {
  const std::vector<Vec3> pts = surface_grid(4, 5, false);
  for (auto [nu, nv] : {std::pair<int, int>{5, 5}, {0, 20}, {20, 0}, {-4, -5}}) {
    bool thrown = false;
    try {
      GridNearest bad(pts, nu, nv);
    } catch (const Error& e) {
      thrown = e.code() == ErrorCode::InvalidArgument && std::string(e.what()).find("20 points for a " + std::to_string(nu) + " x " + std::to_string(nv)) != std::string::npos;
    }
    assert_true(thrown);
  }
}

}  // namespace

int main() {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(matches_brute_force_on_many_grids),
      cmocka_unit_test(ties_go_to_the_lowest_index),
      cmocka_unit_test(refuses_a_size_that_does_not_match),
  };
  return cmocka_run_group_tests(tests, nullptr, nullptr);
}
