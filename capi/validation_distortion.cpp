// dbs_distortion_*: triangle distortion of the Delaunay mesh or of a caller's mesh.
#include <limits>
#include <string>

#include "validation_handles.hpp"

using namespace dbs::capi;

namespace {

// The default thread count of a run (all hardware threads); results do not depend on it.
constexpr int kAllThreads = 0;

dbs::DomainScaling scaling_of(int32_t scaling) {
  if (scaling == DBS_SCALING_UNIFORM) return dbs::DomainScaling::Uniform;
  if (scaling == DBS_SCALING_PER_AXIS) return dbs::DomainScaling::PerAxis;
  fail_status(DBS_ERR_OUT_OF_RANGE, "scaling " + std::to_string(scaling) + " is neither DBS_SCALING_UNIFORM (0) nor DBS_SCALING_PER_AXIS (1)");
}

void require_measure(int32_t measure, int32_t last) { require_index("measure", measure, static_cast<std::size_t>(last) + 1); }

const dbs::MeasureSummary& summary_of(const dbs::DistortionSummary& s, int32_t measure) {
  switch (measure) {
    case DBS_MEASURE_CONFORMAL: return s.conformal;
    case DBS_MEASURE_AREA: return s.area;
    case DBS_MEASURE_STRETCH_L2: return s.stretch_l2;
    case DBS_MEASURE_STRETCH_LINF: return s.stretch_linf;
    case DBS_MEASURE_EDGE_DIFFERENCE: return s.edge_difference;
    case DBS_MEASURE_SIGMA1: return s.sigma1;
    default: return s.sigma2;
  }
}

double value_of(const dbs::TriangleDistortion& t, int32_t measure) {
  if (measure == DBS_MEASURE_FOLDED) return t.folded ? 1.0 : 0.0;
  if (measure == DBS_MEASURE_DEGENERATE) return t.degenerate ? 1.0 : 0.0;
  if (measure == DBS_MEASURE_CROPPED) return t.cropped ? 1.0 : 0.0;
  if (t.degenerate || t.cropped) return std::numeric_limits<double>::quiet_NaN();
  switch (measure) {
    case DBS_MEASURE_CONFORMAL: return t.conformal;
    case DBS_MEASURE_AREA: return t.area;
    case DBS_MEASURE_STRETCH_L2: return t.stretch_l2;
    case DBS_MEASURE_STRETCH_LINF: return t.stretch_linf;
    case DBS_MEASURE_EDGE_DIFFERENCE: return t.edge_difference;
    case DBS_MEASURE_SIGMA1: return t.sigma1;
    default: return t.sigma2;
  }
}

}  // namespace

int dbs_mesh_distortion(const dbs_mesh* mesh, int32_t scaling, dbs_distortion** out) {
  return guarded(__func__, [&] {
    require_non_null(mesh, "mesh");
    require_non_null(out, "out");
    const dbs::DomainScaling s = scaling_of(scaling);
    *out = new dbs_distortion{dbs::measure_distortion(mesh->cloud.points(), mesh->u, mesh->v, mesh->mesh.triangles, s, mesh->mesh.reference_normals)};
  });
}

int dbs_distortion_create(const dbs_result* result, const dbs_cloud* cloud, const int32_t* triangles, size_t n_triangles, int32_t scaling, dbs_distortion** out) {
  return guarded(__func__, [&] {
    require_non_null(result, "result");
    require_non_null(cloud, "cloud");
    if (n_triangles > 0) require_non_null(triangles, "triangles");
    require_non_null(out, "out");
    const dbs::DomainScaling s = scaling_of(scaling);
    std::vector<dbs::Triangle> list;
    // A count no array can have, of the caller's triangles or of ours (it was an internal error
    // between the two bounds before 0.4).
    if (n_triangles > std::numeric_limits<size_t>::max() / (3 * sizeof(int32_t)) || n_triangles > list.max_size())
      fail_status(DBS_ERR_INVALID_ARGUMENT, "triangle count " + std::to_string(n_triangles) + " exceeds any addressable array");
    list.resize(n_triangles);
    for (size_t t = 0; t < n_triangles; ++t) list[t] = {triangles[3 * t], triangles[3 * t + 1], triangles[3 * t + 2]};
    *out = new dbs_distortion{dbs::measure_result_distortion(result->result, cloud->cloud, list, s, kAllThreads)};
  });
}

void dbs_distortion_destroy(dbs_distortion* distortion) { delete distortion; }

int dbs_distortion_stat(const dbs_distortion* distortion, int32_t stat, double* out) {
  return guarded(__func__, [&] {
    require_non_null(distortion, "distortion");
    require_non_null(out, "out");
    require_index("stat", stat, DBS_DISTORTION_CROPPED + 1);
    const dbs::DistortionSummary& s = distortion->distortion.summary;
    switch (stat) {
      case DBS_DISTORTION_TRIANGLES: *out = static_cast<double>(s.triangles); break;
      case DBS_DISTORTION_DEGENERATE: *out = static_cast<double>(s.degenerate); break;
      case DBS_DISTORTION_FOLDED: *out = static_cast<double>(s.folded); break;
      case DBS_DISTORTION_SCALE_U: *out = s.scale_u; break;
      case DBS_DISTORTION_SCALE_V: *out = s.scale_v; break;
      case DBS_DISTORTION_CROPPED: *out = static_cast<double>(s.cropped); break;
      default: *out = s.mesh_stretch_l2; break;
    }
  });
}

int dbs_distortion_summary(const dbs_distortion* distortion, int32_t measure, int32_t summary, double* out) {
  return guarded(__func__, [&] {
    require_non_null(distortion, "distortion");
    require_non_null(out, "out");
    require_measure(measure, DBS_MEASURE_SIGMA2);
    require_index("summary", summary, DBS_SUMMARY_MAX + 1);
    const dbs::MeasureSummary& s = summary_of(distortion->distortion.summary, measure);
    const double values[] = {s.min, s.mean, s.p95, s.max};
    *out = values[summary];
  });
}

int dbs_distortion_values(const dbs_distortion* distortion, int32_t measure, double* out, size_t capacity) {
  return guarded(__func__, [&] {
    require_non_null(distortion, "distortion");
    require_non_null(out, "out");
    require_measure(measure, DBS_MEASURE_CROPPED);
    const std::vector<dbs::TriangleDistortion>& triangles = distortion->distortion.triangles;
    require_capacity("out", capacity, triangles.size(), "values");
    for (size_t t = 0; t < triangles.size(); ++t) out[t] = value_of(triangles[t], measure);
  });
}
