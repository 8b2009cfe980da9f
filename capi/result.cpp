// dbs_result_*: per-point outputs, statistics, surface evaluation and saving.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>

#include "firewall.hpp"
#include "number_text.hpp"
#include "result_io.hpp"

using namespace dbs::capi;

namespace {

/// Copies a per-point array into a caller buffer of `capacity` values.
template <class From, class To>
void copy_values(const std::vector<From>& values, To* out, size_t capacity, const char* name) {
  require_capacity(name, capacity, values.size(), "values");
  std::transform(values.begin(), values.end(), out, [](From x) { return static_cast<To>(x); });
}

/// A parameter of dbs_result_evaluate: finite and inside [0,1].
void require_unit(const char* name, double value) {
  if (!std::isfinite(value)) fail_status(DBS_ERR_NON_FINITE, std::string("parameter ") + name + " is not finite (" + dbs::significant_text(value, 6) + ")");
  if (value < 0.0 || value > 1.0) fail_status(DBS_ERR_OUT_OF_RANGE, std::string("parameter ") + name + " = " + dbs::significant_text(value, 6) + " is outside [0, 1]");
}

double stat_value(const dbs::Result& r, int32_t stat) {
  switch (stat) {
    case DBS_STAT_MEAN_DISTANCE: return r.mean_distance;
    case DBS_STAT_MAX_DISTANCE: return r.max_distance;
    case DBS_STAT_RMS_DISTANCE: return r.rms_distance;
    case DBS_STAT_ACCURACY: return r.accuracy;
    case DBS_STAT_ACCURACY_MET: return r.accuracy_met ? 1.0 : 0.0;
    case DBS_STAT_LEVELS: return r.levels;
    case DBS_STAT_PATCHES: return static_cast<double>(r.patches.size());
    case DBS_STAT_LEAVES: return static_cast<double>(r.leaf_count());
    case DBS_STAT_ITERATIONS: return r.iterations;
    case DBS_STAT_SECONDS: return r.seconds;
    case DBS_STAT_LENGTH_SCALE: return r.length_scale;
    case DBS_STAT_SECONDS_INDEX: return r.stage_seconds.index;
    case DBS_STAT_SECONDS_EVOLVE: return r.stage_seconds.evolve;
    case DBS_STAT_SECONDS_SUBDIVIDE: return r.stage_seconds.subdivide;
    case DBS_STAT_SECONDS_PARAMETERIZE: return r.stage_seconds.parameterize;
    case DBS_STAT_SECONDS_FOLDS: return r.stage_seconds.folds;
    case DBS_STAT_REQUESTED_ACCURACY: return r.requested_accuracy;
    case DBS_STAT_REQUESTED_MET: return r.requested_accuracy_met ? 1.0 : 0.0;
    case DBS_STAT_NOISE: return r.noise;
    case DBS_STAT_FOLDED_SHARE: return r.folded_share;
    case DBS_STAT_FOLDED_POINTS: return static_cast<double>(r.folded_points);
    case DBS_STAT_UNDECIDED_POINTS: return static_cast<double>(r.undecided_points);
    case DBS_STAT_COINCIDENT_POINTS: return static_cast<double>(r.coincident_points);
    case DBS_STAT_JUDGED_POINTS: return static_cast<double>(r.judged_points);
    case DBS_STAT_REPAIRED_POINTS: return static_cast<double>(r.repaired_points);
    case DBS_STAT_SOLVER: return r.solver;
    case DBS_STAT_CERES_ITERATIONS: return static_cast<double>(r.ceres_iterations);
    case DBS_STAT_LOSS_SCALE: return r.loss_scale;
    case DBS_STAT_COLLAPSED_POINTS: return static_cast<double>(r.collapsed_points);
    case DBS_STAT_BOUNDARY_GAP: return r.boundary_gap;
    case DBS_STAT_SCALE_RATIO: return r.scale_ratio;
    case DBS_STAT_COVERAGE: return r.coverage;
    case DBS_STAT_CLAMPED_POINTS: return static_cast<double>(r.clamped_points);
    case DBS_STAT_FAR_POINTS: return static_cast<double>(r.far_points);
    case DBS_STAT_CROPPED_POINTS: return static_cast<double>(r.cropped_points);
    case DBS_STAT_TURNED_POINTS: return static_cast<double>(r.turned_points);
    case DBS_STAT_TURNED_SHARE: return r.turned_share;
    case DBS_STAT_SMOOTHED_POINTS: return static_cast<double>(r.smoothed_points);
    case DBS_STAT_PASSES: return static_cast<double>(r.passes);
    case DBS_STAT_COARSE: return r.coarse ? 1.0 : 0.0;
    default: break;
  }
  fail_status(DBS_ERR_OUT_OF_RANGE, "stat " + std::to_string(stat) + " is outside its range [0, " + std::to_string(DBS_STAT_COARSE + 1) + ")");
}

}  // namespace

void dbs_result_destroy(dbs_result* result) { delete result; }

int dbs_result_point_count(const dbs_result* result, size_t* out) {
  return guarded(__func__, [&] {
    require_non_null(result, "result");
    require_non_null(out, "out");
    *out = result->result.u.size();
  });
}

int dbs_result_uv(const dbs_result* result, double* out_uv, size_t capacity) {
  return guarded(__func__, [&] {
    require_non_null(result, "result");
    require_non_null(out_uv, "out_uv");
    const dbs::Result& r = result->result;
    require_capacity("out_uv", capacity, r.u.size(), "pairs");
    for (size_t i = 0; i < r.u.size(); ++i) {
      out_uv[2 * i] = r.u[i];
      out_uv[2 * i + 1] = r.v[i];
    }
  });
}

int dbs_result_distances(const dbs_result* result, double* out, size_t capacity) {
  return guarded(__func__, [&] {
    require_non_null(result, "result");
    require_non_null(out, "out");
    copy_values(result->result.distance, out, capacity, "out");
  });
}

int dbs_result_point_patches(const dbs_result* result, int32_t* out, size_t capacity) {
  return guarded(__func__, [&] {
    require_non_null(result, "result");
    require_non_null(out, "out");
    copy_values(result->result.patch, out, capacity, "out");
  });
}

int dbs_result_point_levels(const dbs_result* result, int32_t* out, size_t capacity) {
  return guarded(__func__, [&] {
    require_non_null(result, "result");
    require_non_null(out, "out");
    copy_values(result->result.level, out, capacity, "out");
  });
}

int dbs_result_repaired(const dbs_result* result, int32_t* out, size_t capacity) {
  return guarded(__func__, [&] {
    require_non_null(result, "result");
    require_non_null(out, "out");
    if (result->result.repaired.size() != result->result.u.size()) fail_status(DBS_ERR_INTERNAL, "the result's repair flags do not match its points");
    copy_values(result->result.repaired, out, capacity, "out");
  });
}

static_assert(DBS_POINT_REPAIRED == dbs::kPointRepaired && DBS_POINT_FAR == dbs::kPointFar && DBS_POINT_CLAMPED == dbs::kPointClamped && DBS_POINT_CROPPED == dbs::kPointCropped &&
                  DBS_POINT_TURNED == dbs::kPointTurned,
              "DBS_POINT_* and dbs::PointFlag must agree");

int dbs_result_point_flags(const dbs_result* result, int32_t* out, size_t capacity) {
  return guarded(__func__, [&] {
    require_non_null(result, "result");
    require_non_null(out, "out");
    require_capacity("out", capacity, result->result.u.size(), "values");
    const std::vector<std::int32_t> flags = result->result.point_flags();
    std::copy(flags.begin(), flags.end(), out);
  });
}

int dbs_result_evaluate(const dbs_result* result, double u, double v, double* out_xyz, double* out_normal) {
  return guarded(__func__, [&] {
    require_non_null(result, "result");
    require_non_null(out_xyz, "out_xyz");
    require_unit("u", u);
    require_unit("v", v);
    dbs::Vec3 normal;
    dbs::Vec3 point = result->result.evaluate(u, v, out_normal ? &normal : nullptr);
    std::copy(point.data(), point.data() + 3, out_xyz);
    if (out_normal) std::copy(normal.data(), normal.data() + 3, out_normal);
  });
}

int dbs_result_evaluate_many(const dbs_result* result, const double* uv, size_t n, double* out_xyz, double* out_normal, double* out_su, double* out_sv) {
  return guarded(__func__, [&] {
    require_non_null(result, "result");
    if (n == 0) return;
    require_non_null(uv, "uv");
    require_non_null(out_xyz, "out_xyz");
    if (n > SIZE_MAX / 3 / sizeof(double)) fail_status(DBS_ERR_INVALID_ARGUMENT, "n = " + std::to_string(n) + " is more points than any array can hold");
    // Every pair is checked before anything is written: a refused call leaves the outputs as they were.
    for (size_t k = 0; k < n; ++k) {
      const std::string at = " of pair " + std::to_string(k);
      require_unit(("u" + at).c_str(), uv[2 * k]);
      require_unit(("v" + at).c_str(), uv[2 * k + 1]);
    }
    result->result.evaluate_many(uv, n, out_xyz, out_normal, out_su, out_sv, 0);
  });
}

int dbs_result_stat(const dbs_result* result, int32_t stat, double* out) {
  return guarded(__func__, [&] {
    require_non_null(result, "result");
    require_non_null(out, "out");
    *out = stat_value(result->result, stat);
  });
}

int dbs_result_patches(const dbs_result* result, const dbs_patches** out) {
  return guarded(__func__, [&] {
    require_non_null(result, "result");
    require_non_null(out, "out");
    *out = &result->all;
  });
}

int dbs_result_save(const dbs_result* result, const dbs_cloud* cloud, const char* path) {
  return guarded(__func__, [&] {
    require_non_null(result, "result");
    require_non_null(cloud, "cloud");
    require_non_null(path, "path");
    dbs::save_result(result->result, cloud->cloud, path);
  });
}
