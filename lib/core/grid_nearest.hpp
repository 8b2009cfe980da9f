// The nearest point of a structured grid of points (a surface's samples, nu x nv, u fastest):
// a quadtree of bounding boxes over blocks of the grid's indices. The grid's structure gives
// the tree for free: each node is a block of index space, its box the union of its
// children's, so it is built in one pass over the points (a general k-d tree over the 64 x 64
// samples of a projector cost about 570 instructions a sample, as much as sampling the
// surface twice; this costs a few). The answer does not depend on the traversal: the point of
// least squared distance, the lowest index among equals.
#pragma once
#include <cstdint>
#include <vector>

#include "geometry.hpp"

namespace dbs {

class GridNearest {
 public:
  /// Over `points` (nu x nv, u fastest, at least one; they must outlive this).
  GridNearest(const std::vector<Vec3>& points, int nu, int nv);

  /// Index of the point nearest q (0 when no distance compares: non-finite points or q).
  std::size_t nearest(const Vec3& q) const;

 private:
  struct Level {
    int nu = 0, nv = 0;  // nodes a side
    std::vector<Box3> boxes;
  };
  void search(const Vec3& q, int level, int i, int j, double& best2, std::size_t& best) const;

  const std::vector<Vec3>& points_;
  int nu_, nv_;
  std::vector<Level> levels_;  // root first; the last one's nodes are blocks of kBlock x kBlock points
};

}  // namespace dbs
