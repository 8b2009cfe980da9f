// The libdbs benchmark: parameterizes height-field clouds of random points on the unit square,
// bounded by the square's sides, and prints a table per surface with one row per size: points,
// wall time of dbs_parameterize and of each of its stages, peak memory, iterations, levels,
// patches, leaves, mean distance.
//
// Three surfaces: "smooth", z = 0.2 sin(pi x) sin(pi y), which one base surface fits,
// "rippled", the same plus 0.01 sin(16 pi x) sin(16 pi y), whose ripples are finer than the largest
// grid of one patch can follow, so the recursive method has to subdivide, and "outliers", the
// smooth surface with every 50th point (2%) moved 0.1 (10% of the size) up or down, a scan's gross
// outliers. "clean mean" is the mean distance of the other points (of all points on the first two).
// --solver and --loss choose the curve-projection solver (DBS_OPT_SOLVER, DBS_OPT_LOSS).
//
// usage: dbs-bench [--surface smooth|rippled|outliers|both|all] [--sizes 10k,100k,1M] [--threads N]
//                  [--max-level N] [--relative-accuracy F] [--solver linear|ceres]
//                  [--loss none|huber|cauchy|soft_l1] [--repair 0|1] [--cancel-trials N]
//
// With --cancel-trials N, a second table per surface gives how soon the library answers its
// progress callback: the longest silence between two calls, and the median and largest time
// from a cancel (asked at N moments spread evenly over a run) to dbs_parameterize's return.
//
// Peak memory is the rise of the process's peak resident set (VmHWM, reset per size through
// /proc/self/clear_refs where the kernel allows it) over the resident set before the cloud is
// handed to the library: it covers the library's copy of the cloud and the whole run.
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "bench_arguments.hpp"
#include "cancel_latency.hpp"
#include "dbs.h"

namespace {

constexpr double kPi = 3.14159265358979323846;

// splitmix64: a fixed, portable sequence so every run benchmarks the same clouds.
class Random {
 public:
  explicit Random(std::uint64_t seed) : state_(seed) {}
  double uniform() { return static_cast<double>(next() >> 11) * 0x1.0p-53; }

 private:
  std::uint64_t next() {
    std::uint64_t z = (state_ += 0x9e3779b97f4a7c15ULL);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
  }
  std::uint64_t state_;
};

struct Surface {
  const char* name;
  const char* formula;
  double ripple;  // amplitude of the 0.01-scale ripples; 0 = smooth
  int outlier_every;  // every n-th point moved 0.1 off the surface; 0 = none
};

bool is_outlier(const Surface& surface, std::size_t i) { return surface.outlier_every > 0 && i % static_cast<std::size_t>(surface.outlier_every) == 0; }

constexpr Surface kSurfaces[] = {
    {"smooth", "z = 0.2 sin(pi x) sin(pi y)", 0.0, 0},
    {"rippled", "z = 0.2 sin(pi x) sin(pi y) + 0.01 sin(16 pi x) sin(16 pi y)", 0.01, 0},
    {"outliers", "z = 0.2 sin(pi x) sin(pi y), 2% of the points moved +-0.1 along z", 0.0, 50},
};

std::vector<double> height_field(const Surface& surface, std::size_t count, std::uint64_t seed) {
  Random random(seed);
  std::vector<double> xyz(3 * count);
  for (std::size_t i = 0; i < count; ++i) {
    double x = random.uniform(), y = random.uniform();
    xyz[3 * i] = x;
    xyz[3 * i + 1] = y;
    xyz[3 * i + 2] = 0.2 * std::sin(kPi * x) * std::sin(kPi * y) + surface.ripple * std::sin(16 * kPi * x) * std::sin(16 * kPi * y);
    if (is_outlier(surface, i)) xyz[3 * i + 2] += (i / static_cast<std::size_t>(surface.outlier_every)) % 2 ? 0.1 : -0.1;
  }
  return xyz;
}

/// A "Vm...:  1234 kB" field of /proc/self/status in KiB, or -1 where there is none.
long status_kib(const char* field) {
  std::ifstream status("/proc/self/status");
  std::string line;
  std::size_t length = std::strlen(field);
  while (std::getline(status, line)) {
    if (line.compare(0, length, field) == 0 && line.size() > length && line[length] == ':') return std::atol(line.c_str() + length + 1);
  }
  return -1;
}

/// Makes VmHWM start again from the current resident set (Linux >= 4.0); false if refused.
bool reset_peak_memory() {
  std::ofstream clear_refs("/proc/self/clear_refs");
  clear_refs << "5";
  clear_refs.flush();
  return static_cast<bool>(clear_refs);
}

[[noreturn]] void fail(const char* what, int status) {
  std::fprintf(stderr, "dbs-bench: %s failed: %s (%s)\n", what, dbs_last_error_message(), dbs_status_string(status));
  std::exit(EXIT_FAILURE);
}

void check(int status, const char* what) {
  if (status != DBS_OK) fail(what, status);
}

[[noreturn]] void usage_error(const std::string& message) {
  std::fprintf(stderr, "dbs-bench: %s\nusage: dbs-bench [--surface smooth|rippled|outliers|both|all] [--sizes 10k,100k,1M] [--threads N] [--max-level N] [--relative-accuracy F] [--solver linear|ceres] [--loss none|huber|cauchy|soft_l1] [--repair 0|1] [--cancel-trials N]\n", message.c_str());
  std::exit(2);
}

/// "10000", "10k" or "1M" as a point count.
std::size_t parse_size(const std::string& text) {
  char* end = nullptr;
  double value = std::strtod(text.c_str(), &end);
  std::string suffix(end);
  if (suffix == "k" || suffix == "K") value *= 1e3;
  else if (suffix == "m" || suffix == "M") value *= 1e6;
  else if (!suffix.empty()) usage_error("'" + text + "' is not a size (e.g. 50000, 10k, 1M)");
  if (end == text.c_str() || !(value >= 1.0 && value <= 1e9) || value != std::floor(value)) usage_error("'" + text + "' is not a size between 1 and 1e9 points");
  return static_cast<std::size_t>(value);
}

int parse_int(const std::string& option, const std::string& text) { return bench::parse_small_int(option, text, usage_error); }

struct Settings {
  std::vector<const Surface*> surfaces{&kSurfaces[0], &kSurfaces[1]};
  std::vector<std::size_t> sizes{10000, 100000, 1000000};
  int threads = 0;
  int max_level = -1;               // -1: the library's default
  double relative_accuracy = -1.0;  // < 0: the library's default
  int solver = DBS_SOLVER_LINEAR;
  int loss = DBS_LOSS_NONE;
  int repair = -1;        // -1: the library's default (DBS_OPT_REPAIR)
  int cancel_trials = 0;  // 0: no responsiveness table
};

Settings parse_arguments(int argc, char** argv) {
  Settings settings;
  for (int i = 1; i < argc; ++i) {
    std::string arg = argv[i];
    if (arg == "-h" || arg == "--help") usage_error("benchmark of dbs_parameterize on height-field clouds");
    if (i + 1 >= argc) usage_error(arg + (arg.rfind("--", 0) == 0 ? " needs a value" : ": unknown argument"));
    std::string value = argv[++i];
    if (arg == "--surface") {
      settings.surfaces.clear();
      for (const Surface& surface : kSurfaces) {
        if (value == surface.name || (value == "both" && surface.outlier_every == 0) || value == "all") settings.surfaces.push_back(&surface);
      }
      if (settings.surfaces.empty()) usage_error("--surface: '" + value + "' is not smooth, rippled, outliers, both or all");
    } else if (arg == "--sizes") {
      settings.sizes.clear();
      std::stringstream list(value);
      std::string item;
      while (std::getline(list, item, ',')) settings.sizes.push_back(parse_size(item));
      if (settings.sizes.empty()) usage_error("--sizes needs at least one size");
    } else if (arg == "--threads") {
      settings.threads = parse_int(arg, value);
    } else if (arg == "--cancel-trials") {
      settings.cancel_trials = parse_int(arg, value);
    } else if (arg == "--max-level") {
      settings.max_level = parse_int(arg, value);
    } else if (arg == "--solver") {
      if (value == "linear") settings.solver = DBS_SOLVER_LINEAR;
      else if (value == "ceres") settings.solver = DBS_SOLVER_CERES;
      else usage_error("--solver: '" + value + "' is not linear or ceres");
    } else if (arg == "--repair") {
      settings.repair = parse_int(arg, value);
    } else if (arg == "--loss") {
      const char* const names[] = {"none", "huber", "cauchy", "soft_l1"};  // DBS_LOSS_* order
      settings.loss = -1;
      for (int k = 0; k < 4; ++k)
        if (value == names[k]) settings.loss = k;
      if (settings.loss < 0) usage_error("--loss: '" + value + "' is not none, huber, cauchy or soft_l1");
    } else if (arg == "--relative-accuracy") {
      settings.relative_accuracy = bench::parse_number(arg, value, [](double x) { return x > 0.0; }, "a positive number", usage_error);
    } else {
      usage_error("unknown option '" + arg + "'");
    }
  }
  return settings;
}

double stat(const dbs_result* result, int32_t id) {
  double value = 0.0;
  check(dbs_result_stat(result, id, &value), "dbs_result_stat");
  return value;
}

}  // namespace

int main(int argc, char** argv) {
  Settings settings = parse_arguments(argc, argv);
  static const double bottom[] = {0, 0, 0, 1, 0, 0}, right[] = {1, 0, 0, 1, 1, 0};
  static const double top[] = {0, 1, 0, 1, 1, 0}, left[] = {0, 0, 0, 0, 1, 0};

  dbs_options* options = nullptr;
  check(dbs_options_create(&options), "dbs_options_create");
  check(dbs_options_set_int(options, DBS_OPT_THREADS, settings.threads), "dbs_options_set_int(threads)");
  if (settings.max_level >= 0) check(dbs_options_set_int(options, DBS_OPT_MAX_LEVEL, settings.max_level), "dbs_options_set_int(max_level)");
  check(dbs_options_set_int(options, DBS_OPT_SOLVER, settings.solver), "dbs_options_set_int(solver)");
  check(dbs_options_set_int(options, DBS_OPT_LOSS, settings.loss), "dbs_options_set_int(loss)");
  if (settings.repair >= 0) check(dbs_options_set_int(options, DBS_OPT_REPAIR, settings.repair), "dbs_options_set_int(repair)");
  int32_t repair = 0;
  dbs_options_get_int(options, DBS_OPT_REPAIR, &repair);
  if (settings.relative_accuracy > 0.0) check(dbs_options_set_double(options, DBS_OPT_RELATIVE_ACCURACY, settings.relative_accuracy), "dbs_options_set_double(relative_accuracy)");
  int32_t max_level = 0;
  double relative_accuracy = 0.0;
  dbs_options_get_int(options, DBS_OPT_MAX_LEVEL, &max_level);
  dbs_options_get_double(options, DBS_OPT_RELATIVE_ACCURACY, &relative_accuracy);
  dbs_boundary* boundary = nullptr;
  check(dbs_boundary_create(bottom, 2, right, 2, top, 2, left, 2, &boundary), "dbs_boundary_create");

  static const char* const loss_names[] = {"none", "huber", "cauchy", "soft_l1"};
  std::printf("libdbs %s, max level %d, relative accuracy %g, threads %s, solver %s, loss %s, repair %s\n", dbs_version_string(), max_level, relative_accuracy,
              settings.threads == 0 ? "all" : std::to_string(settings.threads).c_str(), settings.solver == DBS_SOLVER_CERES ? "ceres" : "linear", loss_names[settings.loss],
              repair ? "on" : "off");
  std::printf("times in seconds: the whole dbs_parameterize call, then its stages (index: k-d tree, length scale and noise estimate;\n"
              "evolve: base surfaces on all levels; subdivide: middle curves and subclouds; project: every point onto its leaves;\n"
              "folds: the reference-free fold measure); noise: the estimated sigma; folded: its share of folded points\n");
  for (const Surface* surface : settings.surfaces) {
    std::printf("\n%s: %s\n\n", surface->name, surface->formula);
    std::printf("| points | time | index | evolve | subdivide | project | folds | peak memory (MiB) | iterations | Ceres iterations | levels | patches | leaves | mean distance | clean mean | max distance | noise | folded | target met |\n");
    std::printf("|-------:|-----:|------:|-------:|----------:|--------:|------:|------------------:|-----------:|-----------------:|-------:|--------:|-------:|--------------:|-----------:|-------------:|------:|-------:|:----------:|\n");
    std::fflush(stdout);
    for (std::size_t count : settings.sizes) {
      std::vector<double> xyz = height_field(*surface, count, 20240601 + count);
      bool peak_was_reset = reset_peak_memory();
      long rss_before = status_kib(peak_was_reset ? "VmRSS" : "VmHWM");

      dbs_cloud* cloud = nullptr;
      dbs_result* result = nullptr;
      check(dbs_cloud_create(xyz.data(), count, &cloud), "dbs_cloud_create");
      auto start = std::chrono::steady_clock::now();
      check(dbs_parameterize(cloud, boundary, options, &result), "dbs_parameterize");
      double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      long peak = status_kib("VmHWM");

      std::vector<double> distance(count);
      check(dbs_result_distances(result, distance.data(), count), "dbs_result_distances");
      double clean_sum = 0.0;
      std::size_t clean = 0;
      for (std::size_t i = 0; i < count; ++i)
        if (!is_outlier(*surface, i)) clean_sum += distance[i], ++clean;
      char memory[32] = "n/a";
      if (rss_before >= 0 && peak >= 0) std::snprintf(memory, sizeof memory, "%.1f", static_cast<double>(peak - rss_before) / 1024.0);
      std::printf("| %zu | %.2f | %.2f | %.2f | %.2f | %.2f | %.2f | %s | %.0f | %.0f | %.0f | %.0f | %.0f | %.3g | %.3g | %.3g | %.2g | %.2f%% | %s |\n", count, seconds,
                  stat(result, DBS_STAT_SECONDS_INDEX), stat(result, DBS_STAT_SECONDS_EVOLVE), stat(result, DBS_STAT_SECONDS_SUBDIVIDE),
                  stat(result, DBS_STAT_SECONDS_PARAMETERIZE), stat(result, DBS_STAT_SECONDS_FOLDS), memory, stat(result, DBS_STAT_ITERATIONS),
                  stat(result, DBS_STAT_CERES_ITERATIONS), stat(result, DBS_STAT_LEVELS), stat(result, DBS_STAT_PATCHES), stat(result, DBS_STAT_LEAVES),
                  stat(result, DBS_STAT_MEAN_DISTANCE), clean > 0 ? clean_sum / static_cast<double>(clean) : 0.0, stat(result, DBS_STAT_MAX_DISTANCE),
                  stat(result, DBS_STAT_NOISE), 100.0 * stat(result, DBS_STAT_FOLDED_SHARE), stat(result, DBS_STAT_ACCURACY_MET) != 0.0 ? "yes" : "no");
      std::fflush(stdout);
      dbs_result_destroy(result);
      dbs_cloud_destroy(cloud);
    }
    if (settings.cancel_trials > 0) {
      std::printf("\n%s, progress and cancel (%d cancels spread over a run):\n\n", surface->name, settings.cancel_trials);
      std::printf("| points | longest silence (s) | cancel latency median (s) | cancel latency max (s) |\n|-------:|------:|------:|------:|\n");
      for (std::size_t count : settings.sizes) {
        std::vector<double> xyz = height_field(*surface, count, 20240601 + count);
        dbs_cloud* cloud = nullptr;
        check(dbs_cloud_create(xyz.data(), count, &cloud), "dbs_cloud_create");
        const bench::Responsiveness r = bench::measure_responsiveness(cloud, boundary, options, settings.cancel_trials);
        std::printf("| %zu | %.3f | %.3f | %.3f |\n", count, r.longest_silence, r.median_latency, r.max_latency);
        std::fflush(stdout);
        dbs_cloud_destroy(cloud);
      }
    }
  }
  dbs_boundary_destroy(boundary);
  dbs_options_destroy(options);
  return EXIT_SUCCESS;
}
