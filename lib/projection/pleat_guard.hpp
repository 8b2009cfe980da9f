// Pleat-free grid updates. A grid projection moves every interior node of a patch's grid
// along the current surface's normal; where the cloud overhangs, bends sharply or is too
// thin for the ray to find, neighbouring nodes can cross, and the surface through the moved
// grid forms a reversed sheet (Su x Sv against the surface it came from). Points projected
// onto such a sheet fold in (u,v), and children sampled from it inherit the pleat.
//
// The guard accepts the move only where it keeps the orientation: no cell of the moved grid
// (none of the four triangles its corners span) may turn by more than about 90 degrees
// against the same cell before the move. The offsets of the corners of every offending cell
// are halved, round after round; after the last round they are withdrawn (a cell that does
// not move keeps the orientation it had). A cell that already fails the test before the move
// (a skewed or concave cell of the sample) has no orientation to keep and is not judged. The grid starts as a sample of a pleat-free
// surface, so the grid after the move is pleat-free too, by induction from the Coons patch
// of the boundary. (Checking the interpolating spline between the nodes as well was tried:
// on the hard shapes of dbs-bench-folds it held back more than it saved.)
#pragma once
#include <cstddef>
#include <vector>

#include "grid.hpp"

namespace dbs {

struct GuardedMove {
  Grid grid;                     // the moved grid
  std::size_t damped_nodes = 0;  // nodes whose offset was reduced
};

/// Moves the interior nodes of `start` (a grid sampled on the current surface) by offsets[k]
/// along directions.points[k], reduced where the move would pleat the grid. Border nodes
/// stay. Sizes must match (Error(InvalidArgument)).
GuardedMove move_without_pleats(const Grid& start, const Grid& directions, const std::vector<double>& offsets);

}  // namespace dbs
