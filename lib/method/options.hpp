// Options of a parameterization run, their defaults and their documented ranges.
#pragma once
#include <functional>
#include <vector>

#include "ray_cloud.hpp"
#include "robust_loss.hpp"

namespace dbs {

struct Patch;

enum class Solver { Linear = 0, Ceres = 1 };

/// Progress observer: fraction in [0,1], stage name; returns true to cancel.
using ProgressFn = std::function<bool(double fraction, const char* stage)>;
/// Level observer: called once per finished quadtree level with that level's patches;
/// returns true to cancel.
using LevelFn = std::function<bool(int level, const std::vector<const Patch*>& patches)>;
/// Warning observer: one line naming a likely mistake in the inputs (input_checks.hpp).
using WarningFn = std::function<void(const char* message)>;

struct Options {
  double accuracy = 0.0;            // absolute mean-distance target; 0 = use relative_accuracy
  double relative_accuracy = 1e-3;  // fraction of the cloud's box diagonal (CornerFrameBox)
  int max_level = 4;
  int initial_grid = 5;
  int max_grid = 11;
  double smoothing = 0.5;           // gamma of eq. (6)
  Solver solver = Solver::Linear;
  int threads = 0;                  // 0 = hardware concurrency
  double subcloud_near = 0.25;
  double subcloud_own = 0.05;
  /// 1: the accuracy target is raised to the noise floor (what a surface on the true surface
  /// would score against the cloud's estimated noise); 0: the target is used as given.
  int noise_floor = 1;
  /// 1: the last-resort repair of points the surfaces never reached (fold_repair.hpp); on by
  /// default since it refits the leaves it repairs (0.4): folds and mean distance fall or stay
  /// on every shape of dbs-bench-folds and every cloud of dbs-bench.
  int repair = 1;
  /// 1: the (u,v) of points on turned sheets and around them are smoothed and their leaves
  /// refitted (turned_smoothing.hpp), kept when the mean distance stays within the larger of
  /// the one before and the target: fewer folds for more points on turned sheets, so off by
  /// default.
  int smooth_turned = 0;
  /// Where the plain pass pleated, a second pass from a coarse root, and the better result
  /// kept (coarse_pass.hpp): 1 folds first, 2 fit first; 0: the plain pass only.
  int coarse_pass = 1;
  /// 1: a patch whose largest grid misses the target is fitted to its sample at their feet
  /// and stays a leaf where that comes within 0.85 times it (fit_to_target.hpp); 0: eq. (5)'s
  /// projections alone.
  int fit_to_target = 1;
  /// The Ceres refinement (curve_refinement.hpp), used with Solver::Ceres only: the robust
  /// loss, its scale in cloud units (0 = derived from the cloud: 3 sigma of its estimated
  /// noise, at least one spacing h), iterations per curve and the function tolerance.
  LossKind loss = LossKind::None;
  double loss_scale = 0.0;
  int ceres_max_iterations = 25;
  double ceres_function_tolerance = 1e-6;
  /// Neighbourhood of the outline of dbs_boundary_detect and dbs_boundary_from_corners
  /// (outline.hpp): the nearest points a point's angular gap is judged on.
  int outline_neighbours = 24;
  /// 1: points outside the boundary (Result::clamped) are cropped: no (u,v), distance, patch
  /// or level (NaN and -1), left out of the fold measure, the repair, the statistics, the
  /// validation and the files; 0: they keep their foot clamped onto the domain's edge.
  int crop = 0;
  /// 1: a gross mismatch of cloud and boundary (any warning of input_checks.hpp but the
  /// clamped points when they are cropped) fails the run with ErrorCode::Degenerate.
  int strict = 0;
  ProgressFn progress;
  LevelFn on_level;
  WarningFn warning;
  /// For tests: called before each progress report with its stage and the work units
  /// (points projected, grid nodes solved) counted so far in the run.
  std::function<void(const char* stage, unsigned long long units)> work_probe;
  /// For tests: a patch's rays see at most about this many of its points (ray_cloud.hpp).
  std::size_t max_ray_points = kMaxRayPoints;
};

/// Option identifiers; values equal the DBS_OPT_* numbers of the C API.
enum class OptionId {
  Accuracy = 0,
  RelativeAccuracy = 1,
  MaxLevel = 2,
  InitialGrid = 3,
  MaxGrid = 4,
  Smoothing = 5,
  Solver = 6,
  Threads = 7,
  SubcloudNear = 8,
  SubcloudOwn = 9,
  NoiseFloor = 10,
  Repair = 11,
  Loss = 12,
  LossScale = 13,
  CeresMaxIterations = 14,
  CeresFunctionTolerance = 15,
  OutlineNeighbours = 16,
  Crop = 17,
  Strict = 18,
  SmoothTurned = 19,
  CoarsePass = 20,
  FitToTarget = 21,
};

struct OptionInfo {
  const char* name;  // e.g. "max_level"
  bool is_integer;
  double min;
  double max;
};

/// Name, type and range of an option; throws Error(InvalidArgument) for an unknown id.
OptionInfo option_info(int id);
/// Sets an option after checking type and range (including the cross-option rules
/// initial_grid <= max_grid and subcloud_own <= subcloud_near); throws Error(OutOfRange)
/// naming the option, the value and the range, Error(NonFinite) for NaN/Inf,
/// Error(InvalidArgument) for an unknown id or a real value for an integer option,
/// Error(Unsupported) for the Ceres solver in a build without Ceres.
void set_option(Options& options, int id, double value);
/// Current value of an option as a double.
double get_option(const Options& options, int id);

}  // namespace dbs
