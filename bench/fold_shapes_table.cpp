// The fold table of the fold-free work (issue 10): the analytic hard shapes of
// tests/support/fold_shapes.hpp (known parameters, reference triangles used only for scoring)
// parameterized by dbs_parameterize through the public C API with default options, and by the
// meshless reference (Floater-Reimers, k = 12 inverse-distance weights, one sparse solve).
//
// Columns: points; reference triangles; quadtree levels and patches; folded reference
// triangles (signed (u,v) area negative or below 1e-3 of the median: inverted + collapsed) and
// their share; the reference-free fold measure of the library (DBS_STAT_FOLDED_POINTS and, since 0.4, + DBS_STAT_COLLAPSED_POINTS;
// _SHARE, "n/a" with a dbs.h or library older than 0.3); mean point-to-surface distance and the
// target used (DBS_STAT_ACCURACY); the result surface's distance to the truth, mean over the
// points of dist(S(u_i,v_i), noise-free surface); wall time of dbs_parameterize; then the same
// reference folds and time for the meshless reference; last, the points on a turned sheet:
// those on the surface (within 10 times the target and a spacing) where its own normal Su x Sv
// at the point's (u,v) points against the noise-free surface's normal at its true (a,b). A
// pleated base surface can carry points in the right order (no folded triangle) on a sheet
// turned over: its normals, a mesh of S over the domain and a fit to S are then wrong there
// (libraries before 0.4 lack the derivatives: n/a); and the library's own count of them, which
// needs no truth (DBS_STAT_TURNED_*). The bench repeats the library's "on the surface" rule
// (beyond_repair_reach) from the statistics, as it sees the C API only.
//
// usage: dbs-bench-folds [--shape NAME[,NAME...]] [--threads N] [--max-level N] [--repair 0|1] [--smooth-turned 0|1] [--coarse-pass 0|1|2] [--fit-to-target 0|1] [--solver linear|ceres] [--density F] [--noise F] [--save DIR]
// --noise F adds Gaussian noise along the normal, sigma F times the diagonal (a noisy shape
// keeps its own where larger): the hard shapes as a scanner sees them.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "bench_arguments.hpp"
#include "dbs.h"
#include "fold_shapes.hpp"
#include "meshless_reference.hpp"

namespace {

using dbs_folds::FoldCount;
using dbs_folds::FoldShape;

[[noreturn]] void usage_error(const std::string& message) {
  std::fprintf(stderr, "dbs-bench-folds: %s\nusage: dbs-bench-folds [--shape NAME[,NAME...]] [--threads N] [--max-level N] [--repair 0|1] [--smooth-turned 0|1] [--coarse-pass 0|1|2] [--fit-to-target 0|1] [--solver linear|ceres] [--density F] [--noise F] [--save DIR]\nshapes:", message.c_str());
  for (const std::string& name : dbs_folds::fold_shape_names()) std::fprintf(stderr, " %s", name.c_str());
  std::fprintf(stderr, "\n");
  std::exit(2);
}

int parse_int(const std::string& option, const std::string& text) { return bench::parse_small_int(option, text, usage_error); }

struct Settings {
  std::vector<std::string> shapes = dbs_folds::fold_shape_names();
  int threads = -1;    // -1: the library's default
  int max_level = -1;  // -1: the library's default
  int repair = -1;     // -1: the library's default (DBS_OPT_REPAIR)
  int smooth_turned = -1;  // -1: the library's default (DBS_OPT_SMOOTH_TURNED)
  int coarse_pass = -1;    // -1: the library's default (DBS_OPT_COARSE_PASS)
  int fit_to_target = -1;  // -1: the library's default (DBS_OPT_FIT_TO_TARGET)
  int solver = -1;     // -1: the library's default (DBS_OPT_SOLVER)
  std::string save_dir;  // non-empty: each shape's cloud and boundary are written there
  double density = 1.0;  // points as a multiple of each shape's usual 4,000 or so
  double noise = 0.0;    // Gaussian noise along the normal, sigma relative to the diagonal
};

Settings parse_arguments(int argc, char** argv) {
  Settings settings;
  for (int i = 1; i < argc; ++i) {
    std::string arg = argv[i];
    if (arg == "-h" || arg == "--help") usage_error("folds of dbs_parameterize on the analytic hard shapes");
    if (i + 1 >= argc) usage_error(arg + (arg.rfind("--", 0) == 0 ? " needs a value" : ": unknown argument"));
    std::string value = argv[++i];
    if (arg == "--shape") {
      settings.shapes.clear();
      std::stringstream list(value);
      std::string item;
      const std::vector<std::string> known = dbs_folds::fold_shape_names();
      while (std::getline(list, item, ',')) {
        bool found = false;
        for (const std::string& name : known) found = found || name == item;
        if (!found) usage_error("--shape: unknown shape '" + item + "'");
        settings.shapes.push_back(item);
      }
      if (settings.shapes.empty()) usage_error("--shape needs at least one shape");
    } else if (arg == "--threads") {
      settings.threads = parse_int(arg, value);
    } else if (arg == "--max-level") {
      settings.max_level = parse_int(arg, value);
    } else if (arg == "--repair") {
      settings.repair = parse_int(arg, value);
    } else if (arg == "--smooth-turned") {
      settings.smooth_turned = parse_int(arg, value);
    } else if (arg == "--coarse-pass") {
      settings.coarse_pass = parse_int(arg, value);
    } else if (arg == "--fit-to-target") {
      settings.fit_to_target = parse_int(arg, value);
    } else if (arg == "--density") {
      settings.density = bench::parse_number(arg, value, [](double x) { return x > 0.0 && x <= 1000.0; }, "a number in (0, 1000]", usage_error);
    } else if (arg == "--noise") {
      settings.noise = bench::parse_number(arg, value, [](double x) { return x >= 0.0 && x <= 0.05; }, "a number in [0, 0.05]", usage_error);
    } else if (arg == "--save") {
      settings.save_dir = value;
    } else if (arg == "--solver") {
      if (value == "linear") settings.solver = DBS_SOLVER_LINEAR;
      else if (value == "ceres") settings.solver = DBS_SOLVER_CERES;
      else usage_error("--solver: '" + value + "' is not a solver (linear or ceres)");
    } else {
      usage_error("unknown option '" + arg + "'");
    }
  }
  return settings;
}

std::string percent(const FoldCount& count) {
  char text[32];
  std::snprintf(text, sizeof text, "%.2f%%", 100.0 * count.share);
  return text;
}

std::string folds(const FoldCount& count) {
  char text[64];
  std::snprintf(text, sizeof text, "%zu (%zu+%zu)", count.folded, count.inverted, count.collapsed);
  return text;
}

/// One row for dbs_parameterize; false (and the message in `error`) when a call failed.
struct Run {
  bool ok = false;
  std::string error;
  FoldCount folds;
  double levels = 0, patches = 0, mean_distance = 0, accuracy = 0, to_truth = 0, seconds = 0;
  std::string reference_free = "n/a";  // the library's own fold measure, points (share)
  std::string turned = "n/a";          // points on a sheet turned against the truth (share)
  std::string reference_free_turned = "n/a";  // the library's own count (DBS_STAT_TURNED_*)
  std::string stages = "n/a";                  // "index / evolve / subdivide / project / folds" seconds
};

/// "count (share%)", share in [0,1].
std::string count_with_share(double count, double share) {
  char text[48];
  std::snprintf(text, sizeof text, "%.0f (%.2f%%)", count, 100.0 * share);
  return text;
}

/// The points whose result surface normal (su x sv, 3 doubles a point each) points against
/// the noise-free surface's normal at their true parameters, as "count (share%)" of the points
/// on the surface where the noise-free normal is defined. A point farther from the surface
/// (`distance`) than `reach` has no sheet under it and is not judged (the library's rule: 10
/// times the target and a spacing). A zero or NaN su x sv counts as turned: it has no
/// orientation to keep.
std::string turned_points(const FoldShape& shape, const std::vector<double>& su, const std::vector<double>& sv, const std::vector<double>& distance, double reach) {
  std::size_t turned = 0, judged = 0;
  for (std::size_t i = 0; i < shape.count(); ++i) {
    if (distance[i] > reach) continue;
    const dbs_folds::Point3 truth = dbs_folds::surface_normal(shape.surface, shape.uv_true[2 * i], shape.uv_true[2 * i + 1]);
    if (truth[0] == 0.0 && truth[1] == 0.0 && truth[2] == 0.0) continue;  // singular there
    const double* a = &su[3 * i];
    const double* b = &sv[3 * i];
    const double n[3] = {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
    ++judged;
    if (!(n[0] * truth[0] + n[1] * truth[1] + n[2] * truth[2] > 0.0)) ++turned;
  }
  return count_with_share(static_cast<double>(turned), judged > 0 ? static_cast<double>(turned) / static_cast<double>(judged) : 0.0);
}

/// A count of the library's statistic `count_id` and its share `share_id` of the judged points,
/// as "count (share%)"; "n/a" when the library does not give them.
std::string count_and_share(const dbs_result* result, int32_t count_id, int32_t share_id) {
  double count = 0.0, share = 0.0;
  if (dbs_result_stat(result, count_id, &count) != DBS_OK || dbs_result_stat(result, share_id, &share) != DBS_OK) return "n/a";
  return count_with_share(count, share);
}

/// Writes the shape as DIR/NAME.xyz (with the true parameters as two further columns, which
/// readers ignore) and DIR/NAME_boundary.txt (docs/FORMATS.md), so that dbs-param can run on
/// it (--report pictures) and a script can score it, and DIR/NAME_triangles.txt (the reference
/// triangles, three 0-based point indices a line, counter-clockwise in the true parameters);
/// false when a file cannot be written.
bool save_shape(const FoldShape& shape, const std::string& dir) {
  const std::string cloud_path = dir + "/" + shape.name + ".xyz", boundary_path = dir + "/" + shape.name + "_boundary.txt";
  std::FILE* cloud = std::fopen(cloud_path.c_str(), "w");
  if (!cloud) return false;
  std::fprintf(cloud, "# %s: %s; noise along the normal, sigma %.6g\n# x y z, then the true parameters a b (ignored by dbs-param); point i + %zu j is node (i, j) of the jittered grid\n", shape.name.c_str(), shape.description.c_str(), shape.noise_sigma, shape.grid_a);
  for (std::size_t k = 0; k < shape.count(); ++k)
    std::fprintf(cloud, "%.17g %.17g %.17g %.17g %.17g\n", shape.xyz[3 * k], shape.xyz[3 * k + 1], shape.xyz[3 * k + 2], shape.uv_true[2 * k], shape.uv_true[2 * k + 1]);
  const bool cloud_ok = std::fclose(cloud) == 0;
  std::FILE* boundary = std::fopen(boundary_path.c_str(), "w");
  if (!boundary) return false;
  const std::pair<const char*, const std::vector<double>*> sides[] = {{"bottom", &shape.bottom}, {"right", &shape.right}, {"top", &shape.top}, {"left", &shape.left}};
  for (const auto& [name, points] : sides) {
    std::fprintf(boundary, "%s\n", name);
    for (std::size_t i = 0; i + 2 < points->size(); i += 3) std::fprintf(boundary, "%.17g %.17g %.17g\n", (*points)[i], (*points)[i + 1], (*points)[i + 2]);
  }
  const bool boundary_ok = std::fclose(boundary) == 0;
  std::FILE* triangles = std::fopen((dir + "/" + shape.name + "_triangles.txt").c_str(), "w");
  if (!triangles) return false;
  for (std::size_t t = 0; t < shape.triangle_count(); ++t)
    std::fprintf(triangles, "%d %d %d\n", shape.triangles[3 * t], shape.triangles[3 * t + 1], shape.triangles[3 * t + 2]);
  return std::fclose(triangles) == 0 && boundary_ok && cloud_ok;
}

double stat(const dbs_result* result, int32_t id) {
  double value = std::nan("");
  dbs_result_stat(result, id, &value);
  return value;
}

Run run_dbs(const FoldShape& shape, const dbs_options* options) {
  Run run;
  const std::size_t per_side = shape.bottom.size() / 3;
  dbs_cloud* cloud = nullptr;
  dbs_boundary* boundary = nullptr;
  dbs_result* result = nullptr;
  int status = dbs_cloud_create(shape.xyz.data(), shape.count(), &cloud);
  if (status == DBS_OK) {
    status = dbs_boundary_create(shape.bottom.data(), per_side, shape.right.data(), shape.right.size() / 3, shape.top.data(), shape.top.size() / 3,
                                 shape.left.data(), shape.left.size() / 3, &boundary);
  }
  if (status == DBS_OK) {
    const auto start = std::chrono::steady_clock::now();
    status = dbs_parameterize(cloud, boundary, options, &result);
    run.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  }
  std::vector<double> uv(2 * shape.count()), on_surface(3 * shape.count());
  if (status == DBS_OK) status = dbs_result_uv(result, uv.data(), shape.count());
#if DBS_VERSION_NUMBER >= 400
  std::vector<double> su(3 * shape.count()), sv(3 * shape.count());
  if (status == DBS_OK) status = dbs_result_evaluate_many(result, uv.data(), shape.count(), on_surface.data(), nullptr, su.data(), sv.data());
  std::vector<double> distance(shape.count());
  if (status == DBS_OK) status = dbs_result_distances(result, distance.data(), shape.count());
  if (status == DBS_OK) run.turned = turned_points(shape, su, sv, distance, std::max(10.0 * stat(result, DBS_STAT_ACCURACY), stat(result, DBS_STAT_LENGTH_SCALE)));
#else
  for (std::size_t i = 0; status == DBS_OK && i < shape.count(); ++i) status = dbs_result_evaluate(result, uv[2 * i], uv[2 * i + 1], &on_surface[3 * i], nullptr);
#endif
  if (status != DBS_OK) {
    run.error = std::string(dbs_status_string(status)) + ": " + dbs_last_error_message();
  } else {
    run.ok = true;
    run.folds = dbs_folds::fold_share(uv, shape.triangles);
    run.levels = stat(result, DBS_STAT_LEVELS);
    run.patches = stat(result, DBS_STAT_PATCHES);
    run.mean_distance = stat(result, DBS_STAT_MEAN_DISTANCE);
    run.accuracy = stat(result, DBS_STAT_ACCURACY);
    run.to_truth = dbs_folds::mean_distance_to_surface(shape, on_surface);
#ifdef DBS_STAT_FOLDED_SHARE
    run.reference_free = count_and_share(result, DBS_STAT_FOLDED_POINTS, DBS_STAT_FOLDED_SHARE);
#endif
#ifdef DBS_STAT_SECONDS_FOLDS
    char stages[96];
    std::snprintf(stages, sizeof stages, "%.2f / %.2f / %.2f / %.2f / %.2f", stat(result, DBS_STAT_SECONDS_INDEX), stat(result, DBS_STAT_SECONDS_EVOLVE), stat(result, DBS_STAT_SECONDS_SUBDIVIDE),
                  stat(result, DBS_STAT_SECONDS_PARAMETERIZE), stat(result, DBS_STAT_SECONDS_FOLDS));
    run.stages = stages;
#endif
#ifdef DBS_STAT_TURNED_POINTS
    run.reference_free_turned = count_and_share(result, DBS_STAT_TURNED_POINTS, DBS_STAT_TURNED_SHARE);
#endif
#ifdef DBS_STAT_COLLAPSED_POINTS
    double collapsed = 0.0;
    if (dbs_result_stat(result, DBS_STAT_COLLAPSED_POINTS, &collapsed) == DBS_OK) {
      char text[32];
      std::snprintf(text, sizeof text, " + %.0f collapsed", collapsed);
      run.reference_free += text;
    }
#endif
  }
  dbs_result_destroy(result);
  dbs_boundary_destroy(boundary);
  dbs_cloud_destroy(cloud);
  return run;
}

}  // namespace

int main(int argc, char** argv) {
  const Settings settings = parse_arguments(argc, argv);
  dbs_options* options = nullptr;
  if (dbs_options_create(&options) != DBS_OK) {
    std::fprintf(stderr, "dbs-bench-folds: dbs_options_create failed: %s\n", dbs_last_error_message());
    return EXIT_FAILURE;
  }
  if (settings.threads >= 0) dbs_options_set_int(options, DBS_OPT_THREADS, settings.threads);
  if (settings.max_level >= 0) dbs_options_set_int(options, DBS_OPT_MAX_LEVEL, settings.max_level);
  if (settings.repair >= 0 && dbs_options_set_int(options, DBS_OPT_REPAIR, settings.repair) != DBS_OK) usage_error(std::string("--repair: ") + dbs_last_error_message());
#ifdef DBS_OPT_SMOOTH_TURNED
  if (settings.smooth_turned >= 0 && dbs_options_set_int(options, DBS_OPT_SMOOTH_TURNED, settings.smooth_turned) != DBS_OK) usage_error(std::string("--smooth-turned: ") + dbs_last_error_message());
#else
  if (settings.smooth_turned > 0) usage_error("--smooth-turned: this libdbs has no DBS_OPT_SMOOTH_TURNED");
#endif
#ifdef DBS_OPT_COARSE_PASS
  if (settings.coarse_pass >= 0 && dbs_options_set_int(options, DBS_OPT_COARSE_PASS, settings.coarse_pass) != DBS_OK) usage_error(std::string("--coarse-pass: ") + dbs_last_error_message());
#else
  if (settings.coarse_pass > 0) usage_error("--coarse-pass: this libdbs has no DBS_OPT_COARSE_PASS");
#endif
#ifdef DBS_OPT_FIT_TO_TARGET
  if (settings.fit_to_target >= 0 && dbs_options_set_int(options, DBS_OPT_FIT_TO_TARGET, settings.fit_to_target) != DBS_OK) usage_error(std::string("--fit-to-target: ") + dbs_last_error_message());
#else
  if (settings.fit_to_target > 0) usage_error("--fit-to-target: this libdbs has no DBS_OPT_FIT_TO_TARGET");
#endif
  if (settings.solver >= 0 && dbs_options_set_int(options, DBS_OPT_SOLVER, settings.solver) != DBS_OK) usage_error(std::string("--solver: ") + dbs_last_error_message());
  int32_t max_level = 0, threads = 0, repair = 0, solver = 0;
  dbs_options_get_int(options, DBS_OPT_SOLVER, &solver);
  double relative_accuracy = 0.0;
  dbs_options_get_int(options, DBS_OPT_REPAIR, &repair);
  int32_t smooth_turned = 0, coarse_pass = 0, fit_to_target = 0;
#ifdef DBS_OPT_FIT_TO_TARGET
  dbs_options_get_int(options, DBS_OPT_FIT_TO_TARGET, &fit_to_target);
#endif
#ifdef DBS_OPT_SMOOTH_TURNED
  dbs_options_get_int(options, DBS_OPT_SMOOTH_TURNED, &smooth_turned);
#endif
#ifdef DBS_OPT_COARSE_PASS
  dbs_options_get_int(options, DBS_OPT_COARSE_PASS, &coarse_pass);
#endif
  dbs_options_get_int(options, DBS_OPT_MAX_LEVEL, &max_level);
  dbs_options_get_int(options, DBS_OPT_THREADS, &threads);
  dbs_options_get_double(options, DBS_OPT_RELATIVE_ACCURACY, &relative_accuracy);

  std::printf("libdbs %s, max level %d, relative accuracy %g, threads %s, repair %s, smoothing of turned sheets %s, coarse pass %s, fit to the target %s, solver %s, noise %g of the diagonal\n", dbs_version_string(), max_level, relative_accuracy,
              threads == 0 ? "all" : std::to_string(threads).c_str(), repair ? "on" : "off", smooth_turned ? "on" : "off", coarse_pass == 0 ? "off" : coarse_pass == 2 ? "on, fit first" : "on, folds first", fit_to_target ? "on" : "off", solver == DBS_SOLVER_CERES ? "ceres" : "linear", settings.noise);
  std::printf("folds: reference triangles whose signed (u,v) area is negative or below 1e-3 of the median, as inverted+collapsed;\n"
              "to truth: mean distance of the result surface at each point's (u,v) to the noise-free surface;\n"
              "turned: points on the result surface where its normal Su x Sv points against the noise-free surface's; ref.-free turned: the library's count;\n"
              "stages: the seconds of time (s) by stage, index / evolve / subdivide / project (with the repair and the smoothing) / folds (the fold measure)\n\n");
  std::printf("| shape | points | triangles | levels | patches | folds | folds %% | ref.-free folds | mean distance | target | to truth | time (s) | meshless folds | meshless %% | meshless time (s) | turned | ref.-free turned | stages (s) |\n");
  std::printf("|-------|-------:|----------:|-------:|--------:|------:|--------:|----------------:|--------------:|-------:|---------:|---------:|---------------:|-----------:|------------------:|-------:|-----------------:|-----------:|\n");
  std::fflush(stdout);
  int failures = 0;
  for (const std::string& name : settings.shapes) {
    const FoldShape shape = dbs_folds::fold_shape(name, settings.density, settings.noise);
    if (!settings.save_dir.empty() && !save_shape(shape, settings.save_dir)) {
      std::fprintf(stderr, "dbs-bench-folds: cannot write %s into %s\n", shape.name.c_str(), settings.save_dir.c_str());
      return EXIT_FAILURE;
    }
    const Run run = run_dbs(shape, options);
    std::string meshless_folds = "n/a", meshless_share = "n/a", meshless_time = "n/a";
    try {
      const dbs_folds::MeshlessReference reference = dbs_folds::meshless_reference(shape);
      const FoldCount count = dbs_folds::fold_share(reference.uv, shape.triangles);
      meshless_folds = folds(count);
      meshless_share = percent(count);
      char text[32];
      std::snprintf(text, sizeof text, "%.2f", reference.seconds);
      meshless_time = text;
    } catch (const std::exception& e) {
      meshless_folds = std::string("error: ") + e.what();
    }
    if (run.ok) {
      std::printf("| %s | %zu | %zu | %.0f | %.0f | %s | %s | %s | %.3g | %.3g | %.3g | %.2f | %s | %s | %s | %s | %s | %s |\n", shape.name.c_str(), shape.count(), shape.triangle_count(),
                  run.levels, run.patches, folds(run.folds).c_str(), percent(run.folds).c_str(), run.reference_free.c_str(), run.mean_distance, run.accuracy, run.to_truth, run.seconds,
                  meshless_folds.c_str(), meshless_share.c_str(), meshless_time.c_str(), run.turned.c_str(), run.reference_free_turned.c_str(), run.stages.c_str());
    } else {
      ++failures;
      std::printf("| %s | %zu | %zu | error: %s | | | | | | | | %.2f | %s | %s | %s | | | |\n", shape.name.c_str(), shape.count(), shape.triangle_count(), run.error.c_str(),
                  run.seconds, meshless_folds.c_str(), meshless_share.c_str(), meshless_time.c_str());
    }
    std::fflush(stdout);
  }
  dbs_options_destroy(options);
  return failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
