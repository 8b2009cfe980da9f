#include "evolve.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "fit_to_target.hpp"
#include "grid_projection.hpp"
#include "meshless_seed.hpp"
#include "parallel.hpp"
#include "robust_loss.hpp"
#include "surface_projection.hpp"

namespace dbs {

namespace {

/// Grid projections at one grid size while the pleat guard keeps damping some nodes.
constexpr int kMaxDampedSteps = 4;

/// The pilot measurement of a growing grid: about this many points of the error sample ...
constexpr std::size_t kPilotPoints = 512;
/// ... and the grid grows unmeasured when their error is above this x the target. A pilot
/// that misjudges (its points hold several times their share of far points) costs a grid
/// one growth more, never a target reported met that is not.
constexpr double kPilotMargin = 3.0;

/// measure_distances with a bound to stop above: the rounds, every kStopRounds[r]-th point of
/// the sample not measured yet (a sample smaller than the first is measured whole).
constexpr std::array<std::size_t, 5> kStopRounds{{16, 8, 4, 2, 1}};

/// The smallest grid that moves a node (3 x 3: one interior node).
constexpr int kMinWarmUpGrid = 3;

/// evolve_patch_with_restart: a patch ending more than this times above the target is evolved
/// again from the coarsest warm-up, and still that far above after it, from the meshless seed
/// (10 before the noisy caps of dbs-bench-folds: the noise floor raises the target, and a
/// 300-degree cap with noise of 0.25% of its diagonal ended 6.1 times above it, its median 1.4
/// times, unwrapped; of the clean hard shapes' roots only the three that the median spares
/// end higher: the fingers 6.9, the mushroom 24, the tall dome 25; the open box 4.3) ...
constexpr double kCoarseRestartFactor = 5.0;
/// ... which is kept where its error is below this times the first one's (the 300-degree cap:
/// 0.03-0.18; where both wrap the cloud: 0.70-0.99).
constexpr double kCoarseRestartGain = 0.5;

/// evolve_patch_with_restart: the restarts are for a cloud the surface has not reached for
/// the most part; where the median distance of its points is at most this times the target,
/// most of the cloud lies on the surface and only a feature stands off it (an overhanging
/// cap, a tall dome: medians of 0.02-0.17 times the target on the hard shapes of
/// dbs-bench-folds, where every restart was evolved and then dropped; the sphere caps whose
/// restarts were kept: 3.9-230 times).
constexpr double kUnreachedMedian = 1.0;

/// The median distance to `patch`'s surface of about kPilotPoints points of its subcloud
/// (evenly strided).
double median_distance(const Patch& patch, const std::vector<Vec3>& points, const EvolveSettings& settings) {
  const std::size_t n = patch.subcloud.size();
  if (n == 0) return 0.0;
  const std::size_t stride = std::max<std::size_t>(1, n / kPilotPoints);
  const SurfaceProjector projector(patch.surface, FootPrecision::Measure);
  std::vector<double> distance((n + stride - 1) / stride);
  metered_for(settings.meter, distance.size(), settings.threads, [&](std::size_t k) {
    distance[k] = projector.project(points[patch.subcloud[k * stride]]).distance;
    count_work(settings.meter);
  });
  const auto middle = distance.begin() + static_cast<std::ptrdiff_t>(distance.size() / 2);
  std::nth_element(distance.begin(), middle, distance.end());
  return *middle;
}

/// Grid projections of `patch` at one grid size: where the pleat guard held nodes back, the
/// surface moves on from where it got to, along its new normals, up to kMaxDampedSteps
/// times: an overhang or a steep wall is reached in a few damped steps instead of being
/// pleated over (pleat_guard.hpp).
void project_damped(Patch& patch, int grid, const DirectedProjector& projector, const EvolveSettings& settings, RefinementCounts& counts) {
  for (int step = 0; step < kMaxDampedSteps; ++step) {
    std::size_t damped = 0;
    Grid projected = project_grid(patch.surface, grid, grid, projector, settings.gamma, &damped, settings.refinement, &counts, settings.threads, settings.meter);
    patch.surface = BaseSurface(patch.surface.boundary(), projected);
    patch.grid = std::move(projected);
    ++patch.iterations;
    patch.damped_nodes += damped;
    if (damped == 0) break;
  }
}

}  // namespace

void measure_distances(const BaseSurface& surface, const std::vector<Vec3>& points, const PointList& indices, std::size_t stride, int threads, double& out_mean, double& out_max,
                       LossKind loss, double loss_scale, double* out_loss_mean, WorkMeter* meter) {
  if (indices.empty()) {
    out_mean = out_max = 0.0;
    if (out_loss_mean) *out_loss_mean = 0.0;
    return;
  }
  const SurfaceProjector projector(surface, FootPrecision::Distance);
  measure_distances(projector, points, indices, stride, threads, out_mean, out_max, loss, loss_scale, out_loss_mean, meter);
}

void measure_distances(const SurfaceProjector& projector, const std::vector<Vec3>& points, const PointList& indices, std::size_t stride, int threads, double& out_mean,
                       double& out_max, LossKind loss, double loss_scale, double* out_loss_mean, WorkMeter* meter, std::vector<Vec2>* feet, std::size_t feet_step,
                       double stop_above, bool* out_stopped, double* out_measured_error) {
  stride = std::max<std::size_t>(stride, 1);
  const std::size_t count = (indices.size() + stride - 1) / stride;
  out_mean = 0.0;
  out_max = 0.0;
  if (out_loss_mean) *out_loss_mean = 0.0;
  if (out_stopped) *out_stopped = false;
  if (count == 0) return;
  std::vector<double> distance(count);
  auto measure = [&](std::size_t k) {
    const Vec3& q = points[indices[k * stride]];
    if (feet) {
      // Each point writes only its own foot.
      Vec2& start = (*feet)[k * feet_step];
      const Foot foot = std::isnan(start.x()) ? projector.project(q) : projector.project_from(q, start);
      start = Vec2(foot.u, foot.v);
      distance[k] = foot.distance;
    } else {
      distance[k] = projector.project(q).distance;
    }
    count_work(meter);
  };
  // The figures over the points measured (all of them when `measured` is null), each point
  // counted in index order so that they do not depend on the thread count; a point left
  // unmeasured counts as 0. Returns the error the target is judged on.
  auto settle = [&](const std::vector<char>* measured) {
    double sum = 0.0, loss_sum = 0.0, max = 0.0;
    std::size_t measured_count = 0;
    for (std::size_t k = 0; k < count; ++k) {
      if (measured && !(*measured)[k]) continue;
      ++measured_count;
      sum += distance[k];
      if (out_loss_mean) loss_sum += robust_distance(loss, loss_scale, distance[k]);
      max = std::max(max, distance[k]);
    }
    out_mean = sum / static_cast<double>(count);
    out_max = max;
    if (out_loss_mean) *out_loss_mean = loss_sum / static_cast<double>(count);
    if (out_measured_error) *out_measured_error = (out_loss_mean ? loss_sum : sum) / static_cast<double>(std::max<std::size_t>(measured_count, 1));
    return out_loss_mean ? *out_loss_mean : out_mean;
  };
  if (!std::isfinite(stop_above) || count < kStopRounds.front()) {
    metered_for(meter, count, threads, measure);
    settle(nullptr);
    return;
  }
  // In rounds over the sample interleaved (every kStopRounds[0]-th point first, then the ones
  // halfway between, ...), each spread over the whole patch. The errors are never negative
  // and are summed in index order, as the whole sample's would be: the rounded sum of all of
  // them is at least that of the measured ones (rounding is monotone), so once the measured
  // ones' error is above stop_above, the whole sample's is too, and the others are left
  // unmeasured: the decision is the one the whole measurement takes, and the figures are
  // lower bounds. The rounds do not depend on the thread count.
  std::vector<char> measured(count, 0);
  for (std::size_t step : kStopRounds) {
    std::vector<std::size_t> round;
    for (std::size_t k = 0; k < count; k += step)
      if (!measured[k]) round.push_back(k), measured[k] = 1;
    metered_for(meter, round.size(), threads, [&](std::size_t r) { measure(round[r]); });
    if (step == 1) break;
    if (settle(&measured) > stop_above) {
      if (out_stopped) *out_stopped = true;
      return;
    }
  }
  settle(nullptr);
}

void evolve_patch(Patch& patch, const std::vector<Vec3>& points, const DirectedProjector& projector, const EvolveSettings& settings, const EvolveTick& tick) {
  patch.point_count = patch.subcloud.size();
  patch.iterations = 0;
  patch.damped_nodes = 0;
  patch.refined_curves = 0;
  patch.ceres_iterations = 0;
  patch.solver = settings.refinement.enabled ? 1 : 0;
  patch.error = 0.0;
  patch.far_above = false;
  if (patch.subcloud.empty()) {
    patch.mean_distance = patch.max_distance = 0.0;
    patch.accurate = true;
    return;
  }
  const std::size_t stride = std::max<std::size_t>(1, patch.subcloud.size() / std::max<std::size_t>(settings.error_sample, 1));
  const bool robust = settings.error_loss != LossKind::None;
  double mean = 0.0, max = 0.0, loss_mean = 0.0;
  RefinementCounts counts;
  double error = 0.0;
  // Whether the last measurement covered the whole sample on the last surface (its largest
  // grid's, measured without a bound): only then are all of `feet` on that surface.
  bool measured_whole = false;
  // Each sample point's foot on the last surface it was measured on: the surface moves
  // little from one grid to the next, so the descent starts there (NaN: not measured yet).
  std::vector<Vec2> feet;
  // The coarser grids first, unmeasured (EvolveSettings::warm_up_grid).
  for (int grid = std::max(settings.warm_up_grid, kMinWarmUpGrid); settings.warm_up_grid > 0 && grid < settings.initial_grid; ++grid) project_damped(patch, grid, projector, settings, counts);
  for (int grid = settings.initial_grid;; ++grid) {
    project_damped(patch, grid, projector, settings, counts);
    const SurfaceProjector surface_projector(patch.surface, FootPrecision::Measure);
    // A grid that can still grow is first judged on a pilot of about kPilotPoints of the
    // sample: far above the target, it grows without the whole sample being measured.
    const std::size_t sampled = (patch.subcloud.size() + stride - 1) / stride;
    if (feet.size() != sampled) feet.assign(sampled, Vec2(std::nan(""), std::nan("")));
    if (grid < settings.max_grid && sampled >= 2 * kPilotPoints) {
      double pilot_mean = 0.0, pilot_max = 0.0, pilot_loss = 0.0;
      measure_distances(surface_projector, points, patch.subcloud, stride * (sampled / kPilotPoints), settings.threads, pilot_mean, pilot_max, settings.error_loss,
                        settings.error_loss_scale, robust ? &pilot_loss : nullptr, settings.meter, &feet, sampled / kPilotPoints);
      const double pilot_error = robust ? pilot_loss : pilot_mean;
      if (settings.far_above > 0.0 && pilot_error > settings.far_above * settings.accuracy) {
        patch.far_above = true;
        if (settings.stop_when_far) {
          mean = pilot_mean;
          max = pilot_max;
          error = pilot_error;
          if (tick) tick(grid);
          break;
        }
      }
      if (pilot_error > kPilotMargin * settings.accuracy) {
        if (tick) tick(grid);
        continue;
      }
    }
    // A grid that can still grow needs only to know whether it met the target: its
    // measurement stops once it is certainly above it.
    double measured_error = 0.0;
    measure_distances(surface_projector, points, patch.subcloud, stride, settings.threads, mean, max, settings.error_loss, settings.error_loss_scale, robust ? &loss_mean : nullptr,
                      settings.meter, &feet, 1, grid < settings.max_grid ? settings.accuracy : std::numeric_limits<double>::infinity(), nullptr, &measured_error);
    error = robust ? loss_mean : mean;
    measured_whole = grid >= settings.max_grid;
    if (tick) tick(grid);
    if (error <= settings.accuracy || grid >= settings.max_grid) break;
    if (settings.far_above > 0.0 && measured_error > settings.far_above * settings.accuracy) {
      patch.far_above = true;
      if (settings.stop_when_far) {
        // The figures of a measurement cut short are lower bounds: the error and mean become
        // the estimate from the points measured, comparable with a pilot's or a full one's.
        error = measured_error;
        if (!robust) mean = measured_error;
        break;
      }
    }
  }
  // A patch stopped far above the target (stop_when_far) has only part of its feet on its
  // surface and is not fitted.
  if (settings.fit_to_target && measured_whole) fit_to_target(patch, points, stride, feet, settings, mean, max, error);
  // The sample's figures; a patch that stays a leaf is measured on all its points by the
  // projection of its subcloud (A2), which computes those distances anyway.
  patch.mean_distance = mean;
  patch.max_distance = max;
  patch.refined_curves = counts.curves;
  patch.ceres_iterations = counts.iterations;
  patch.error = error;
  patch.accurate = error <= settings.accuracy;
}

void evolve_patch_with_restart(Patch& patch, const std::vector<Vec3>& points, const DirectedProjector& projector, const EvolveSettings& settings) {
  // The start without the subcloud (the root's is the whole cloud): each candidate borrows
  // the patch's for its evolution.
  PointList subcloud;
  subcloud.swap(patch.subcloud);
  const Patch start = patch;
  subcloud.swap(patch.subcloud);
  evolve_patch(patch, points, projector, settings);
  // Far above the target with most of the cloud unreached (the median is measured once: a
  // restart is only tried from the first evolution's verdict).
  auto far_above = [&] { return !patch.accurate && patch.error > kCoarseRestartFactor * settings.accuracy; };
  const bool unreached = far_above() && median_distance(patch, points, settings) > kUnreachedMedian * settings.accuracy;
  auto evolve_from = [&](Patch& candidate, const EvolveSettings& candidate_settings) {
    candidate.subcloud.swap(patch.subcloud);
    evolve_patch(candidate, points, projector, candidate_settings);
    candidate.subcloud.swap(patch.subcloud);
  };
  // The work of both counts (iterations, damped nodes, Ceres); the kept one's surface and
  // figures stand.
  auto keep_better = [&](Patch& other) {
    Patch& kept = other.error < kCoarseRestartGain * patch.error ? other : patch;
    const Patch& dropped = &kept == &other ? patch : other;
    kept.iterations += dropped.iterations;
    kept.damped_nodes += dropped.damped_nodes;
    kept.refined_curves += dropped.refined_curves;
    kept.ceres_iterations += dropped.ceres_iterations;
    kept.far_above = kept.far_above || dropped.far_above;
    kept.restarts = patch.restarts + 1;
    if (&kept != &other) return;
    other.subcloud.swap(patch.subcloud);
    patch = std::move(other);
  };
  if (!unreached) return;
  if (settings.warm_up_grid > 0 && settings.initial_grid > kMinWarmUpGrid + 1) {
    Patch coarse = start;
    EvolveSettings from_coarse = settings;
    from_coarse.warm_up_grid = kMinWarmUpGrid;
    evolve_from(coarse, from_coarse);
    keep_better(coarse);
  }
  if (!far_above()) return;
  Patch seeded = start;
  seeded.subcloud.swap(patch.subcloud);
  bool seeds = false;
  try {
    seeds = seed_from_meshless_map(seeded, points, settings.initial_grid, settings.meter);
  } catch (...) {
    seeded.subcloud.swap(patch.subcloud);  // a cancel: the patch keeps its subcloud
    throw;
  }
  seeded.subcloud.swap(patch.subcloud);
  if (!seeds) return;
  EvolveSettings from_seed = settings;
  from_seed.warm_up_grid = 0;  // the seed lies on the cloud already
  evolve_from(seeded, from_seed);
  keep_better(seeded);
}

}  // namespace dbs
