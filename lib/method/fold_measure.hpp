// A fold measure that needs no connectivity and trusts no surface: it judges a
// parameterization (u,v) of an unorganized cloud from the cloud alone.
//
// For every point: its neighbourhood (the kNeighbours nearest, widened to every point within
// max(kSpacingRadius x spacing, kNoiseRadius x sigma), at most kMaxNeighbourhood of them; one
// that is not surface-like, as at a border of the cloud, is tried once kRetryRadius x wider).
// Neighbours torn from the point in (u,v) (|duv|/|dp| above kTearRatio x the point's stretch,
// a low quantile of that ratio: the far side of a thin flap, a seam, a flipped patch's rim)
// are left out. Over the rest: a tangent frame by PCA (the eigenvector of the smallest
// eigenvalue is the normal) and the least-squares 2x2 linear map J from the neighbours'
// tangent coordinates (relative to the point) to their (du,dv). The normals are oriented
// consistently by Hoppe's minimum spanning tree over the kNN graph (weight 1 - |n_i.n_j|, torn
// edges heavier than any other, edges only between similar normals and along both tangent
// planes; Prim from the lowest unvisited index, ties by index), so a point's orientation is
// sign(det J) against that oriented normal. In each connected component of the graph the sign
// of the majority of its decided points is "right" (the normals of two components are oriented
// independently, so no sign is comparable across them); points of the other sign are folded.
// A globally mirrored (u,v) therefore folds nothing. The (u,v) only choose which neighbours
// count; normals come from the cloud alone, no surface is consulted. A sound point that
// several sound points of its own sheet (graph neighbours) see torn away is marked torn
// (kFoldTorn), for the repair; it still counts as decided and unfolded. The (u,v) are taken to
// lie in the unit square: near its border a tear may be the boundary's cut.
//
// A point is undecided (never folded) when its neighbourhood is not surface-like, its
// neighbours do not constrain J, J explains less than half of the (du,dv), the sign of J is
// not significant (its smallest singular value below 1e-3 of the largest or within 3 standard
// errors of 0), |det J| is below 1e-3 of the median, or its component has no majority.
// Folds are seen at the neighbourhood's scale (a few spacings): jitter of single points in
// (u,v) is not a fold here. Two sheets closer than about 3 spacings (an undersampled flap)
// cannot be told apart from one and may be misjudged.
//
// Deterministic and bit-identical for any thread count; invariant to a uniform scale and a
// rigid motion of the cloud with sigma (only ratios to the spacing and to sigma are used).
// O(N (k + m) log N) for k = kNeighbours and m = kMaxNeighbourhood: a neighbourhood wider than
// the k nearest is gathered from the cloud thinned to every 4^l-th point (the finest l that
// yields at most about m points), so a large sigma costs at most m points per query.
#pragma once
#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

#include "geometry.hpp"
#include "work_meter.hpp"

namespace dbs {

/// The measure's fixed settings (ratios only, so the measure is scale-invariant).
namespace fold {
constexpr std::size_t kNeighbours = 16;          ///< nearest points of a neighbourhood (the point included)
constexpr double kSpacingRadius = 3.0;           ///< neighbourhood radius at least this x the cloud spacing
constexpr double kNoiseRadius = 6.0;             ///< ... and at least this x sigma
constexpr std::size_t kMaxNeighbourhood = 128;   ///< larger neighbourhoods are thinned evenly by index
constexpr double kRetryRadius = 2.0;             ///< a neighbourhood not surface-like is tried once this x wider
constexpr std::size_t kGraphNeighbours = 10;     ///< nearest points joined in the orientation graph
constexpr double kMaxFlatness = 0.3;             ///< surface-like: lambda_min <= this x lambda_mid
constexpr double kMinEdgeCosine = 0.5;           ///< graph edge only between normals within 60 degrees
constexpr double kMaxEdgeNormalCosine = 0.5;     ///< ... and whose direction is within 30 degrees of both tangent planes
constexpr double kStretchQuantile = 0.25;        ///< a point's stretch: this quantile of its neighbours' |duv|/|dp|
constexpr double kTearRatio = 4.0;               ///< neighbour torn: |duv|/|dp| above this x the stretch
constexpr double kMinSpread = 1e-2;              ///< tangent coordinates: smallest / largest moment
constexpr double kMaxResidual = 0.5;             ///< J must explain at least half of sum |duv|^2
constexpr double kMaxCondition = 1e3;            ///< singular values of J
constexpr double kSignificance = 3.0;            ///< smallest singular value in standard errors
constexpr double kMinDetShare = 1e-3;            ///< |det J| relative to the median
constexpr double kCoincident = 1e-12;            ///< (u,v) tolerance of count_coincident
constexpr std::size_t kTornNeighbours = 3;       ///< sound points that see a point thrown off make it kFoldTorn
}  // namespace fold

/// Per-point verdicts of measure_folds().
/// kFoldCollapsed: undecided (never counted as folded) because the point's neighbourhood is
/// squeezed in (u,v): most neighbours share its (u,v), the local map is of rank about one
/// (smallest singular value below 1e-3 of the largest) or |det J| is below 1e-3 of the
/// median; the points a surface never reached pile up like that (collapses, which keep
/// their orientation and so cannot be told folded).
/// kFoldScrambled: undecided because no linear map explains the (u,v) of the neighbourhood
/// (J explains less than half of them): its points are shuffled in (u,v), as where a
/// surface pleated below the scale of its grid meets the cloud.
/// kFoldTorn: decided and not folded (counted as such), but seen thrown off by at least
/// kTornNeighbours sound points of its sheet: points that have it among their
/// orientation-graph neighbours (their nearest points on the same sheet: normals within 60
/// degrees, along both tangent planes) and find it much farther in (u,v) than its distance
/// suggests (|duv|/|dp| above kTearRatio x their own stretch); a pair both nearer the unit
/// square's border than to each other in (u,v) is a cut the boundary makes, not a tear. A
/// continuous sheet torn apart in (u,v): where leaves meet under an overhang, points a leaf's
/// surface passed at a distance take feet on another part of the domain, a scramble the
/// measure's local maps do not see (they leave the torn neighbours out, as they must for a
/// thin flap, whose two sides are never graph neighbours). The points on both sides of the
/// tear see each other so (a disk of points thrown elsewhere in the domain: about as many
/// torn points outside it as inside); a clump of a few points thrown off is undecided instead.
enum : std::int8_t { kFoldOk = 1, kFoldUndecided = 0, kFolded = -1, kFoldCollapsed = -2, kFoldScrambled = -3, kFoldTorn = -4 };

/// The verdicts the repair is for: folded, collapsed, scrambled or torn (plain undecided
/// points are not, unless amid such points: fold_repair.hpp).
inline bool doubted_verdict(std::int8_t state) { return state == kFolded || state == kFoldCollapsed || state == kFoldScrambled || state == kFoldTorn; }

struct FoldMeasure {
  std::size_t points = 0;      ///< number of points judged
  std::size_t folded = 0;      ///< points whose neighbourhood is mapped with reversed orientation
  std::size_t undecided = 0;   ///< points whose orientation could not be decided (not counted as folded)
  std::size_t coincident = 0;  ///< points sharing one (u,v) with another point (see count_coincident)
  std::size_t collapsed = 0;   ///< undecided points whose neighbourhood is squeezed (kFoldCollapsed), part of `undecided`
  std::size_t torn = 0;        ///< decided, unfolded points torn from their sheet's neighbours (kFoldTorn), not part of `undecided`
  double folded_share = 0.0;   ///< folded / (points - undecided); 0 when no point is decided
  std::vector<std::int8_t> state;  ///< per point: kFoldOk (+1), kFolded (-1), kFoldUndecided (0), kFoldCollapsed (-2), kFoldScrambled (-3), kFoldTorn (-4)
  /// Per point: the unit normal towards which a surface agreeing with the (u,v) turns its
  /// Su x Sv there: the point's PCA normal, oriented with the others and signed by its
  /// component's majority (a surface S with S(u_i,v_i) near the points and the orientation
  /// of their (u,v) has Su x Sv . right_normal > 0). Zero where that is unknown (a point
  /// outside the orientation graph, or its component without a majority). For turned_sheets.hpp.
  std::vector<Vec3> right_normal;
};

/// Judges the parameterization (u[i], v[i]) of points[i], (u,v) in the unit square (kFoldTorn
/// takes points near its border for a cut of the boundary). noise_sigma >= 0 is the cloud's noise
/// level in cloud units (0: unknown or noise-free); threads as Options::threads (0 = all cores).
/// Throws Error(InvalidArgument) when the sizes differ or noise_sigma < 0, Error(NonFinite) for
/// a non-finite point, parameter or sigma. Fewer than 4 distinct points: all undecided.
FoldMeasure measure_folds(const std::vector<Vec3>& points, const std::vector<double>& u, const std::vector<double>& v, double noise_sigma, int threads, WorkMeter* meter = nullptr);

/// What measure_folds finds from the cloud alone (its index, spacing, thinned levels, the
/// orientation graph's edges and each point's neighbourhood), kept for judging several
/// parameterizations of the same points: the repair judges its candidates one after the
/// other, and the cloud is searched once for all of them. Each point's neighbourhood is
/// found the first time the point is judged; judge() gives the verdicts of measure_folds
/// bit for bit. `points` must outlive the object. judge() may not run concurrently with
/// itself on one object (it fills the neighbourhoods); it is otherwise as measure_folds.
class FoldNeighbourhoods {
 public:
  /// Throws as measure_folds for a non-finite point or a noise level not finite or negative.
  FoldNeighbourhoods(const std::vector<Vec3>& points, double noise_sigma);
  ~FoldNeighbourhoods();
  FoldNeighbourhoods(const FoldNeighbourhoods&) = delete;
  FoldNeighbourhoods& operator=(const FoldNeighbourhoods&) = delete;

  std::size_t size() const;
  /// measure_folds(points, u, v, noise_sigma, threads, meter) of the constructor's points.
  FoldMeasure judge(const std::vector<double>& u, const std::vector<double>& v, int threads, WorkMeter* meter = nullptr);

 private:
  struct Impl;
  friend FoldMeasure measure_folds(const std::vector<Vec3>&, const std::vector<double>&, const std::vector<double>&, double, int, WorkMeter*);
  std::unique_ptr<Impl> impl_;
};

/// Values given on the points `judged` (indices into `points`, distinct, one value each)
/// spread over every point: each takes the value of the nearest judged point (ties: the lower
/// index). Deterministic for any thread count. For std::int8_t (verdicts) and Vec3 (normals).
template <class T>
std::vector<T> spread_from_judged(const std::vector<Vec3>& points, const std::vector<std::size_t>& judged, const std::vector<T>& values, int threads, WorkMeter* meter = nullptr);

/// The verdicts of measure_folds on the points `judged` spread over every point
/// (spread_from_judged).
std::vector<std::int8_t> spread_verdicts(const std::vector<Vec3>& points, const std::vector<std::size_t>& judged, const std::vector<std::int8_t>& state, int threads, WorkMeter* meter = nullptr);

/// Number of points i for which some j != i has |u_i - u_j| <= 1e-12 and |v_i - v_j| <= 1e-12
/// (exact duplicates included). O(N log N). Throws Error(InvalidArgument) when the sizes differ.
std::size_t count_coincident(const std::vector<double>& u, const std::vector<double>& v);

}  // namespace dbs
