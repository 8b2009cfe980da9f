#include "leaf_refit.hpp"

#include <algorithm>

#include "grid_fit.hpp"
#include "parallel.hpp"

namespace dbs {

namespace {

double median(std::vector<double> values) {
  if (values.empty()) return 0.0;
  const auto mid = values.begin() + static_cast<std::ptrdiff_t>(values.size() / 2);
  std::nth_element(values.begin(), mid, values.end());
  return *mid;
}

}  // namespace

void place_on_leaf(Result& result, const std::vector<Vec3>& points, std::size_t i, const Vec2& uv) {
  result.u[i] = uv.x();
  result.v[i] = uv.y();
  const int leaf = result.leaf_at(uv.x(), uv.y());
  result.distance[i] = (result.evaluate(uv.x(), uv.y()) - points[i]).norm();
  result.patch[i] = leaf;
  result.level[i] = static_cast<std::int8_t>(result.patches[leaf].level);
}

void put_back(Result& result, const std::vector<Vec3>& points, std::size_t i, const Placement& before, const std::vector<char>& refitted) {
  result.u[i] = before.u;
  result.v[i] = before.v;
  result.patch[i] = before.patch;
  result.level[i] = before.level;
  result.distance[i] = before.distance;
  if (refitted[static_cast<std::size_t>(result.leaf_at(before.u, before.v))]) result.distance[i] = (result.evaluate(before.u, before.v) - points[i]).norm();
}

std::vector<char> patch_flags(const Result& result, const std::vector<int>& ids) {
  std::vector<char> flags(result.patches.size(), 0);
  for (int id : ids) flags[static_cast<std::size_t>(id)] = 1;
  return flags;
}

std::vector<int> refit_marked_leaves(Result& result, const std::vector<Vec3>& points, const std::vector<char>& outlier, const std::vector<char>& marked, int threads) {
  std::vector<std::vector<std::size_t>> data(result.patches.size()), members(result.patches.size());
  std::vector<char> touched(result.patches.size(), 0);
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (result.left_out(i)) continue;  // placed after the repair, or cropped: no leaf of their own
    const std::size_t leaf = static_cast<std::size_t>(result.leaf_at(result.u[i], result.v[i]));
    members[leaf].push_back(i);
    if (!outlier[i]) data[leaf].push_back(i);
    if (marked[i]) touched[leaf] = 1;
  }
  std::vector<int> leaves;
  for (std::size_t id = 0; id < touched.size(); ++id)
    if (touched[id]) leaves.push_back(static_cast<int>(id));
  // Each leaf writes only its own patch, each point only its own distance; the fits share
  // the cardinal functions of the leaves' grid sizes, made here.
  GridFitBasis basis;
  for (int id : leaves) basis.add(result.patches[static_cast<std::size_t>(id)].grid.nu, result.patches[static_cast<std::size_t>(id)].grid.nv);
  std::vector<char> kept(leaves.size(), 0);
  parallel_for(leaves.size(), threads, [&](std::size_t k) {
    const std::size_t id = static_cast<std::size_t>(leaves[k]);
    Patch& leaf = result.patches[id];
    std::vector<double> before, after;
    for (std::size_t i : members[id]) before.push_back((result.evaluate(result.u[i], result.v[i]) - points[i]).norm());
    const BaseSurface old_surface = leaf.surface;
    const Grid old_grid = leaf.grid;
    if (!fit_grid_to_parameters(leaf, data[id], points, result.u, result.v, &basis)) return;  // not refitted: the caller decides about its moved points
    for (std::size_t i : members[id]) after.push_back((result.evaluate(result.u[i], result.v[i]) - points[i]).norm());
    // A fit that would move the surface away from most of the leaf's points is not kept.
    if (median(after) > median(before)) {
      leaf.surface = old_surface;  // and the distances stay as they were
      leaf.grid = old_grid;
      return;
    }
    kept[k] = 1;
    for (std::size_t m = 0; m < members[id].size(); ++m) result.distance[members[id][m]] = after[m];
  });
  // (Stepping every point of a refitted leaf towards its foot on the new surface was tried:
  // it halves the mushroom's mean distance but nearly doubles its folds.)
  std::vector<int> refitted;
  for (std::size_t k = 0; k < leaves.size(); ++k)
    if (kept[k]) refitted.push_back(leaves[k]);
  return refitted;
}

}  // namespace dbs
