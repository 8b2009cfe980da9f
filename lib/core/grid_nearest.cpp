#include "grid_nearest.hpp"

#include <algorithm>
#include <array>
#include <limits>
#include <string>
#include <utility>

#include "error.hpp"

namespace dbs {

namespace {

/// Points a side of a leaf block.
constexpr int kBlock = 4;

double box_distance2(const Vec3& q, const Box3& b) { return (b.min - q).cwiseMax(q - b.max).cwiseMax(0.0).squaredNorm(); }

}  // namespace

GridNearest::GridNearest(const std::vector<Vec3>& points, int nu, int nv) : points_(points), nu_(nu), nv_(nv) {
  if (nu < 1 || nv < 1 || points.size() != static_cast<std::size_t>(nu) * static_cast<std::size_t>(nv))
    fail(ErrorCode::InvalidArgument, "GridNearest: " + std::to_string(points.size()) + " points for a " + std::to_string(nu) + " x " + std::to_string(nv) + " grid");
  // The leaf blocks, then each level of parents of 2 x 2 nodes up to a single root.
  Level leaves;
  leaves.nu = (nu + kBlock - 1) / kBlock;
  leaves.nv = (nv + kBlock - 1) / kBlock;
  leaves.boxes.resize(static_cast<std::size_t>(leaves.nu) * leaves.nv);
  for (int j = 0; j < nv; ++j)
    for (int i = 0; i < nu; ++i) leaves.boxes[static_cast<std::size_t>(j / kBlock) * leaves.nu + i / kBlock].extend(points[static_cast<std::size_t>(j) * nu + i]);
  std::vector<Level> up{std::move(leaves)};
  while (up.back().nu > 1 || up.back().nv > 1) {
    const Level& child = up.back();
    Level parent;
    parent.nu = (child.nu + 1) / 2;
    parent.nv = (child.nv + 1) / 2;
    parent.boxes.resize(static_cast<std::size_t>(parent.nu) * parent.nv);
    for (int j = 0; j < child.nv; ++j)
      for (int i = 0; i < child.nu; ++i) {
        const Box3& b = child.boxes[static_cast<std::size_t>(j) * child.nu + i];
        Box3& p = parent.boxes[static_cast<std::size_t>(j / 2) * parent.nu + i / 2];
        p.min = p.min.cwiseMin(b.min);
        p.max = p.max.cwiseMax(b.max);
      }
    up.push_back(std::move(parent));
  }
  levels_.assign(std::make_move_iterator(up.rbegin()), std::make_move_iterator(up.rend()));
}

void GridNearest::search(const Vec3& q, int level, int i, int j, double& best2, std::size_t& best) const {
  if (level + 1 == static_cast<int>(levels_.size())) {
    // A leaf block: its points, the lowest index winning a tie.
    const int i1 = std::min(nu_, (i + 1) * kBlock), j1 = std::min(nv_, (j + 1) * kBlock);
    for (int b = j * kBlock; b < j1; ++b)
      for (int a = i * kBlock; a < i1; ++a) {
        const std::size_t k = static_cast<std::size_t>(b) * nu_ + a;
        const double d2 = (points_[k] - q).squaredNorm();
        if (d2 < best2 || (d2 == best2 && k < best)) best2 = d2, best = k;
      }
    return;
  }
  // The (up to four) children, nearest box first; a box farther than the best is passed.
  const Level& below = levels_[static_cast<std::size_t>(level) + 1];
  std::array<std::pair<double, int>, 4> order;
  int count = 0;
  for (int b = 2 * j; b < std::min(below.nv, 2 * j + 2); ++b)
    for (int a = 2 * i; a < std::min(below.nu, 2 * i + 2); ++a) order[count++] = {box_distance2(q, below.boxes[static_cast<std::size_t>(b) * below.nu + a]), b * below.nu + a};
  for (int c = 1; c < count; ++c)  // insertion sort of at most four
    for (int d = c; d > 0 && order[d] < order[d - 1]; --d) std::swap(order[d], order[d - 1]);
  for (int c = 0; c < count; ++c) {
    if (order[c].first > best2) break;
    search(q, level + 1, order[c].second % below.nu, order[c].second / below.nu, best2, best);
  }
}

std::size_t GridNearest::nearest(const Vec3& q) const {
  double best2 = std::numeric_limits<double>::infinity();
  std::size_t best = points_.size();
  search(q, 0, 0, 0, best2, best);
  return best < points_.size() ? best : 0;
}

}  // namespace dbs
