// Points of a parameterization torn off their sheet (kFoldTorn, fold_measure.hpp): the fold
// measure's last step, for the repair's wide reaches (fold_repair.hpp).
#pragma once
#include <cstdint>
#include <vector>

#include "fold_local.hpp"
#include "fold_measure.hpp"

namespace dbs::fold_detail {

/// Sound points (kFoldOk in m.state) seen torn away by at least kTornNeighbours sound points
/// whose graph neighbours on their sheet they are (the tear judged at the seeing point, with
/// its own stretch) become kFoldTorn, counted in m.torn. Both sides of a tear are marked: a
/// region thrown elsewhere in the domain is sound within itself, and its points and the sound
/// points around it see each other torn away. `graph` holds kGraphNeighbours slots a point.
void mark_torn(const std::vector<Vec3>& points, const std::vector<double>& u, const std::vector<double>& v, const std::vector<Local>& local,
               const std::vector<std::uint32_t>& graph, FoldMeasure& m);

}  // namespace dbs::fold_detail
