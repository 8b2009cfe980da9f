// Evolution of one dynamic base surface (A1.6 for a single patch): project a grid on the
// current surface onto the cloud, interpolate it, measure the mean distance of the patch's
// subcloud, and grow the grid by one row and one column until the target is met or the grid
// reaches its maximum size.
#pragma once
#include <limits>
#include <functional>
#include <vector>

#include "curve_refinement.hpp"
#include "directed_projection.hpp"
#include "patch.hpp"
#include "surface_projection.hpp"
#include "work_meter.hpp"

namespace dbs {

struct EvolveSettings {
  double accuracy = 0.0;        // mean-distance target, cloud units
  int initial_grid = 5;
  int max_grid = 11;
  /// 0, or the first of the coarser grids projected (unmeasured, from this size up to
  /// initial_grid - 1, at least 3) before the first measured one; the driver projects one,
  /// initial_grid - 1, on every patch. The root starts from the Coons patch of its boundary,
  /// which can lie far from the cloud (a sphere cap closing over a small rim): with 5 x 5
  /// nodes at once its nodes cross, the pleat guard holds most of them back and the surface
  /// never wraps the cloud (270-degree cap, one patch without the repair: mean distance
  /// 0.017-0.047 at three densities against 0.004-0.005 from a 4 x 4 start, 3.2-8.0% folded
  /// against 0.04-0.11%). A
  /// child starts from its parent's surface sampled on its quarter; a coarser projection
  /// first smooths that sample towards its subcloud (on dbs-bench-folds: fewer folds on
  /// five of the six shapes).
  int warm_up_grid = 0;
  double gamma = 0.5;
  int threads = 1;              // for the distance measurement inside one patch
  /// The error that decides whether to grow the grid (and whether the patch met the
  /// target) is measured on about this many evenly strided subcloud points (between this
  /// and twice as many; all of them in a smaller subcloud): the standard error of such a
  /// mean is a few percent of it, and measuring costs a small share of a projection step.
  std::size_t error_sample = 4096;
  /// Counts a unit per densified grid node projected and per point measured (may be null).
  WorkMeter* meter = nullptr;
  /// The Ceres refinement of the grid projection (off: the linear solve alone).
  RefinementSettings refinement;
  /// The error that decides (grow the grid, subdivide, accurate) is the mean of each point's
  /// robust_distance under this loss and scale (cloud units), so that gross outliers do not
  /// force subdivision; LossKind::None: the plain mean distance.
  LossKind error_loss = LossKind::None;
  double error_loss_scale = 0.0;
  /// 0, or a factor F: a patch whose error at a grid is above F times the target is marked
  /// (Patch::far_above) and, with stop_when_far, stops growing its grid there, left to be
  /// subdivided (parameterize.hpp: the coarse pass, the root only). Without stop_when_far
  /// the evolution is the one without the factor.
  double far_above = 0.0;
  bool stop_when_far = false;
  /// A patch whose grid stops growing above the target (but within kFitReach times it) is
  /// fitted to its sample at their feet, kept where that comes clearly below the target
  /// (kFitMargin of it, fit_to_target.hpp).
  bool fit_to_target = true;
};

/// Called after each grid evolution with the grid size reached; may throw to cancel.
using EvolveTick = std::function<void(int grid)>;

/// Evolves `patch` (surface, subcloud set) against `projector` (which indexes the subcloud).
/// Sets surface, grid, iterations, point_count, mean/max distance (plain distances, of the
/// sample), the refinement counts and accurate (the error of EvolveSettings::error_loss within
/// the target). A patch with no points keeps its surface (nothing to fit) and counts as accurate.
void evolve_patch(Patch& patch, const std::vector<Vec3>& points, const DirectedProjector& projector, const EvolveSettings& settings, const EvolveTick& tick = {});

/// evolve_patch for the root, which starts from the Coons patch of its boundary; where it
/// ends far above the target (more than kCoarseRestartFactor times it) with most of its cloud
/// unreached (the median distance of about 512 of its points above the target: where a
/// feature alone stands off the surface, an overhanging cap or a tall dome, no restart did
/// better, and the two cost the 10,201-point mushroom a tenth of its run), again from other
/// starts, each kept where its error is below kCoarseRestartGain times the best so far (the
/// work of all counts in the iterations, damped nodes and Ceres figures; `restarts` counts
/// the starts tried):
/// - warmed up from the coarsest grid (3 x 3). On a cloud closing over a small rim (a
///   300-degree sphere cap) grids warmed up from one size below the first cross over the rim
///   and never wrap it (mean distance 0.17-0.28), while a single interior node first lifts the
///   surface towards the far pole and the finer grids inflate it from there (0.009-0.031).
///   Where both starts wrap the cloud their errors differ by a few percent and the finer
///   start is kept (the coarse one, 2-15% nearer on the mushroom and the cone, folds more
///   after subdivision);
/// - still far above: the meshless seed (meshless_seed.hpp; only with the boundary on the
///   cloud and its border), for a cloud closing over a smaller rim still (330 degrees: the
///   root's error 0.74-0.83 from either warm-up, 0.003-0.019 from the seed; 300 degrees at
///   10,000 points: 0.24 and 0.18 from the warm-ups, 0.0045 from the seed).
void evolve_patch_with_restart(Patch& patch, const std::vector<Vec3>& points, const DirectedProjector& projector, const EvolveSettings& settings);

/// Mean and maximum distance of points[indices[k]] (k strided by `stride`) to `surface`;
/// deterministic for any thread count. `out_loss_mean`, when given, receives the mean of
/// robust_distance(loss, loss_scale, d) over the same points; `meter` (may be null) counts a
/// unit per point.
void measure_distances(const BaseSurface& surface, const std::vector<Vec3>& points, const PointList& indices, std::size_t stride, int threads, double& out_mean, double& out_max,
                       LossKind loss = LossKind::None, double loss_scale = 0.0, double* out_loss_mean = nullptr, WorkMeter* meter = nullptr);
/// The same with a projector onto the surface (FootPrecision::Distance or Measure), built once for
/// several measurements of one surface. With `feet`, the k-th point measured starts its descent
/// from (*feet)[k * feet_step] (from the nearest sample where that is NaN) and leaves its foot
/// there. With a finite `stop_above`, the measurement stops as soon as the error (the mean
/// distance, or the loss's mean when out_loss_mean is given) is certainly above it: the
/// figures are then lower bounds (the points left unmeasured count as 0, their feet stay as
/// they were) and `out_stopped`, when given, is set; the figures of a measurement that did not
/// stop are those of one without the bound. `out_measured_error`, when given, receives the error
/// over the points measured only (their mean, not a lower bound): after a stop, an estimate of
/// the whole sample's from the evenly spread rounds measured; otherwise the error itself.
void measure_distances(const SurfaceProjector& projector, const std::vector<Vec3>& points, const PointList& indices, std::size_t stride, int threads, double& out_mean,
                       double& out_max, LossKind loss = LossKind::None, double loss_scale = 0.0, double* out_loss_mean = nullptr, WorkMeter* meter = nullptr,
                       std::vector<Vec2>* feet = nullptr, std::size_t feet_step = 1, double stop_above = std::numeric_limits<double>::infinity(), bool* out_stopped = nullptr,
                       double* out_measured_error = nullptr);

}  // namespace dbs
