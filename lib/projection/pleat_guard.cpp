#include "pleat_guard.hpp"

#include <Eigen/Geometry>

#include <algorithm>
#include <string>

#include "error.hpp"

namespace dbs {

namespace {

/// Rounds of halving before an offending node's offset is withdrawn.
constexpr int kHalvingRounds = 6;
/// A triangle of a moved cell may turn against the cell before the move by up to
/// acos(kMinCosine) (just under 90 degrees): steep walls are reached in a few damped steps,
/// a reversed sheet never.
constexpr double kMinCosine = 0.02;
/// Rounds after the halving ones (offsets withdrawn) before the grid is left unmoved.
constexpr int kWithdrawRounds = 4;

/// True when a triangle of the moved cell turns against the cell before the move.
bool cell_turns(const Grid& before, const Grid& after, int i, int j) {
  const Vec3 a0 = before(i, j), b0 = before(i + 1, j), c0 = before(i + 1, j + 1), d0 = before(i, j + 1);
  const Vec3 reference = (c0 - a0).cross(d0 - b0);
  const double reference_length = reference.norm();
  if (!(reference_length > 0.0)) return false;  // a collapsed cell (a pole of the boundary) has no orientation to keep
  const Vec3 n = reference / reference_length;
  const Vec3 a = after(i, j), b = after(i + 1, j), c = after(i + 1, j + 1), d = after(i, j + 1);
  for (const Vec3& t : {Vec3((b - a).cross(c - a)), Vec3((c - a).cross(d - a)), Vec3((b - a).cross(d - a)), Vec3((c - b).cross(d - b))}) {
    const double length = t.norm();
    if (length > 0.0 && t.dot(n) < kMinCosine * length) return true;
  }
  return false;
}

Grid moved_grid(const Grid& start, const Grid& directions, const std::vector<double>& offsets, const std::vector<double>& scale) {
  Grid g = start;
  for (int j = 1; j + 1 < g.nv; ++j)
    for (int i = 1; i + 1 < g.nu; ++i) {
      const std::size_t k = static_cast<std::size_t>(j) * g.nu + i;
      g.points[k] += scale[k] * offsets[k] * directions.points[k];
    }
  return g;
}

}  // namespace

GuardedMove move_without_pleats(const Grid& start, const Grid& directions, const std::vector<double>& offsets) {
  const std::size_t n = start.points.size();
  if (directions.points.size() != n || offsets.size() != n || directions.nu != start.nu || directions.nv != start.nv)
    fail(ErrorCode::InvalidArgument, "move_without_pleats: grid, directions and offsets differ in size");
  GuardedMove out;
  if (start.nu < 3 || start.nv < 3) {
    out.grid = start;
    return out;
  }
  std::vector<double> scale(n, 1.0);
  std::vector<char> damped(n, 0);
  for (int round = 0;; ++round) {
    Grid moved = moved_grid(start, directions, offsets, scale);
    std::vector<char> offending((start.nu - 1) * (start.nv - 1), 0);
    bool any = false;
    for (int j = 0; j + 1 < start.nv; ++j)
      for (int i = 0; i + 1 < start.nu; ++i)
        if (cell_turns(start, moved, i, j)) offending[j * (start.nu - 1) + i] = any = true;
    if (!any) {
      out.grid = std::move(moved);
      break;
    }
    // The corners of every offending cell move less; after the halving rounds, not at all
    // (a cell whose four corners are back at the start cannot turn against itself).
    const double factor = round < kHalvingRounds ? 0.5 : 0.0;
    for (int j = 0; j + 1 < start.nv; ++j)
      for (int i = 0; i + 1 < start.nu; ++i) {
        if (!offending[j * (start.nu - 1) + i]) continue;
        for (int dj = 0; dj < 2; ++dj)
          for (int di = 0; di < 2; ++di) {
            const std::size_t k = static_cast<std::size_t>(j + dj) * start.nu + (i + di);
            scale[k] *= factor;
            damped[k] = 1;
          }
      }
    if (round > kHalvingRounds + kWithdrawRounds) {
      // Unreachable in exact arithmetic (a cell whose corners are all back is the start's
      // own); should rounding keep a cell turning, the grid does not move at all this time.
      out.grid = start;
      for (int j = 1; j + 1 < start.nv; ++j)
        for (int i = 1; i + 1 < start.nu; ++i) damped[static_cast<std::size_t>(j) * start.nu + i] = 1;
      break;
    }
  }
  out.damped_nodes = static_cast<std::size_t>(std::count(damped.begin(), damped.end(), 1));
  return out;
}

}  // namespace dbs
