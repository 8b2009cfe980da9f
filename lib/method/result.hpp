// The outcome of a parameterization: per-point parameters in input order, the quadtree of
// patches, and summary statistics.
#pragma once
#include <cstdint>
#include <vector>

#include "patch.hpp"

namespace dbs {

/// Bits of Result::point_flags; values equal the DBS_POINT_* of the C API.
enum PointFlag : std::int32_t {
  kPointRepaired = 1,  ///< the last-resort repair gave it its (u,v) (Result::repaired)
  kPointFar = 2,       ///< far outside the cloud's body (Result::outside_body)
  kPointClamped = 4,   ///< outside the boundary (Result::clamped)
  kPointCropped = 8,   ///< cropped (Result::cropped)
  kPointTurned = 16,   ///< judged on a turned sheet of the surface (Result::turned)
};

struct Result {
  // per point, input order
  std::vector<double> u, v, distance;
  std::vector<std::int32_t> patch;
  std::vector<std::int8_t> level;  // at most Options' largest max_level, 8: a byte a point
  /// Per point: 1 when the last-resort repair (fold_repair.hpp) gave it its (u,v) from its
  /// neighbours (its distance is then to the surface at that (u,v)); all 0 when it was off.
  std::vector<char> repaired;
  std::size_t repaired_points = 0;
  /// Points the smoothing of turned sheets moved (turned_smoothing.hpp); 0 when it was off.
  std::size_t smoothed_points = 0;
  // the quadtree; patches[id].id == id; patches[0] is the root
  std::vector<Patch> patches;
  // summary
  double mean_distance = 0.0, max_distance = 0.0, rms_distance = 0.0;
  double accuracy = 0.0;      // target used (the effective one), cloud units
  bool accuracy_met = false;  // every leaf met it
  double requested_accuracy = 0.0;      // the caller's target (absolute or relative), cloud units
  bool requested_accuracy_met = false;  // every leaf met the requested target
  double noise = 0.0;                   // estimated noise deviation sigma along the normal, cloud units
  // The fold measure of the (u,v) (fold_measure.hpp): no connectivity, no trust in the surface.
  // It judges at most 20,000 points of the body, evenly spread over the input order; counts are of those.
  std::size_t judged_points = 0, folded_points = 0, undecided_points = 0, coincident_points = 0;
  std::size_t collapsed_points = 0;  // of the undecided: neighbourhood squeezed in (u,v)
  double folded_share = 0.0;  // folded / decided points
  // Of the judged points, those on a sheet of the surface turned against the cloud
  // (turned_sheets.hpp), and their share of the judged points on the surface the measure
  // gives a normal.
  std::size_t turned_points = 0;
  double turned_share = 0.0;
  std::vector<char> turned;  // per point: 1 for those turned_points (empty until measured)
  /// Passes of the method run (parameterize.hpp): 1, or 2 when the coarse pass ran after the
  /// plain one; `coarse` says that this result is the coarse pass's.
  int passes = 1;
  bool coarse = false;
  /// The points-weighted mean error of the level-1 patches when they were evolved (0 without
  /// any; a leaf's error changes afterwards with its projection and repair): the coarse pass's
  /// first level is compared with the plain pass's on it.
  double first_level_error = 0.0;
  int levels = 0;             // quadtree levels present (1 = root only)
  int iterations = 0;         // grid evolutions over all patches
  int solver = 0;             // the solver that ran (Solver: 0 linear, 1 Ceres)
  std::size_t refined_curves = 0;    // grid sections the Ceres solver refined, all patches
  std::size_t ceres_iterations = 0;  // Ceres iterations over them
  double loss_scale = 0.0;    // the robust loss's scale used, cloud units; 0 without a loss
  double length_scale = 0.0;  // h
  // The inputs checked against each other (input_checks.hpp).
  double boundary_gap = 0.0;    // the boundary's distance to the cloud, in spacings h
  double scale_ratio = 1.0;     // the cloud's size / the boundary's
  double coverage = 1.0;        // share of [0,1]^2 covered by the points' (u,v)
  std::size_t clamped_points = 0;  // points outside the boundary by more than h, clamped onto the domain's edge
  /// Per point: 1 when far outside the cloud's body (cloud_body.hpp): it took the (u,v) of its
  /// nearest point of the body and is left out of the surfaces, the repair and the statistics.
  std::vector<char> outside_body;
  std::size_t far_points = 0;
  /// Per point: 1 when outside the boundary (input_checks.hpp: its foot, before the repair,
  /// lay on the domain's edge more than a spacing h from the surface); all 0 for an empty run.
  std::vector<char> clamped;
  /// Per point: 1 when cropped (Options::crop: clamped or far outside the body): its u, v and
  /// distance are NaN, its patch and level -1, and every statistic, validation and file
  /// leaves it out.
  std::vector<char> cropped;
  std::size_t cropped_points = 0;
  double seconds = 0.0;
  /// Wall-clock time of each stage (their sum is about `seconds`).
  struct StageSeconds {
    double index = 0.0, evolve = 0.0, subdivide = 0.0, parameterize = 0.0, folds = 0.0;
    StageSeconds& operator+=(const StageSeconds& o) {
      index += o.index, evolve += o.evolve, subdivide += o.subdivide, parameterize += o.parameterize, folds += o.folds;
      return *this;
    }
  } stage_seconds;

  /// Whether point i is left out of the statistics and the validation: far outside the
  /// body (its (u,v) is borrowed from a neighbour) or cropped (it has none).
  bool left_out(std::size_t i) const {
    return (i < outside_body.size() && outside_body[i]) || (i < cropped.size() && cropped[i]);
  }
  /// Whether point i was cropped (it has no (u,v)).
  bool is_cropped(std::size_t i) const { return i < cropped.size() && cropped[i]; }
  /// The distances the statistics count (those of points not left_out), in input order.
  std::vector<double> counted_distances() const;
  /// Per point, the PointFlag bits that hold for it.
  std::vector<std::int32_t> point_flags() const;

  std::size_t leaf_count() const;
  /// The leaf whose rectangle contains (u,v); on a seam the one with the larger u (then v)
  /// start, so every (u,v) has exactly one leaf.
  int leaf_at(double u, double v) const;
  /// Surface point (and unit normal) at global (u,v) in [0,1]^2.
  Vec3 evaluate(double u, double v, Vec3* normal = nullptr) const;
  /// The surface's partial derivatives at global (u,v) with respect to u and v (the leaf's
  /// own derivatives scaled by its rectangle's size).
  void derivatives(double u, double v, Vec3& su, Vec3& sv) const;
  /// evaluate() and derivatives() at n global (u,v) (uv: 2n values, each in [0,1]) into the
  /// 3n-value outputs; any output but xyz may be null. Each k is independent, so the result
  /// does not depend on `threads` (as Options::threads).
  void evaluate_many(const double* uv, std::size_t n, double* xyz, double* normal, double* su, double* sv, int threads) const;
};

}  // namespace dbs
