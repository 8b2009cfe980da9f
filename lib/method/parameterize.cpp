#include "parameterize.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <memory>
#include <new>
#include <numeric>
#include <string>

#include "cloud_index.hpp"
#include "coarse_pass.hpp"
#include "corner_frame.hpp"
#include "error.hpp"
#include "evolve.hpp"
#include "fold_measure.hpp"
#include "cloud_body.hpp"
#include "fold_repair.hpp"
#include "input_checks.hpp"
#include "noise_estimate.hpp"
#include "number_text.hpp"
#include "parallel.hpp"
#include "progress.hpp"
#include "repair_snapshot.hpp"
#include "ray_cloud.hpp"
#include "subcloud.hpp"
#include "robust_loss.hpp"
#include "subdivide.hpp"
#include "surface_projection.hpp"
#include "turned_sheets.hpp"
#include "turned_smoothing.hpp"
#include "work_meter.hpp"

namespace dbs {
namespace {

// Share of the progress range given to each phase.
constexpr double kIndexEnd = 0.05;
constexpr double kLevelsEnd = 0.85;
/// Where the fold measure starts in what is left after the levels (parameterize has 0.9).
constexpr double kFoldsShare = 0.95;

/// The noise floor is this safety factor times the mean distance sigma sqrt(2/pi) that a
/// surface on the true surface scores against Gaussian noise sigma.
constexpr double kNoiseFloorFactor = 1.25;
constexpr double kPi = 3.14159265358979323846;
/// The derived scale of the robust loss: this many noise sigmas (a point within it counts
/// as on the surface), but at least one spacing h (a clean cloud still has a scale).
constexpr double kLossScaleSigmas = 3.0;
/// The loss scales accepted, in units of h.
constexpr double kMinLossScale = 1e-6, kMaxLossScale = 1e6;

/// The sizes of clouds and boundaries supported (bounding-box diagonals, in any unit).
constexpr double kMinSize = 1e-100, kMaxSize = 1e75;

/// Most points the fold measure judges (about 0.25 s: the measure takes about 1.2 s per 100k
/// points); a scan of up to this many is judged, and repaired, point by point.
constexpr std::size_t kFoldJudgedPoints = 20000;

// A patch with fewer points than this is not subdivided: its children would have too few
// points to carry a grid.
constexpr std::size_t kMinPointsToSubdivide = 64;
/// Leaves projected together, each on one thread, while their subclouds hold at most this
/// many points in all: their feet are kept (56 bytes a point) until merged in leaf order. A
/// larger leaf is projected alone, its points on all threads.
constexpr std::size_t kLeafBatchPoints = 65536;

using Clock = std::chrono::steady_clock;

/// A number for a message, whatever the host's locale.
std::string format_number(double x) { return significant_text(x, 6); }

double seconds_since(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

/// Progress fraction at the end of quadtree level `level` (levels are not known in advance,
/// so each level gets half of what is left).
double level_progress_end(int level) { return kIndexEnd + (kLevelsEnd - kIndexEnd) * (1.0 - std::pow(0.5, level + 1)); }

/// Thrown by the coarse pass where it gives up (Driver).
struct CoarsePassAbandoned {};

/// The mean error of the patches of `level` among `patches`, each weighted by its points (0
/// without any).
double level_error(const std::vector<Patch>& patches, int level) {
  double sum = 0.0, count = 0.0;
  for (const Patch& p : patches)
    if (p.level == level) {
      sum += p.error * static_cast<double>(p.point_count);
      count += static_cast<double>(p.point_count);
    }
  return count > 0.0 ? sum / count : 0.0;
}

class Driver {
 public:
  /// `coarse`: the coarse pass (coarse_pass.hpp): the root stops growing its grid far above the
  /// target, and the pass is given up (CoarsePassAbandoned) when its first level's error is above
  /// `plain_first_level_error`, the plain pass's, times coarse_abandon_ratio().
  Driver(const PointCloud& cloud, const Boundary& boundary, const Options& options, bool coarse, double plain_first_level_error = 0.0)
      : points_(cloud.points()), boundary_(boundary), options_(options), progress_(options.progress), threads_(resolve_threads(options.threads)),
        plain_first_level_error_(plain_first_level_error) {
    result_.coarse = coarse;
    meter_.set_report([this] { report_work(); });
    // Points far outside the cloud's body (cloud_body.hpp) decide nothing: not the relative
    // target, nor the spacing, nor any surface; they are placed after the others.
    body_ = cloud_body(points_, boundary);
    // The magnitudes supported: within them every product the method forms stays a normal
    // double (tried from 1e-100 to 1e75; 1e100 overflows the fourth powers of some fits).
    for (const auto& [what, size] : {std::pair<const char*, double>{"cloud", body_.diagonal}, {"boundary", boundary.size()}})
      if (size != 0.0 && !(size >= kMinSize && size <= kMaxSize))  // 0: coincident points, refused below
        fail(ErrorCode::OutOfRange, std::string("the ") + what + "'s size (bounding-box diagonal) " + format_number(size) + " is outside the supported range [" +
                                        format_number(kMinSize) + ", " + format_number(kMaxSize) + "]: scale the input");
    result_.outside_body = body_.far;
    result_.far_points = points_.size() - body_.body.size();
    result_.requested_accuracy = options.accuracy > 0.0 ? options.accuracy : options.relative_accuracy * body_.diagonal;
    Patch root{BaseSurface(boundary)};
    if (points_.size() > std::numeric_limits<std::uint32_t>::max()) fail(ErrorCode::OutOfRange, "the cloud has " + std::to_string(points_.size()) + " points; at most 4294967295 are supported");
    root.subcloud.assign(body_.body.begin(), body_.body.end());
    // A cloud without far points is all body: its list of every index is the root's
    // subcloud, and is not kept twice (8 bytes a point at the peak of a large run).
    body_points_ = body_.body.size();
    if (result_.far_points == 0) std::vector<std::size_t>().swap(body_.body);
    result_.patches.push_back(std::move(root));
  }

  Result run() {
    const auto start = Clock::now();
    // The tree's build and the noise estimate's fits (about 20,000).
    begin_stage("index", 0.0, kIndexEnd, index_build_work(body_points_) + 20000);
    // The root's subcloud is the whole cloud in input order, so this index (the same trees as
    // one over that subcloud) also serves the root's evolution and subdivision.
    const IndexBuild build{threads_, &meter_};
    cloud_index_ = result_.far_points == 0 ? std::make_unique<CloudIndex>(points_, build) : std::make_unique<CloudIndex>(points_, body_.body, build);
    const NoiseEstimate noise = estimate_noise(*cloud_index_, threads_, &meter_);
    result_.length_scale = noise.spacing;
    result_.noise = noise.sigma;
    result_.stage_seconds.index = seconds_since(start);
    if (!(result_.length_scale > 0.0)) fail(ErrorCode::Degenerate, "the cloud's points all coincide (length scale 0)");
    check_boundary_against_cloud(*cloud_index_, boundary_, result_.length_scale, checks_);
    warn_or_fail(boundary_warnings(checks_));
    if (result_.far_points > 0) warn({far_points_warning()});
    result_.accuracy = options_.noise_floor ? std::max(result_.requested_accuracy, noise_floor()) : result_.requested_accuracy;
    set_refinement();
    report(kIndexEnd, "index");

    std::vector<int> level_ids{0};
    for (int level = 0; !level_ids.empty(); ++level) {
      level_ids = process_level(level, level_ids);
      result_.levels = level + 1;
    }
    const auto parameterize_start = Clock::now();
    project_across_borders();
    // Judged on the feet, before the repair moves any point.
    check_parameters(result_, checks_);
    warn_or_fail(parameter_warnings(checks_, body_points_, options_.crop != 0));
    choose_cropped();
    result_.stage_seconds.parameterize += seconds_since(parameterize_start);
    // The fold measure judges the result; with the repair on it judges it first for the
    // repair, and again only when the repair moved a point.
    const double levels_end = level_progress_end(result_.levels - 1);
    begin_stage("folds", levels_end + (1.0 - levels_end) * kFoldsShare, 1.0, std::min(points_.size(), kFoldJudgedPoints));
    auto folds_start = Clock::now();
    std::vector<std::size_t> judged;
    FoldMeasure folds = judge_folds(judged);
    result_.stage_seconds.folds = seconds_since(folds_start);
    result_.repaired.assign(points_.size(), 0);
    if (options_.repair) {
      // The narrow repair first; where it moved points and leaves points the measure doubts
      // (or where torn points were all there was), the wide ones from the same start, each
      // kept only when the measure doubts fewer points after it than after the best so far and
      // the mean distance stays at most the unrepaired one (the repair is on by default
      // because it raises neither folds nor fit; fold_repair.hpp). Nothing is saved when there
      // is nothing to repair.
      auto repair_start = Clock::now();
      const std::vector<char> narrow = doubtful_points(result_, points_, judged, folds.state, threads_, &meter_);
      // Torn points are for the wide reaches only: where they are all there is to repair, the
      // narrow repair is skipped and the wide ones start from the unrepaired result.
      const bool narrow_work = repair_has_work(result_, narrow);
      if (narrow_work || folds.torn > 0) {
        const RepairSnapshot unrepaired(result_);
        const double unrepaired_mean = mean_counted_distance();
        const FoldMeasure initial = folds;
        bool moved = narrow_work && repair(narrow);
        result_.stage_seconds.parameterize += seconds_since(repair_start);
        if (moved) {
          folds_start = Clock::now();
          folds = judge_folds(judged);
          result_.stage_seconds.folds += seconds_since(folds_start);
        }
        std::size_t best_doubts = doubted_points(folds);
        // The rings step over the points the measure judged (all, or its sample of a large cloud).
        const int widest = max_wide_rings(judged.empty() ? points_.size() : judged.size(), noise_floor() > result_.requested_accuracy);
        for (int rings = 1; (moved || !narrow_work) && rings <= widest && best_doubts > 0; ++rings) {
          repair_start = Clock::now();
          const RepairSnapshot best(result_);
          unrepaired.restore(result_);
          const bool wide_moved = repair(doubtful_points(result_, points_, judged, initial.state, threads_, &meter_, RepairReach{rings}));
          result_.stage_seconds.parameterize += seconds_since(repair_start);
          if (!wide_moved) {
            best.restore(result_);
            continue;
          }
          folds_start = Clock::now();
          FoldMeasure wide = judge_folds(judged);
          result_.stage_seconds.folds += seconds_since(folds_start);
          const std::size_t doubts = doubted_points(wide);
          if (doubts < best_doubts && mean_counted_distance() <= unrepaired_mean) {
            folds = std::move(wide);
            best_doubts = doubts;
            moved = true;
          } else {
            best.restore(result_);
          }
        }
        if (moved && result_.repaired_points > 0) {
          // The chosen repair's regions untangled (fold_repair.hpp), kept only when neither
          // the mean distance nor the points the measure doubts rise (the repair never raises
          // the fit).
          repair_start = Clock::now();
          const RepairSnapshot tangled(result_);
          const double tangled_mean = mean_counted_distance();
          const Repair untangled = untangle_repaired(result_, points_, threads_);
          if (!untangled.refitted.empty()) {
            const std::vector<std::vector<double>> distances = counted_distances_by_patch();
            for (int id : untangled.refitted) judge_leaf(result_.patches[static_cast<std::size_t>(id)], distances[static_cast<std::size_t>(id)]);
          }
          result_.stage_seconds.parameterize += seconds_since(repair_start);
          if (untangled.repaired > 0) {
            folds_start = Clock::now();
            FoldMeasure straight = judge_folds(judged);
            result_.stage_seconds.folds += seconds_since(folds_start);
            if (mean_counted_distance() <= tangled_mean && doubted_points(straight) <= doubted_points(folds)) folds = std::move(straight);
            else tangled.restore(result_);
          } else if (!untangled.refitted.empty()) {
            tangled.restore(result_);  // every moved point went back: the refits go too
          }
        }
      } else {
        result_.stage_seconds.parameterize += seconds_since(repair_start);
      }
    }
    // The surface under the judged points, against the normals the last judge found; again
    // after a smoothing of its turned sheets that was kept.
    folds_start = Clock::now();
    TurnedSheets turned = turned_sheets(result_, judged, folds, threads_);
    result_.stage_seconds.folds += seconds_since(folds_start);
    if (options_.smooth_turned && turned.turned > 0 && smooth_turned(judged, turned, folds)) {
      folds_start = Clock::now();
      turned = turned_sheets(result_, judged, folds, threads_);
      result_.stage_seconds.folds += seconds_since(folds_start);
    }
    folds_start = Clock::now();
    result_.turned_points = turned.turned;
    result_.turned_share = turned.share;
    result_.turned.assign(points_.size(), 0);
    for (std::size_t i : turned.points) result_.turned[i] = 1;
    result_.stage_seconds.folds += seconds_since(folds_start);
    // The last judge is made: the neighbourhoods kept for the judges go (up to tens of MB).
    judged_neighbourhoods_.reset();
    std::vector<Vec3>().swap(judged_points_);
    place_far_points();
    summarize();
    crop();
    result_.boundary_gap = checks_.boundary_gap;
    result_.scale_ratio = checks_.scale_ratio;
    result_.coverage = checks_.coverage;
    result_.clamped_points = checks_.clamped;
    result_.judged_points = folds.points;
    result_.folded_points = folds.folded;
    result_.undecided_points = folds.undecided;
    result_.collapsed_points = folds.collapsed;
    result_.coincident_points = folds.coincident;
    result_.folded_share = folds.folded_share;
    result_.seconds = seconds_since(start);
    report(1.0, "done");
    return std::move(result_);
  }

 private:
  /// Evolves the patches of one level, subdivides those that missed the target, reports the
  /// level; returns the ids of the next level's patches.
  std::vector<int> process_level(int level, const std::vector<int>& ids) {
    const double begin = level == 0 ? kIndexEnd : level_progress_end(level - 1);
    const double end = level_progress_end(level);
    const auto evolve_start = Clock::now();

    // One index per patch over its subcloud, shared by evolution and subdivision.
    std::vector<std::unique_ptr<CloudIndex>> indices(ids.size());
    std::vector<std::unique_ptr<DirectedProjector>> projectors(ids.size());
    const int outer = std::min<int>(threads_, static_cast<int>(ids.size()));
    EvolveSettings settings;
    settings.accuracy = result_.accuracy;
    settings.initial_grid = options_.initial_grid;
    settings.warm_up_grid = options_.initial_grid - 1;
    settings.max_grid = options_.max_grid;
    settings.gamma = options_.smoothing;
    settings.fit_to_target = options_.fit_to_target != 0;
    settings.refinement = refinement_;
    if (refinement_.enabled && refinement_.loss != LossKind::None) {
      settings.error_loss = refinement_.loss;
      settings.error_loss_scale = result_.loss_scale;
    }
    settings.threads = std::max(1, threads_ / std::max(outer, 1));
    settings.meter = &meter_;
    // A dense patch's rays see an even sample of its points (ray_cloud.hpp).
    std::vector<RayCloud> ray_clouds;
    std::uint64_t expected = 0;
    for (int id : ids) {
      const Patch& patch = result_.patches[id];
      ray_clouds.push_back(ray_cloud(patch.subcloud, result_.length_scale, options_.max_ray_points));
      const std::size_t rays_see = ray_clouds.back().sampled() ? ray_clouds.back().points.size() : patch.subcloud.size();
      expected += evolve_work(rays_see) + (id == 0 && !ray_clouds.back().sampled() ? 0 : index_build_work(rays_see));
    }
    begin_stage("evolve", begin, begin + 0.8 * (end - begin), expected);
    auto will_split = [&](const Patch& p) { return !p.accurate && level < options_.max_level && p.point_count >= kMinPointsToSubdivide; };
    meter_.run(ids.size(), outer, [&](std::size_t k) {
      Patch& patch = result_.patches[ids[k]];
      const bool root = patch.parent < 0;
      RayCloud& rays = ray_clouds[k];
      const IndexBuild build{settings.threads, &meter_};
      if (rays.sampled()) indices[k] = std::make_unique<CloudIndex>(points_, rays.points, build);
      else if (!root) indices[k] = std::make_unique<CloudIndex>(points_, patch.subcloud, build);
      PointList().swap(rays.points);  // the index holds its own copy
      projectors[k] = std::make_unique<DirectedProjector>(indices[k] ? *indices[k] : *cloud_index_, rays.length_scale);
      // Only the root starts far from the cloud, from the Coons patch of its boundary.
      EvolveSettings own = settings;
      // The root is watched for an error far above the target (the coarse pass stops it there),
      // when it can be subdivided.
      if (root && level < options_.max_level && patch.subcloud.size() >= kMinPointsToSubdivide) {
        own.far_above = kCoarseStop;
        own.stop_when_far = result_.coarse;
      }
      if (root) evolve_patch_with_restart(patch, points_, *projectors[k], own);
      else evolve_patch(patch, points_, *projectors[k], own);
      // A leaf's index goes as soon as it is evolved, not with the level's: the level's other
      // patches may still be evolving, and every index held adds to the peak of a large run.
      // A patch to split keeps its index for its middle curves, a few rays, which make the
      // ray columns again two patches at a time: the columns of a level's every patch held
      // until its subdivision raised the peak of the outliers 1M bench by 20 MiB.
      if (!root && !will_split(patch)) {
        projectors[k].reset();
        indices[k].reset();
      } else if (indices[k]) {
        indices[k]->release_ray_columns();
      } else if (cloud_index_) {
        cloud_index_->release_ray_columns();
      }
    });
    // The coarse pass gives up when its children fit worse than the plain pass's did (a coarse
    // root that left a steep wall unreached): folds first, kCoarseAbandonRatio times worse,
    // since a worse fit may still be kept there (coarse_pass.hpp).
    if (level == 1) {
      result_.first_level_error = level_error(result_.patches, 1);
      if (result_.coarse && result_.first_level_error > coarse_abandon_ratio(options_) * plain_first_level_error_) throw CoarsePassAbandoned{};
    }
    for (int id : ids) {
      const Patch& p = result_.patches[id];
      result_.iterations += p.iterations;
      result_.refined_curves += p.refined_curves;
      result_.ceres_iterations += p.ceres_iterations;
    }
    result_.stage_seconds.evolve += seconds_since(evolve_start);
    const auto subdivide_start = Clock::now();

    std::vector<int> split;
    for (std::size_t k = 0; k < ids.size(); ++k) {
      const Patch& p = result_.patches[ids[k]];
      if (will_split(p)) split.push_back(static_cast<int>(k));
    }
    // A patch's index serves its evolution and its middle curves only: a leaf's went after its
    // evolution (the root's, the whole cloud's, goes now when the root is a leaf), a split
    // patch's goes once its curves are made.
    auto release_index = [&](std::size_t k) {
      projectors[k].reset();
      indices[k].reset();
      if (result_.patches[ids[k]].parent < 0) cloud_index_.reset();
    };
    for (std::size_t k = 0, next = 0; k < ids.size(); ++k) {
      if (next < split.size() && static_cast<std::size_t>(split[next]) == k) ++next;
      else release_index(k);
    }
    std::vector<std::unique_ptr<std::array<Patch, 4>>> owned(split.size());
    expected = 0;
    for (int k : split) expected += result_.patches[ids[static_cast<std::size_t>(k)]].subcloud.size();
    begin_stage("subdivide", begin + 0.8 * (end - begin), begin + 0.9 * (end - begin), expected);
    meter_.run(split.size(), std::min<int>(threads_, static_cast<int>(split.size())), [&](std::size_t s) {
      const std::size_t k = static_cast<std::size_t>(split[s]);
      const Patch& parent = result_.patches[ids[k]];
      owned[s] = std::make_unique<std::array<Patch, 4>>(subdivide_patch(parent, *projectors[k], options_.smoothing, options_.initial_grid, refinement_));
      // The middle curves were the index's last use: it goes before the children's lists
      // are made, which lowers the peak of a large run.
      release_index(k);
      std::array<Patch, 4>& quad = *owned[s];
      const std::array<const BaseSurface*, 4> surfaces{{&quad[0].surface, &quad[1].surface, &quad[2].surface, &quad[3].surface}};
      const int inner = std::max(1, threads_ / std::max<int>(1, static_cast<int>(split.size())));
      std::array<PointList, 4> parts = split_subcloud(points_, parent.subcloud, surfaces, options_.subcloud_near, options_.subcloud_own, inner, &meter_);
      for (int c = 0; c < 4; ++c) quad[c].subcloud = std::move(parts[c]);
      // An inner patch no longer needs its points (only leaves parameterize, A2).
      PointList().swap(result_.patches[ids[k]].subcloud);
    });
    projectors.clear();
    indices.clear();
    cloud_index_.reset();
    result_.stage_seconds.subdivide += seconds_since(subdivide_start);

    // The patches that stay leaves parameterize their points now (A2, first part), which also
    // measures each of them on all its points.
    const auto leaves_start = Clock::now();
    expected = 0;
    for (std::size_t k = 0, next = 0; k < ids.size(); ++k) {
      if (next < split.size() && static_cast<std::size_t>(split[next]) == k) ++next;
      else expected += result_.patches[ids[k]].subcloud.size();
    }
    begin_stage("parameterize", begin + 0.9 * (end - begin), end, expected);
    // The points' parameters are made with the first leaves: while the upper levels run, the
    // indices of their patches are alive, and both together would set the peak of the run.
    if (result_.u.empty() && split.size() < ids.size()) start_parameters();
    std::vector<int> leaves;
    for (std::size_t k = 0, next_split = 0; k < ids.size(); ++k) {
      if (next_split < split.size() && static_cast<std::size_t>(split[next_split]) == k) ++next_split;
      else leaves.push_back(ids[k]);
    }
    project_leaves(leaves);
    result_.stage_seconds.parameterize += seconds_since(leaves_start);

    std::vector<int> next;
    for (std::size_t s = 0; s < split.size(); ++s) {
      const int parent_id = ids[static_cast<std::size_t>(split[s])];
      for (int c = 0; c < 4; ++c) {
        Patch child = std::move((*owned[s])[c]);
        child.id = static_cast<int>(result_.patches.size());
        child.parent = parent_id;
        child.level = level + 1;
        result_.patches[parent_id].children[c] = child.id;
        next.push_back(child.id);
        result_.patches.push_back(std::move(child));
      }
    }

    if (options_.on_level) {
      std::vector<const Patch*> view;
      for (int id : ids) view.push_back(&result_.patches[id]);
      if (options_.on_level(level, view)) fail(ErrorCode::Cancelled, "cancelled by the level callback after level " + std::to_string(level));
    }
    report(end, "parameterize");
    return next;
  }

  /// The Ceres refinement's settings (Solver::Ceres only), its loss scale in units of h.
  void set_refinement() {
    result_.solver = static_cast<int>(options_.solver);
    if (options_.solver != Solver::Ceres) return;
    refinement_.enabled = true;
    refinement_.loss = options_.loss;
    refinement_.max_iterations = options_.ceres_max_iterations;
    refinement_.function_tolerance = options_.ceres_function_tolerance;
    const double scale = options_.loss_scale > 0.0 ? options_.loss_scale : std::max(kLossScaleSigmas * result_.noise, result_.length_scale);
    refinement_.loss_scale = scale / result_.length_scale;
    // Far outside the cloud's spacing the loss's squares under- or overflow (NaN errors).
    if (!(refinement_.loss_scale >= kMinLossScale && refinement_.loss_scale <= kMaxLossScale))
      fail(ErrorCode::OutOfRange, "the loss scale " + format_number(scale) + " is outside [1e-6, 1e6] times the cloud's spacing h = " + format_number(result_.length_scale));
    if (options_.loss != LossKind::None) result_.loss_scale = scale;
  }

  /// The fold measure of the result on at most kFoldJudgedPoints points, evenly strided over
  /// the input order (a sparser cloud of the same surface: the measure sizes its
  /// neighbourhoods from the spacing), so that it costs a bounded share of a large run.
  /// The points judged and their neighbourhoods are the same for every judge of one run
  /// (the repair moves only (u,v)): found by the first, kept for the others.
  FoldMeasure judge_folds(std::vector<std::size_t>& judged) {
    // Of the kept points only: `judged` lists them, left empty when they are all the points.
    const PointList& body = kept_;
    const std::size_t n = body.size(), count = std::min(n, kFoldJudgedPoints);
    judged.clear();
    const bool all = n == points_.size() && n <= kFoldJudgedPoints;
    if (!judged_neighbourhoods_) {
      if (!all)
        for (std::size_t k = 0; k < count; ++k) judged_points_.push_back(points_[body[static_cast<std::size_t>(static_cast<unsigned long long>(k) * n / count)]]);
      judged_neighbourhoods_ = std::make_unique<FoldNeighbourhoods>(all ? points_ : judged_points_, result_.noise);
    }
    if (all) return judged_neighbourhoods_->judge(result_.u, result_.v, threads_, &meter_);
    std::vector<double> u, v;
    for (std::size_t k = 0; k < count; ++k) {
      const std::size_t i = body[static_cast<std::size_t>(static_cast<unsigned long long>(k) * n / count)];
      judged.push_back(i);
      u.push_back(result_.u[i]);
      v.push_back(result_.v[i]);
    }
    return judged_neighbourhoods_->judge(u, v, threads_, &meter_);
  }

  /// Algorithm A2, seam-aware: each point is projected onto every leaf whose subcloud holds
  /// it. A foot inside its leaf (an orthogonal projection) is preferred to one clamped to a
  /// leaf's border (better_foot); among feet of one kind the least distance wins (ties: the
  /// lower leaf id, as leaves are visited in id order: level by level, in id order within a
  /// level, which is the order of the ids). A point whose best foot is still clamped is then
  /// projected onto the leaves across the border it was clamped to (the leaves whose
  /// rectangle holds the clamped foot's global (u,v)): near a seam, an apex shared by leaf
  /// corners or a feature the leaf's surface does not reach, its orthogonal foot usually
  /// lies on the neighbour, and snapping it to the border collapses many points onto one
  /// (u,v).
  void start_parameters() {
    const std::size_t n = points_.size();
    // 30 bytes a point of fresh memory: at 1M points its first touch alone took 60 ms, the
    // longest wait between two progress calls of the run; so progress is reported between
    // the arrays.
    result_.u.assign(n, 0.0);
    result_.v.assign(n, 0.0);
    report_work();
    result_.distance.assign(n, std::numeric_limits<double>::infinity());
    report_work();
    result_.patch.assign(n, -1);
    result_.level.assign(n, -1);
    inside_.assign(n, 0);
    report_work();
  }

  /// The first part of A2 for the leaves `ids` (in id order): their subclouds' feet on them,
  /// kept where better; each leaf's mean and max distance (over all its points, replacing the
  /// sample's figures of the evolution) and whether it met the target.
  void project_leaves(const std::vector<int>& ids) {
    std::vector<const PointList*> lists;
    for (int id : ids) lists.push_back(&result_.patches[id].subcloud);
    project_onto_leaves(ids, lists, true);
  }

  /// Projects the points lists[b] onto leaf ids[b], for every b, and offers each foot to
  /// consider(), leaf after leaf in the order of `ids`; with `judge`, each leaf is then judged
  /// on its points' distances (judge_leaf). The many small leaves of a deep quadtree go
  /// several at once, one thread each (a leaf's few points are not worth sharing among
  /// threads, and its projector's samples are made on one), their feet kept until offered in
  /// that order, so a point two leaves hold gets the same foot for every thread count. A leaf
  /// with more points goes alone, its points (distinct, each touching only its own state) on
  /// all threads.
  template <class List>
  void project_onto_leaves(const std::vector<int>& ids, const std::vector<const List*>& lists, bool judge) {
    std::size_t first = 0;
    while (first < ids.size()) {
      std::size_t end = first, batch_points = 0;
      while (end < ids.size() && batch_points + lists[end]->size() <= kLeafBatchPoints) batch_points += lists[end++]->size();
      if (threads_ == 1 || end - first < 2) {
        project_onto_leaf(ids[first], *lists[first], judge);
        ++first;
        continue;
      }
      std::vector<std::vector<Foot>> feet(end - first);
      meter_.run(end - first, threads_, [&](std::size_t b) {
        const List& list = *lists[first + b];
        const Patch& leaf = result_.patches[ids[first + b]];
        SurfaceProjector projector(leaf.surface);
        projector.prepare(list.size());
        feet[b].reserve(list.size());
        for (auto i : list) {
          feet[b].push_back(projector.project(points_[i]));
          meter_.add();
        }
      });
      for (std::size_t b = 0; b < feet.size(); ++b) {
        const List& list = *lists[first + b];
        Patch& leaf = result_.patches[ids[first + b]];
        std::vector<double> distance(feet[b].size());
        for (std::size_t k = 0; k < feet[b].size(); ++k) {
          distance[k] = feet[b][k].distance;
          consider(list[k], leaf, feet[b][k]);
        }
        if (judge) judge_leaf(leaf, distance);
      }
      first = end;
    }
  }

  /// project_onto_leaves for one leaf, its points on all threads. Each foot is offered as it
  /// is found, not kept: a leaf may hold the whole cloud (56 bytes a point kept).
  template <class List>
  void project_onto_leaf(int id, const List& list, bool judge) {
    Patch& leaf = result_.patches[id];
    SurfaceProjector projector(leaf.surface);
    projector.prepare(list.size());
    std::vector<double> distance(list.size());
    // The samples tabulated and the distances allocated: 20 ms at 1M points. Only a leaf too
    // large for a batch (alone for every thread count), so the reports stay the same.
    if (list.size() > kLeafBatchPoints) report_work();
    meter_.run(list.size(), threads_, [&](std::size_t k) {
      const Foot foot = projector.project(points_[list[k]]);
      distance[k] = foot.distance;
      consider(list[k], leaf, foot);
      meter_.add();
    });
    if (judge) judge_leaf(leaf, distance);
  }

  /// A leaf's mean and max distance over `distance` and whether it met the target. Summed in
  /// order, so that the figures do not depend on the thread count. With a robust loss the
  /// target is judged on the loss's error, as during the evolution. Nothing for no distances.
  void judge_leaf(Patch& leaf, const std::vector<double>& distance) const {
    if (distance.empty()) return;
    const bool robust = refinement_.enabled && refinement_.loss != LossKind::None;
    double sum = 0.0, max = 0.0, loss_sum = 0.0;
    for (double d : distance) {
      sum += d;
      max = std::max(max, d);
      if (robust) loss_sum += robust_distance(refinement_.loss, result_.loss_scale, d);
    }
    const double count = static_cast<double>(distance.size());
    leaf.mean_distance = sum / count;
    leaf.max_distance = max;
    leaf.error = robust ? loss_sum / count : leaf.mean_distance;
    leaf.accurate = leaf.error <= result_.accuracy;
  }

  /// The noise floor: a surface lying exactly on the true surface scores a mean distance of
  /// about sigma sqrt(2/pi) against points with Gaussian noise sigma along the normal; a
  /// target below that can only be met by following the noise (leaves tilting, subdividing
  /// to the last level, folds), so it is raised to a safety factor above it.
  double noise_floor() const { return kNoiseFloorFactor * result_.noise * std::sqrt(2.0 / kPi); }

  /// The mean distance of the points the statistics count (summed in index order).
  double mean_counted_distance() const {
    const std::vector<double> counted = result_.counted_distances();
    double sum = 0.0;
    for (double d : counted) sum += d;
    return counted.empty() ? 0.0 : sum / static_cast<double>(counted.size());
  }

  /// Points the fold measure judged folded, collapsed, scrambled or torn: what the repair is for.
  static std::size_t doubted_points(const FoldMeasure& folds) {
    return static_cast<std::size_t>(std::count_if(folds.state.begin(), folds.state.end(), doubted_verdict));
  }

  /// The smoothing of turned sheets (turned_smoothing.hpp) of the result that `folds` judged
  /// on the points `judged`: kept when the mean distance stays within the larger of the one
  /// before and the target used and the run does not stop meeting that target, and `folds`
  /// is then the judge of the smoothed result; undone otherwise. On a sampled cloud every
  /// point takes the verdict (turned or not) and the oriented normal of its nearest judged
  /// point, so that a turned sheet is smoothed whole, not in rings around the sample.
  /// `turned`: the turned sheets under `folds`. True when the smoothing was kept.
  bool smooth_turned(std::vector<std::size_t>& judged, const TurnedSheets& turned, FoldMeasure& folds) {
    auto start = Clock::now();
    std::vector<char> flags(points_.size(), 0);
    std::vector<Vec3> normals;
    if (judged.empty()) {
      for (std::size_t i : turned.points) flags[i] = 1;
      normals = folds.right_normal;
    } else {
      std::vector<std::int8_t> judged_flags(judged.size(), 0);
      std::vector<std::size_t> slot(points_.size(), 0);
      for (std::size_t k = 0; k < judged.size(); ++k) slot[judged[k]] = k;
      for (std::size_t i : turned.points) judged_flags[slot[i]] = 1;
      const std::vector<std::int8_t> spread = spread_from_judged(points_, judged, judged_flags, threads_, &meter_);
      for (std::size_t i = 0; i < points_.size(); ++i) flags[i] = spread[i] != 0 && !result_.left_out(i);
      normals = spread_from_judged(points_, judged, folds.right_normal, threads_, &meter_);
    }
    const RepairSnapshot unsmoothed(result_);
    const double mean_before = mean_counted_distance();
    const bool met_before = all_leaves_accurate();
    const CloudIndex index(points_, IndexBuild{threads_, &meter_});
    const TurnedSmoothing smoothed = smooth_turned_sheets(result_, points_, index, flags, normals, refit_outliers(result_, points_, index, threads_), threads_, &meter_);
    const std::vector<std::vector<double>> distances = counted_distances_by_patch();
    for (int id : smoothed.touched) {
      Patch& leaf = result_.patches[static_cast<std::size_t>(id)];
      const std::vector<double>& own = distances[static_cast<std::size_t>(id)];
      if (!own.empty()) {
        judge_leaf(leaf, own);
      } else {  // every point left it: nothing to miss
        leaf.mean_distance = leaf.max_distance = leaf.error = 0.0;
        leaf.accurate = true;
      }
    }
    result_.stage_seconds.parameterize += seconds_since(start);
    if (smoothed.moved == 0) return false;
    if (!(mean_counted_distance() <= std::max(mean_before, result_.accuracy)) || (met_before && !all_leaves_accurate())) {
      unsmoothed.restore(result_);
      return false;
    }
    result_.smoothed_points = smoothed.moved;
    start = Clock::now();
    folds = judge_folds(judged);
    result_.stage_seconds.folds += seconds_since(start);
    return true;
  }

  /// Whether every leaf met the target used (what summarize() makes DBS_STAT_ACCURACY_MET of).
  bool all_leaves_accurate() const {
    for (const Patch& p : result_.patches)
      if (p.is_leaf() && !p.accurate) return false;
    return true;
  }

  /// The last-resort repair (fold_repair.hpp) of the far points and those flagged in
  /// `suspect` (doubtful_points); the refitted leaves are judged again on the points they
  /// parameterize, at the distances of their new surfaces. True when the repair moved a point.
  bool repair(const std::vector<char>& suspect) {
    const Repair repair = repair_folds(result_, points_, suspect, threads_);
    result_.repaired_points = repair.repaired;
    if (repair.refitted.empty()) return repair.repaired > 0;
    const std::vector<std::vector<double>> distances = counted_distances_by_patch();
    for (int id : repair.refitted) judge_leaf(result_.patches[static_cast<std::size_t>(id)], distances[static_cast<std::size_t>(id)]);
    return repair.repaired > 0;
  }

  /// The second part of A2: points whose best foot is clamped try the leaves across.
  void project_across_borders() {
    const std::size_t n = points_.size();
    std::vector<int> leaves;
    for (const Patch& p : result_.patches)
      if (p.is_leaf()) leaves.push_back(p.id);
    const double begin = level_progress_end(result_.levels - 1);
    // Every point belongs to some leaf's subcloud (A4 never drops one); should one be missed,
    // it is treated like a clamped point: it tries every leaf below.
    std::vector<std::size_t> clamped;
    for (std::size_t i = 0; i < n; ++i)
      if (!inside_[i] && !body_.far[i]) clamped.push_back(i);
    if (clamped.empty()) return;
    if (leaves.size() == 1) {
      std::vector<std::size_t> missed;
      for (std::size_t i : clamped)
        if (result_.patch[i] < 0) missed.push_back(i);
      if (!missed.empty()) project_onto_leaf(leaves[0], missed, false);
      return;
    }
    begin_stage("parameterize", begin + (1.0 - begin) * 0.9, begin + (1.0 - begin) * kFoldsShare, clamped.size());
    // Across the border: each leaf takes the clamped points whose foot lies on its rectangle.
    std::vector<std::vector<std::size_t>> across(result_.patches.size());
    for (std::size_t i : clamped) {
      for (int id : leaves) {
        if (id == result_.patch[i]) continue;
        if (result_.patch[i] < 0 || touches(result_.patches[id].rect, result_.u[i], result_.v[i])) across[id].push_back(i);
      }
    }
    std::vector<int> targets;
    std::vector<const std::vector<std::size_t>*> lists;
    for (int id : leaves)
      if (!across[id].empty()) targets.push_back(id), lists.push_back(&across[id]);
    project_onto_leaves(targets, lists, false);
  }

  /// A rectangle of the domain holding (u,v), its border included (to rounding).
  static bool touches(const Rect& r, double u, double v) {
    constexpr double kSlack = 1e-12;
    return u >= r.u0 - kSlack && u <= r.u1 + kSlack && v >= r.v0 - kSlack && v <= r.v1 + kSlack;
  }

  /// Whether a foot (inside its leaf or not, at `distance`) beats the point's current one. An
  /// inside foot beats a clamped one unless it is much farther (then the point lies on another
  /// sheet of the surface near that leaf, e.g. across a thin wall): more than twice the
  /// clamped distance plus two cloud spacings.
  bool better_foot(std::size_t i, bool inside, double distance) const {
    const double current = result_.distance[i];
    if (result_.patch[i] < 0) return true;
    if (inside == static_cast<bool>(inside_[i])) return distance < current;
    const double margin = 2.0 * result_.length_scale;
    if (inside) return distance <= 2.0 * current + margin;
    return !(current <= 2.0 * distance + margin);
  }

  void consider(std::size_t i, const Patch& leaf, const Foot& foot) {
    if (!better_foot(i, foot.inside, foot.distance)) return;
    const Vec2 uv = leaf.rect.to_global(foot.u, foot.v);
    result_.u[i] = uv.x();
    result_.v[i] = uv.y();
    result_.distance[i] = foot.distance;
    result_.patch[i] = leaf.id;
    result_.level[i] = static_cast<std::int8_t>(leaf.level);
    inside_[i] = foot.inside ? 1 : 0;
  }

  void summarize() {
    // Over the body: a point far outside it would be the whole mean.
    double sum = 0.0, sum2 = 0.0, max = 0.0;
    for (std::size_t i : kept_) {
      const double d = result_.distance[i];
      sum += d;
      sum2 += d * d;
      max = std::max(max, d);
    }
    const double n = static_cast<double>(kept_.size());
    result_.mean_distance = sum / n;
    result_.rms_distance = std::sqrt(sum2 / n);
    result_.max_distance = max;
    result_.accuracy_met = result_.requested_accuracy_met = true;
    for (const Patch& p : result_.patches) {
      if (!p.is_leaf()) continue;
      if (!p.accurate) result_.accuracy_met = false;
      // Judged like `accurate`: with a robust loss, on the loss's error.
      if (!(p.error <= result_.requested_accuracy)) result_.requested_accuracy_met = false;
    }
  }

  /// Work units expected to evolve a patch of `points` points (densified section nodes, about
  /// 2 h apart on sections across the patch, and measured points over its grid sizes), for
  /// the progress fraction only.
  std::uint64_t evolve_work(std::size_t points) const {
    const std::uint64_t steps = static_cast<std::uint64_t>(std::max(1, options_.max_grid - options_.initial_grid + 1));
    const std::uint64_t measured = std::min<std::uint64_t>(points, 2 * EvolveSettings().error_sample);
    const std::uint64_t per_section = std::min<std::uint64_t>(512, static_cast<std::uint64_t>(std::sqrt(static_cast<double>(points))) / 2 + 2);
    const std::uint64_t nodes = 2 * static_cast<std::uint64_t>(options_.max_grid) * per_section;
    return steps * (measured + nodes);
  }

  /// Reports `fraction` of `stage` (through the test probe too).
  void report(double fraction, const char* stage) {
    if (options_.work_probe) options_.work_probe(stage, meter_.done());
    progress_.report(fraction, stage);
  }

  /// Points far outside the body take the (u,v), patch and level of their nearest point of
  /// the body, and their distance to the surface there (finite: no squares).
  void place_far_points() {
    if (result_.far_points == 0 || options_.crop) return;  // cropped: they get no (u,v)
    const CloudIndex body(points_, body_.body);
    // Queried from as far away as the body reaches, in the point's direction: squares of
    // the point's own distance may overflow.
    Box3 body_box;
    for (std::size_t i : body_.body) body_box.extend(points_[i]);
    const Vec3 centre = 0.5 * (body_box.min + body_box.max);
    const double reach = kFarOutside * std::max(body_box.diagonal(), boundary_.size());
    for (std::size_t i = 0; i < points_.size(); ++i) {
      if (!body_.far[i]) continue;
      const Vec3 away = points_[i] - centre;
      const double length = away.stableNorm();
      const Vec3 query = length > reach ? Vec3(centre + away * (reach / length)) : points_[i];
      const std::size_t j = body.nearest(query);
      result_.u[i] = result_.u[j];
      result_.v[i] = result_.v[j];
      result_.patch[i] = result_.patch[j];
      result_.level[i] = result_.level[j];
      result_.distance[i] = (points_[i] - result_.evaluate(result_.u[i], result_.v[i])).stableNorm();
    }
  }

  /// The warning for points far outside the body, with the farthest distance.
  std::string far_points_warning() const {
    double farthest = 0.0;
    const Vec3 centre = 0.5 * (boundary_.bounds().min + boundary_.bounds().max);
    for (std::size_t i = 0; i < points_.size(); ++i)
      if (body_.far[i]) farthest = std::max(farthest, (points_[i] - centre).stableNorm());
    return std::to_string(result_.far_points) + " point(s) lie far outside the cloud (beyond " + format_number(kFarOutside) +
           " times its extent; the farthest " + significant_text(farthest, 3) +
           " from the boundary's centre): left out of the target, the spacing, the surfaces and the distance statistics, " +
           (options_.crop ? "and cropped" : "each takes the (u,v) of its nearest point");
  }

  /// Per patch, the distances of the points it parameterizes that the statistics count (not
  /// far outside the body, not cropped), in input order.
  std::vector<std::vector<double>> counted_distances_by_patch() const {
    std::vector<std::vector<double>> distances(result_.patches.size());
    for (std::size_t i = 0; i < points_.size(); ++i)
      if (result_.patch[i] >= 0 && !result_.left_out(i)) distances[static_cast<std::size_t>(result_.patch[i])].push_back(result_.distance[i]);
    return distances;
  }

  /// The points to crop (Options::crop): those outside the boundary and those far outside
  /// the body; the rest are kept_. Their (u,v) stay until crop(): the repair's fill may lean
  /// on them as fixed neighbours, but it neither moves them nor fits surfaces to them.
  void choose_cropped() {
    const std::size_t n = points_.size();
    result_.cropped.assign(n, 0);
    if (options_.crop) {
      for (std::size_t i = 0; i < n; ++i) result_.cropped[i] = result_.clamped[i] || body_.far[i];
      result_.cropped_points = static_cast<std::size_t>(std::count(result_.cropped.begin(), result_.cropped.end(), 1));
    }
    auto kept = [&](std::size_t i) { return !body_.far[i] && !result_.cropped[i]; };
    std::size_t count = 0;
    for (std::size_t i = 0; i < n; ++i) count += kept(i);
    kept_.clear();
    kept_.reserve(count);  // sized first: a list of every point, grown by doubling, held two at its peak
    for (std::size_t i = 0; i < n; ++i)
      if (kept(i)) kept_.push_back(static_cast<std::uint32_t>(i));
    if (kept_.empty())
      fail(ErrorCode::Degenerate, "all " + std::to_string(n) + " points lie outside the boundary (more than a point spacing from the surface at the domain's edge) and were cropped: is it the boundary of this cloud?");
    if (result_.cropped_points > 0) judge_leaves_on_kept_points();
  }

  /// Each leaf judged again on the kept points it parameterizes: its figures, and whether it
  /// (and the run) met the target, are not those of points it has no (u,v) for. A leaf left
  /// with none has nothing to miss.
  void judge_leaves_on_kept_points() {
    const std::vector<std::vector<double>> distances = counted_distances_by_patch();
    for (Patch& leaf : result_.patches) {
      if (!leaf.is_leaf()) continue;
      const std::vector<double>& own = distances[static_cast<std::size_t>(leaf.id)];
      if (own.empty()) {
        leaf.mean_distance = leaf.max_distance = leaf.error = 0.0;
        leaf.accurate = true;
      } else {
        judge_leaf(leaf, own);
      }
    }
  }

  /// Cropped points lose their (u,v), distance, patch and level.
  void crop() {
    constexpr double kNone = std::numeric_limits<double>::quiet_NaN();
    for (std::size_t i = 0; i < points_.size(); ++i) {
      if (!result_.cropped[i]) continue;
      result_.u[i] = result_.v[i] = result_.distance[i] = kNone;
      result_.patch[i] = result_.level[i] = -1;
    }
  }

  /// Each message to the warning callback; with Options::strict the first fails the run.
  void warn_or_fail(const std::vector<std::string>& messages) const {
    if (options_.strict && !messages.empty()) fail(ErrorCode::Degenerate, "strict input checks: " + messages.front());
    warn(messages);
  }

  /// Each message to the warning callback, if any (on the calling thread).
  void warn(const std::vector<std::string>& messages) const {
    if (!options_.warning) return;
    for (const std::string& m : messages) options_.warning(m.c_str());
  }

  /// A stage running from fraction `begin` to `end`, expected to take `expected_units` of
  /// work: reported now, and by report_work() after every WorkMeter::kDefaultReportEvery units.
  void begin_stage(const char* stage, double begin, double end, std::uint64_t expected_units) {
    stage_ = stage;
    stage_begin_ = begin;
    stage_end_ = end;
    stage_units_start_ = meter_.done();
    stage_units_expected_ = std::max<std::uint64_t>(expected_units, 1);
    report(begin, stage);
  }

  /// The work meter's report: the current stage, its fraction estimated from the work done.
  void report_work() {
    const double done = static_cast<double>(meter_.done() - stage_units_start_) / static_cast<double>(stage_units_expected_);
    report(stage_begin_ + (stage_end_ - stage_begin_) * std::min(0.95, done), stage_);
  }

  const std::vector<Vec3>& points_;
  const Boundary& boundary_;
  const Options& options_;
  InputChecks checks_;
  CloudBody body_;
  Progress progress_;
  WorkMeter meter_;
  std::unique_ptr<CloudIndex> cloud_index_;  // the whole cloud's, until the root is split
  std::vector<Vec3> judged_points_;          // judge_folds' points when they are not all of them ...
  std::unique_ptr<FoldNeighbourhoods> judged_neighbourhoods_;  // ... and their neighbourhoods
  const char* stage_ = "index";
  double stage_begin_ = 0.0, stage_end_ = 0.0;
  std::uint64_t stage_units_start_ = 0, stage_units_expected_ = 1;
  int threads_;
  double plain_first_level_error_ = 0.0;
  Result result_;
  RefinementSettings refinement_;
  std::vector<char> inside_;  // per point: its foot lies inside its leaf (A2)
  PointList kept_;                 // the body less the cropped points, increasing
  std::size_t body_points_ = 0;    // body_.body's size (the list itself is dropped when it is every point)
};

/// `options` for one pass of parameterize(): its progress reported from `begin` on (the
/// fraction f of the pass as begin + (1 - begin) f; a pass's own "done" is not passed on, the
/// run's is reported once at the end) and the last fraction it passed on kept in `*last`. Its
/// warnings go to `held` when given (the coarse pass's: passed on only if it is kept), else to
/// the caller, unless an earlier pass gave the same message (`given` records them).
Options pass_options(const Options& options, double begin, double* last, std::vector<std::string>& given, std::vector<std::string>* held = nullptr) {
  Options pass = options;
  if (options.progress)
    pass.progress = [&options, begin, last](double fraction, const char* stage) {
      if (std::string(stage) == "done") return false;
      *last = begin + (1.0 - begin) * fraction;
      return options.progress(*last, stage);
    };
  if (options.warning)
    pass.warning = [&options, &given, held](const char* message) {
      if (held) {
        held->emplace_back(message);
        return;
      }
      if (std::find(given.begin(), given.end(), message) != given.end()) return;
      given.emplace_back(message);
      options.warning(message);
    };
  return pass;
}

}  // namespace

Result parameterize(const PointCloud& cloud, const Boundary& boundary, const Options& options) {
  if (options.solver == Solver::Ceres && !ceres_available()) fail(ErrorCode::Unsupported, "the Ceres solver is not available: this libdbs was built without Ceres");
  std::vector<std::string> given;
  double last = 0.0;
  Result plain = Driver(cloud, boundary, pass_options(options, 0.0, &last, given), false).run();
  // The coarse pass only where the plain one pleated: its root ended far above the target (and
  // was subdivided) and a share of the points lies on turned sheets.
  const bool pleated = coarse_pass_wanted(options, plain);
  Result* kept = &plain;
  Result coarse;
  if (pleated) {
    const auto start = std::chrono::steady_clock::now();
    std::vector<std::string> held;
    // The plain pass already passed (or failed) the strict checks of the inputs: the coarse
    // pass, a second opinion, neither fails on them nor on anything but a cancel.
    Options second = pass_options(options, last, &last, given, &held);
    second.strict = 0;
    try {
      coarse = Driver(cloud, boundary, second, true, plain.first_level_error).run();
      if (coarse_is_better(options, plain, coarse)) kept = &coarse;
    } catch (const CoarsePassAbandoned&) {
    } catch (const Error& e) {
      if (e.code() == ErrorCode::Cancelled) throw;
    } catch (const std::bad_alloc&) {
    }
    if (kept != &coarse) coarse.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    // The kept pass's warnings only (those of the plain pass were given as it ran).
    if (kept == &coarse && options.warning)
      for (const std::string& message : held)
        if (std::find(given.begin(), given.end(), message) == given.end()) {
          given.push_back(message);
          options.warning(message.c_str());
        }
    // Both passes' time counts: a dropped or abandoned coarse pass's as evolution.
    const Result& other = kept == &coarse ? plain : coarse;
    kept->passes = 2;
    kept->seconds += other.seconds;
    if (kept == &coarse) kept->stage_seconds += other.stage_seconds;
    else kept->stage_seconds.evolve += other.seconds;
  }
  if (options.progress && options.progress(1.0, "done")) fail(ErrorCode::Cancelled, "cancelled by the progress callback during \"done\"");
  return std::move(*kept);
}

}  // namespace dbs
