// A node of the base-surface quadtree: its boundary (inside its surface), the rectangle of
// the global domain it parameterizes, its last projected grid, its subcloud and its fit.
#pragma once
#include <array>
#include <cstddef>
#include <vector>

#include "base_surface.hpp"
#include "point_list.hpp"

namespace dbs {

struct Patch {
  int id = 0;
  int level = 0;
  int parent = -1;
  std::array<int, 4> children{{-1, -1, -1, -1}};  // (u-,v-), (u+,v-), (u-,v+), (u+,v+)
  Rect rect;
  BaseSurface surface;
  Grid grid;                           // the grid the surface interpolates
  PointList subcloud;                  // indices into the cloud (kept for leaves)
  std::size_t point_count = 0;         // size of the subcloud
  double mean_distance = 0.0;          // of the subcloud to the surface
  double max_distance = 0.0;
  int iterations = 0;                  // grid evolutions
  bool far_above = false;              // its error at a grid (of its evolution or, for the root, of a restart's) was above EvolveSettings::far_above times the target
  int restarts = 0;                    // evolutions from other starts tried (the root's, see evolve_patch_with_restart)
  std::size_t damped_nodes = 0;        // grid nodes the pleat guard held back, summed over them
  std::size_t refined_curves = 0;      // grid sections the Ceres solver refined
  std::size_t ceres_iterations = 0;    // Ceres iterations over them
  int solver = 0;                      // the solver of its grid projections (0 linear, 1 Ceres)
  double error = 0.0;                  // what decided `accurate`: mean_distance, or with a robust loss the mean robust distance
  bool accurate = false;               // error <= target

  explicit Patch(BaseSurface s) : surface(std::move(s)) {}
  bool is_leaf() const { return children[0] < 0; }
};

}  // namespace dbs
