// The pleat guard on its own: a move that keeps every cell's orientation passes unchanged; a
// move that would fold a cell over its neighbour is damped until no cell turns, and only the
// offending interior nodes are held back; a NaN offset is withdrawn; sizes are checked.
#include <cmath>
#include <limits>
#include <vector>

#include <Eigen/Geometry>

#include "grid.hpp"
#include "pleat_guard.hpp"

#include "core_test_support.hpp"

namespace {

using dbs::Grid;
using dbs::Vec3;

/// A flat n x n grid on [0,1]^2 (z = 0) with every direction +z.
void flat(int n, Grid& grid, Grid& directions) {
  grid = Grid(n, n);
  directions = Grid(n, n);
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      grid(i, j) = Vec3(grid.u(i), grid.v(j), 0.0);
      directions(i, j) = Vec3(0.0, 0.0, 1.0);
    }
}

/// Smallest cosine between a moved cell's triangle normals and +z over the whole grid.
double worst_cosine(const Grid& g) {
  double worst = 1.0;
  for (int j = 0; j + 1 < g.nv; ++j)
    for (int i = 0; i + 1 < g.nu; ++i) {
      const Vec3 a = g(i, j), b = g(i + 1, j), c = g(i + 1, j + 1), d = g(i, j + 1);
      for (const Vec3& t : {Vec3((b - a).cross(c - a)), Vec3((c - a).cross(d - a)), Vec3((b - a).cross(d - a)), Vec3((c - b).cross(d - b))})
        worst = std::min(worst, t.z() / t.norm());
    }
  return worst;
}

void orientation_keeping_move_passes(void**) {
  Grid grid, directions;
  flat(7, grid, directions);
  std::vector<double> offsets(grid.points.size());
  for (std::size_t k = 0; k < offsets.size(); ++k) offsets[k] = 0.05 * std::sin(3.0 * static_cast<double>(k));  // a gentle bumpy lift
  const dbs::GuardedMove move = dbs::move_without_pleats(grid, directions, offsets);
  assert_int_equal(move.damped_nodes, 0);
  for (int j = 0; j < 7; ++j)
    for (int i = 0; i < 7; ++i) {
      const bool border = i == 0 || j == 0 || i == 6 || j == 6;
      const double expected = border ? 0.0 : offsets[static_cast<std::size_t>(j) * 7 + i];
      assert_true(move.grid(i, j).z() == expected);
    }
}

void folding_move_is_damped(void**) {
  Grid grid, directions;
  flat(7, grid, directions);
  // Node (3,3) leans towards +x and moves far: unguarded, it passes its neighbour (4,3) and
  // the cells between them turn over.
  directions(3, 3) = Vec3(1.0, 0.0, 0.2).normalized();
  std::vector<double> offsets(grid.points.size(), 0.0);
  offsets[3 * 7 + 3] = 0.5;
  Grid unguarded = grid;
  unguarded(3, 3) += offsets[3 * 7 + 3] * directions(3, 3);
  assert_true(worst_cosine(unguarded) < 0.0);

  const dbs::GuardedMove move = dbs::move_without_pleats(grid, directions, offsets);
  assert_int_equal(move.damped_nodes, 1);  // the node itself, and no border node
  assert_true(worst_cosine(move.grid) >= 0.02);
  const double moved = (move.grid(3, 3) - grid(3, 3)).norm();
  assert_true(moved > 0.0 && moved < 0.5);  // held back, not withdrawn outright
  for (int j = 0; j < 7; ++j)
    for (int i = 0; i < 7; ++i)
      if (i != 3 || j != 3) assert_true(move.grid(i, j) == grid(i, j));
}

void nan_offset_is_withdrawn(void**) {
  Grid grid, directions;
  flat(5, grid, directions);
  std::vector<double> offsets(grid.points.size(), 0.01);
  offsets[2 * 5 + 2] = std::numeric_limits<double>::quiet_NaN();
  const dbs::GuardedMove move = dbs::move_without_pleats(grid, directions, offsets);
  for (const Vec3& p : move.grid.points) assert_true(dbs::is_finite(p));
  assert_true(move.grid(2, 2) == grid(2, 2));
  assert_true(move.damped_nodes >= 1);
}

void sizes_are_checked(void**) {
  Grid grid, directions;
  flat(5, grid, directions);
  const std::vector<double> short_offsets(3, 0.0);
  assert_int_equal(core_test::error_code_of([&] { dbs::move_without_pleats(grid, directions, short_offsets); }), dbs::ErrorCode::InvalidArgument);
}

}  // namespace

int main() {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(orientation_keeping_move_passes),
      cmocka_unit_test(folding_move_is_damped),
      cmocka_unit_test(nan_offset_is_withdrawn),
      cmocka_unit_test(sizes_are_checked),
  };
  return cmocka_run_group_tests(tests, nullptr, nullptr);
}
