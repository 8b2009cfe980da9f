// dbs_distances_*: statistics of the point-to-surface distances, overall and per patch.
#include <cmath>
#include <string>

#include "number_text.hpp"
#include "validation_handles.hpp"

using namespace dbs::capi;

int dbs_distances_create(const dbs_result* result, double tolerance, dbs_distances** out) {
  return guarded(__func__, [&] {
    require_non_null(result, "result");
    require_non_null(out, "out");
    if (!std::isfinite(tolerance)) fail_status(DBS_ERR_NON_FINITE, "tolerance is not finite");
    if (tolerance < 0.0) fail_status(DBS_ERR_OUT_OF_RANGE, "tolerance " + dbs::significant_text(tolerance, 6) + " is negative (0 = the result's accuracy target)");
    const dbs::Result& r = result->result;
    const double used = tolerance > 0.0 ? tolerance : r.accuracy;
    *out = new dbs_distances{dbs::distance_statistics(r, used)};
  });
}

void dbs_distances_destroy(dbs_distances* distances) { delete distances; }

int dbs_distances_stat(const dbs_distances* distances, int32_t patch, int32_t stat, double* out) {
  return guarded(__func__, [&] {
    require_non_null(distances, "distances");
    require_non_null(out, "out");
    const dbs::DistanceReport& report = distances->report;
    if (patch < -1 || (patch >= 0 && static_cast<size_t>(patch) >= report.per_patch.size())) fail_status(DBS_ERR_OUT_OF_RANGE, "patch " + std::to_string(patch) + " is neither -1 (all points) nor a patch id in [0, " + std::to_string(report.per_patch.size()) + ")");
    require_index("stat", stat, DBS_DISTANCES_TOLERANCE + 1);
    const dbs::DistanceStats& s = patch == -1 ? report.overall : report.per_patch[patch];
    const double values[] = {static_cast<double>(s.count), s.mean, s.rms, s.max, s.p50, s.p90, s.p95, s.p99, s.within, report.tolerance};
    *out = values[stat];
  });
}
