#include "pleat_guard.hpp"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
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
    if (!std::isfinite(length) || t.dot(n) < kMinCosine * length) return true;  // a NaN move or a collapse counts too
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
  const int cells_u = start.nu - 1, cells_v = start.nv - 1;
  // A cell that fails the test before any move (a skewed or concave cell of the sample) has no
  // orientation the guard could keep: it is not judged.
  std::vector<char> judged(static_cast<std::size_t>(cells_u) * cells_v, 0);
  for (int j = 0; j < cells_v; ++j)
    for (int i = 0; i < cells_u; ++i) judged[static_cast<std::size_t>(j) * cells_u + i] = !cell_turns(start, start, i, j);
  // Each withdrawal round sets at least one more interior node back to its start (a judged
  // cell whose four corners are back is the start's own and passes), so the rounds end.
  const int max_rounds = kHalvingRounds + static_cast<int>(n) + 1;
  std::vector<double> scale(n, 1.0);
  std::vector<char> damped(n, 0);
  for (int round = 0;; ++round) {
    Grid moved = moved_grid(start, directions, offsets, scale);
    std::vector<char> offending(judged.size(), 0);
    bool any = false;
    for (int j = 0; j < cells_v; ++j)
      for (int i = 0; i < cells_u; ++i) {
        const std::size_t c = static_cast<std::size_t>(j) * cells_u + i;
        if (judged[c] && cell_turns(start, moved, i, j)) offending[c] = any = true;
      }
    if (!any) {
      out.grid = std::move(moved);
      break;
    }
    if (round >= max_rounds) {  // a safeguard against rounding: the grid does not move this time
      out.grid = start;
      std::fill(scale.begin(), scale.end(), 0.0);
      for (int j = 1; j + 1 < start.nv; ++j)
        for (int i = 1; i + 1 < start.nu; ++i) damped[static_cast<std::size_t>(j) * start.nu + i] = 1;
      break;
    }
    // The corners of every offending cell move less; after the halving rounds, not at all.
    const double factor = round < kHalvingRounds ? 0.5 : 0.0;
    for (int j = 0; j < cells_v; ++j)
      for (int i = 0; i < cells_u; ++i) {
        if (!offending[static_cast<std::size_t>(j) * cells_u + i]) continue;
        for (int dj = 0; dj < 2; ++dj)
          for (int di = 0; di < 2; ++di) {
            const int a = i + di, b = j + dj;
            if (a == 0 || b == 0 || a == start.nu - 1 || b == start.nv - 1) continue;  // border nodes do not move
            const std::size_t k = static_cast<std::size_t>(b) * start.nu + a;
            scale[k] *= factor;
            if (offsets[k] != 0.0) damped[k] = 1;  // a node that was not to move is not held back
          }
      }
  }
  out.damped_nodes = static_cast<std::size_t>(std::count(damped.begin(), damped.end(), 1));
  return out;
}

}  // namespace dbs
