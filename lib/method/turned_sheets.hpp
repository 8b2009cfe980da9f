// Points on a turned sheet: where the result surface under a point turns its back on the
// cloud. The fold measure judges the order of the points' (u,v) and trusts no surface; a
// surface pleated between its grid nodes, or refitted through a squeezed band by the repair,
// can carry points whose (u,v) are in order on a sheet turned over, and there a mesh of the
// surface over the domain overlaps itself and the surface's normals point the wrong way. A
// point counts as turned when the surface's Su x Sv at its (u,v) does not point towards the
// normal the fold measure found for it from the cloud (FoldMeasure::right_normal: its PCA
// normal, oriented consistently over the cloud and signed by the majority of the (u,v) maps
// of its component), so that a globally mirrored (u,v), whose surface is mirrored with it,
// turns nothing. A zero or non-finite Su x Sv counts as turned (it has no orientation to keep).
// Only points on the surface are judged: one farther from it than the repair's reach (10 times
// the target and a spacing, beyond_repair_reach in fold_repair.hpp) has no sheet under it (the surface at its (u,v)
// lies elsewhere, as where the surfaces never reached a feature), and its distance already
// says what is wrong there.
#pragma once
#include <cstddef>
#include <vector>

#include "fold_measure.hpp"
#include "fold_repair.hpp"
#include "result.hpp"

namespace dbs {

struct TurnedSheets {
  std::size_t judged = 0;  ///< points with a right normal that lie on the surface (the rest are not judged)
  std::size_t turned = 0;  ///< ... of them on a turned sheet
  double share = 0.0;      ///< turned / judged; 0 when none is judged
  std::vector<std::size_t> points;  ///< the turned ones, indices of the result's points, in judged order
};

/// The points of `folds` (the fold measure of result's (u,v) on the points `judged`, indices
/// into the result's points, or on every point when `judged` is empty) on a turned sheet of
/// `result`'s surface. threads as Options::threads (0 = all cores); the counts do not depend
/// on it. Throws Error(InvalidArgument) when `judged` (non-empty) and the measure's points
/// differ in number, when `judged` is empty and the measure is not of every point, or when a
/// judged index is not a point of `result`.
TurnedSheets turned_sheets(const Result& result, const std::vector<std::size_t>& judged, const FoldMeasure& folds, int threads);

}  // namespace dbs
