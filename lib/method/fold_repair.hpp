// The last-resort repair of a parameterization (DBS_OPT_REPAIR). A point whose foot lies far
// from its leaf is one the base surfaces never reached (under an overhang, up a steep wall):
// its orthogonal foot sits on a surface that passes it at a distance, and points projected
// from afar crowd into a small part of the domain and fold. Points the fold measure judges
// folded, collapsed or scrambled, and undecided points inside a region of such doubtful
// points (where leaves meet on a steep wall, a surface pleated at a scale below the leaves'
// grids scrambles its points' (u,v): the measure finds no local map there), are repaired too,
// with the ring of their nearest points.
// Every such point takes the
// inverse-distance mean of the (u,v) of its nearest points in 3D (a harmonic fill, the other
// points fixed), then moves towards its orthogonal foot on the result surface within a trust
// radius, and is flagged. Then every leaf holding a repaired point is refitted to its points
// at their (u,v) (a least-squares fit of its grid, its boundary unchanged), so the surface
// comes to the points it had missed, and every point of those leaves gets the distance of
// the refitted surface at its (u,v), patch and level of the leaf there.
//
// After the driver has chosen a reach, untangle_repaired straightens the (u,v) of the repaired
// regions at the scale of single points (untangle.hpp), which the fold measure does not see.
//
// "Far" is more than kRepairFactor times the accuracy target used (which the noise floor keeps
// above the noise, so a noisy cloud's points are not taken for unreached ones) and more than
// kRepairSpacings cloud spacings. A far point that stands alone (a gross outlier) is neither
// repaired nor fitted: few points around it for the cloud's spacing, unless it lies in a sheet
// the surfaces missed (most of its 12 nearest points far too, all within kSheetSpacings
// spacings: the mushroom's cap, sampled about three times sparser than the plate, was taken
// for outliers and held its misplaced (u,v) amid the fill; the layer a few percent of gross
// outliers form is tens of times sparser). Measured on the hard shapes of dbs-bench-folds: the mushroom goes from
// 7.2% to 0.12% folded reference triangles and its mean distance from 0.0208 to 0.0047, the
// tall dome from 8.2% to 0.18% and 0.0183 to 0.011 (the fill alone, without the refit, raised
// their mean distance by 17% and 43%); at 2.5 times the points, where few points are far,
// the points the measure doubts take the mushroom from 3.00% to 1.41% and the dome from
// 4.94% to 1.73%.
#pragma once
#include <cstddef>
#include <cstdint>
#include <vector>

#include "cloud_index.hpp"
#include "grid_fit.hpp"
#include "result.hpp"
#include "work_meter.hpp"

namespace dbs {

constexpr double kRepairFactor = 10.0;         ///< far: beyond this x the target ...
constexpr double kRepairSpacings = 1.0;        ///< ... and beyond this many spacings h
constexpr std::size_t kRepairNeighbours = 12;  ///< neighbours of the harmonic fill
constexpr double kRepairTrust = 0.15;          ///< step towards the foot: at most this x the mean (u,v) distance to the neighbours (0.25 before the wide reaches: a longer step fits better and folds more)
constexpr double kIsolationSpacings = 3.0;      ///< a far point's neighbourhood: at least this many spacings h ...
constexpr double kIsolationShare = 0.25;        ///< ... isolated when it holds less than this share of a sheet's points ...
constexpr double kSheetSpacings = 8.0;          ///< ... unless it lies in a missed sheet: most of its nearest points far too, all within this many spacings h

/// Whether point i of `result` lies farther from its surface than the repair's reach: more
/// than kRepairFactor times the target used and kRepairSpacings spacings ("far" above, without
/// the exceptions of the points outside the boundary or the body).
bool beyond_repair_reach(const Result& result, std::size_t i);
constexpr double kSuspectClusterShare = 0.75;    ///< an undecided point is repaired when at least this share of its neighbours are doubtful too
constexpr double kBorderOffset = 0.4;           ///< ... and it is inside the cloud: its neighbours' centroid within this x their mean distance

constexpr int kMaxWideRings = 2;                ///< the driver tries wide reaches of 1 .. this many rings ...
constexpr double kPointsAcrossPerRing = 48.0;   ///< ... or of 1 .. sqrt(points) / this, the larger

/// The widest reach the driver tries when the rings step over `points` points: the points the
/// fold measure judged (the whole cloud, or its even sample of a large one, at most 20,000
/// points). A ring is a step to the nearest of those points, so over more points the same
/// rings reach a smaller share of the surface, while a region the surfaces missed (round the
/// fingers' tips, under the mushroom's cap) spans the same share at any density. The rings
/// grow with the points across (sqrt(points), rounded): kMaxWideRings below 14,400 points, 3
/// from there (the most over a 20,000-point sample). On the 30 denser clouds of
/// dbs-bench-folds (3.5-8 times its points, 14,279-32,761): 3,174 -> 2,349 folded reference
/// triangles, the fingers at 4 times 287 -> 15; the 102 clouds below 14,400 points unchanged.
/// `noisy`: the cloud's noise floor is above the requested target. There the doubtful points
/// are partly the noise's, and the wider fill moved more sound points (32 noisy clouds at 4 and
/// 6 times the points: the three it changed all fitted worse, the tall dome's folds 266 -> 392),
/// so the widest stays kMaxWideRings.
int max_wide_rings(std::size_t points, bool noisy);

/// How far around the doubtful points the repair reaches. Narrow (wide_rings 0): the doubtful
/// points and one ring of their nearest points, never at the cloud's border. Wide (wide_rings
/// k > 0): the doubtful and the far points and k rings of nearest points around them, border
/// included: where the surfaces missed a whole feature (under a mushroom's cap) the narrow
/// fill is held by points that are themselves misplaced, and only a region whose rim lies in
/// sound territory unfolds; on a tall, narrow feature a wide fill crushes more than it unfolds
/// (a harmonic map's (u,v) shrink up a tube). The driver tries the wide reaches when the
/// narrow one leaves points the fold measure doubts, and keeps the one it judges best.
struct RepairReach {
  int wide_rings = 0;
};

/// What repair_folds did.
struct Repair {
  std::size_t repaired = 0;        ///< points given a new (u,v)
  std::vector<int> refitted;       ///< leaves refitted, in increasing id order
};

/// The points the repair should take besides the far ones, from the fold measure's verdicts
/// `state` on the points `judged` (indices into `points`; empty: `state` is of every point):
/// the folded, collapsed and scrambled points, undecided points amid doubtful ones (never at
/// the cloud's border), and the ring of their kRepairNeighbours nearest points (the narrow
/// `reach`), or those, the torn ones (kFoldTorn: thrown off their sheet, where leaves meet
/// under an overhang) and the far points widened as a wide RepairReach says. Torn points are
/// left to the wide reaches, which the driver keeps only where they leave fewer doubts at no
/// more than the unrepaired mean distance (the narrow one it keeps unchecked): the 10,201-point
/// mushroom of dbs-bench-folds folds 53 -> 27 reference triangles. Where the torn points are
/// all there is to repair, the driver skips the narrow repair and tries the wide ones. On a sampled
/// cloud they are found among the judged points and every point takes the flag of its
/// nearest judged point (a query per point only when there is a suspect). Points far outside
/// the body are never taken. Deterministic for any thread count.
std::vector<char> doubtful_points(const Result& result, const std::vector<Vec3>& points, const std::vector<std::size_t>& judged, const std::vector<std::int8_t>& state, int threads, WorkMeter* meter = nullptr,
                                  RepairReach reach = {});

/// Points that neither move nor take part in a refit: those left out of the result (far outside
/// the body, cropped) and far points that stand alone, gross outliers (see the header).
std::vector<char> refit_outliers(const Result& result, const std::vector<Vec3>& points, const CloudIndex& index, int threads);

/// Whether repair_folds would take any point: one flagged in `suspect` or a far one (the
/// driver saves the result for a second try only then).
bool repair_has_work(const Result& result, const std::vector<char>& suspect);

/// Repairs the far points of `result` (parameters of `points`, which it was made from) and
/// those flagged in `suspect` (doubtful_points; empty: far points only) in place, setting
/// result.repaired, and refits the leaves they land on (their grids, surfaces and the
/// distances of their points change; their mean/max figures are left to the caller). Points
/// far outside the body (result.outside_body) are neither repaired nor data of a refit.
/// Deterministic for any thread count.
Repair repair_folds(Result& result, const std::vector<Vec3>& points, const std::vector<char>& suspect, int threads);

/// After the repair: untangles (untangle.hpp) the (u,v) of the repaired points and of the
/// ring of their kRepairNeighbours nearest points, then refits the leaves the moved points
/// land on, as repair_folds does; a moved point whose leaf keeps its surface goes back, and
/// only it: the repair's own points stay (run inside repair_folds, before its refit, a moved
/// tip point of the 10,000-point fingers made its leaf's refit fail and the fill's points
/// there went back to their crushed feet: 9 -> 73 folded reference triangles).
/// Moved points are flagged repaired and counted in result.repaired_points; the returned
/// `repaired` counts them, `refitted` the leaves refitted. Nothing when no point is repaired.
/// Deterministic for any thread count.
Repair untangle_repaired(Result& result, const std::vector<Vec3>& points, int threads);

}  // namespace dbs
