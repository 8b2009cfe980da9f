// A node of the base-surface quadtree: its boundary (inside its surface), the rectangle of
// the global domain it parameterizes, its last projected grid, its subcloud and its fit.
#pragma once
#include <array>
#include <cstddef>
#include <vector>

#include "base_surface.hpp"

namespace dbs {

struct Patch {
  int id = 0;
  int level = 0;
  int parent = -1;
  std::array<int, 4> children{{-1, -1, -1, -1}};  // (u-,v-), (u+,v-), (u-,v+), (u+,v+)
  Rect rect;
  BaseSurface surface;
  Grid grid;                           // the grid the surface interpolates
  std::vector<std::size_t> subcloud;   // indices into the cloud (kept for leaves)
  std::size_t point_count = 0;         // size of the subcloud
  double mean_distance = 0.0;          // of the subcloud to the surface
  double max_distance = 0.0;
  int iterations = 0;                  // grid evolutions
  std::size_t damped_nodes = 0;        // grid nodes the pleat guard held back, summed over them
  bool accurate = false;               // mean_distance <= target

  explicit Patch(BaseSurface s) : surface(std::move(s)) {}
  bool is_leaf() const { return children[0] < 0; }
};

}  // namespace dbs
