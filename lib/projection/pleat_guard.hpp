// Pleat-free grid updates. A grid projection moves every interior node of a patch's grid
// along the current surface's normal; where the cloud overhangs, bends sharply or is too
// thin for the ray to find, neighbouring nodes can cross, and the surface through the moved
// grid forms a reversed sheet (Su x Sv against the surface it came from). Points projected
// onto such a sheet fold in (u,v), and children sampled from it inherit the pleat.
//
// The guard accepts the move only where it keeps the orientation: a cell of the moved grid
// (each of the four triangles its corners span) and the surface interpolating the moved grid
// (sampled between the nodes) must not turn by more than about 90 degrees against the
// surface before the move at the same parameters. The offsets of the nodes around every
// offending cell or sample are halved, round after round; after the last round they are
// withdrawn (a node that does not move keeps the orientation it had). Since the surface the
// move starts from is itself pleat-free, the surface after the move is too, by induction
// from the Coons patch of the boundary.
#pragma once
#include <cstddef>
#include <vector>

#include "base_surface.hpp"

namespace dbs {

struct GuardedMove {
  Grid grid;                     // the moved grid
  std::size_t damped_nodes = 0;  // nodes whose offset was reduced
};

/// Moves the interior nodes of `start` (a sample of `surface` at the grid's parameters) by
/// offsets[k] along directions.points[k], reduced where the move would pleat the surface.
/// Border nodes stay. Sizes must match (Error(InvalidArgument)).
GuardedMove move_without_pleats(const BaseSurface& surface, const Grid& start, const Grid& directions, const std::vector<double>& offsets);

}  // namespace dbs
