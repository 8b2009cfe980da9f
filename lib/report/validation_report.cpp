#include "validation_report.hpp"

#include <chrono>
#include <cstdio>

#include "circle_pattern.hpp"
#include "distance_stats.hpp"
#include "error.hpp"
#include "json_writer.hpp"
#include "mesh_files.hpp"
#include "png_file.hpp"
#include "raster_view.hpp"
#include "report_directory.hpp"
#include "report_pictures.hpp"
#include "suspicious_triangles.hpp"
#include "textured_mesh.hpp"
#include "validation_mesh.hpp"

namespace dbs {
namespace {

constexpr int kViewWidth = 720, kViewHeight = 540;
constexpr int kDomainSize = 560;
constexpr int kHistogramWidth = 640, kHistogramHeight = 320;

class Stopwatch {
 public:
  double lap() {
    auto now = std::chrono::steady_clock::now();
    double seconds = std::chrono::duration<double>(now - start_).count();
    start_ = now;
    return seconds;
  }

 private:
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
};

void write_summary(JsonWriter& json, const char* key, const MeasureSummary& s) {
  json.begin_object(key);
  json.number("min", s.min);
  json.number("mean", s.mean);
  json.number("p95", s.p95);
  json.number("max", s.max);
  json.end_object();
}

void write_distortion(JsonWriter& json, const char* key, const DistortionSummary& s) {
  json.begin_object(key);
  json.integer("triangles", static_cast<long long>(s.triangles));
  json.integer("degenerate", static_cast<long long>(s.degenerate));
  json.integer("folded", static_cast<long long>(s.folded));
  json.number("scale_u", s.scale_u);
  json.number("scale_v", s.scale_v);
  write_summary(json, "conformal", s.conformal);
  write_summary(json, "area", s.area);
  write_summary(json, "stretch_l2", s.stretch_l2);
  write_summary(json, "stretch_linf", s.stretch_linf);
  write_summary(json, "edge_difference", s.edge_difference);
  json.number("mesh_stretch_l2", s.mesh_stretch_l2);
  json.end_object();
}

void write_distances(JsonWriter& json, const char* key, const DistanceStats& s) {
  json.begin_object(key);
  json.integer("count", static_cast<long long>(s.count));
  json.number("mean", s.mean);
  json.number("rms", s.rms);
  json.number("max", s.max);
  json.number("p50", s.p50);
  json.number("p90", s.p90);
  json.number("p95", s.p95);
  json.number("p99", s.p99);
  json.number("within", s.within);
  json.end_object();
}

void write_text_file(const std::string& path, const std::string& text) {
  std::FILE* f = std::fopen(path.c_str(), "w");
  if (!f) fail(ErrorCode::Io, "cannot open '" + path + "' for writing");
  bool ok = std::fwrite(text.data(), 1, text.size(), f) == text.size();
  ok = std::fclose(f) == 0 && ok;
  if (!ok) fail(ErrorCode::Io, "cannot write '" + path + "'");
}

}  // namespace

void write_validation_report(const Result& result, const PointCloud& cloud, const Options& options, const std::string& dir) {
  make_report_directory(dir);
  const std::string base = dir + "/";

  Stopwatch clock;
  const ValidationMesh mesh = build_validation_mesh(result, cloud, options.threads);
  const double mesh_seconds = clock.lap();
  const Distortion per_axis = measure_distortion(cloud.points(), result.u, result.v, mesh.triangles, DomainScaling::PerAxis, mesh.reference_normals);
  const Distortion uniform = measure_distortion(cloud.points(), result.u, result.v, mesh.triangles, DomainScaling::Uniform, mesh.reference_normals);
  const double distortion_seconds = clock.lap();
  const DistanceReport distances = distance_statistics(result, result.accuracy);
  const double distance_seconds = clock.lap();

  const CirclePattern pattern(per_axis.summary.scale_u, per_axis.summary.scale_v);
  write_textured_obj(base + "mesh.obj", cloud.points(), result.u, result.v, mesh.triangles, pattern.texture(kTexturePixels));
  write_ply_mesh(base + "mesh.ply", cloud.points(), result.u, result.v, mesh.triangles);
  const double mesh_file_seconds = clock.lap();
  write_png(base + "view.png", render_view(cloud.points(), result.u, result.v, mesh.triangles, pattern, default_view(cloud.points(), mesh.triangles), kViewWidth, kViewHeight));
  std::vector<Rect> leaves;
  for (const Patch& p : result.patches)
    if (p.is_leaf()) leaves.push_back(p.rect);
  std::vector<std::size_t> turned;
  for (std::size_t i = 0; i < result.turned.size(); ++i)
    if (result.turned[i]) turned.push_back(i);
  write_png(base + "domain.png", draw_parameter_domain(result.u, result.v, mesh.triangles, per_axis.triangles, mesh.suspicious, turned, leaves, kDomainSize));
  // The distances the statistics count: not those of points far outside the body or cropped.
  write_png(base + "distances.png", draw_distance_histogram(result.counted_distances(), distances.overall, distances.tolerance, kHistogramWidth, kHistogramHeight));
  const double picture_seconds = clock.lap();

  JsonWriter json;
  json.begin_object();
  json.integer("points", static_cast<long long>(cloud.size()));
  json.begin_object("options");
  // The parameterization's options (the outline's neighbourhood is not one of them).
  for (int id = 0; id <= static_cast<int>(OptionId::FitToTarget); ++id)
    if (id != static_cast<int>(OptionId::OutlineNeighbours)) json.number(option_info(id).name, get_option(options, id));
  json.end_object();
  json.begin_object("timings_seconds");
  json.number("parameterize", result.seconds);
  json.number("mesh", mesh_seconds);
  json.number("distortion", distortion_seconds);
  json.number("distances", distance_seconds);
  json.number("mesh_files", mesh_file_seconds);
  json.number("pictures", picture_seconds);
  json.end_object();
  json.begin_object("quadtree");
  json.integer("levels", result.levels);
  json.integer("patches", static_cast<long long>(result.patches.size()));
  json.integer("leaves", static_cast<long long>(result.leaf_count()));
  json.integer("iterations", result.iterations);
  json.number("accuracy", result.accuracy);
  json.boolean("accuracy_met", result.accuracy_met);
  json.number("requested_accuracy", result.requested_accuracy);
  json.boolean("requested_accuracy_met", result.requested_accuracy_met);
  json.number("noise", result.noise);
  json.number("length_scale", result.length_scale);
  json.string("solver", result.solver == static_cast<int>(Solver::Ceres) ? "ceres" : "linear");
  json.integer("ceres_iterations", static_cast<long long>(result.ceres_iterations));
  json.number("loss_scale", result.loss_scale);
  json.end_object();
  json.begin_array("patches");
  for (const Patch& p : result.patches) {
    json.begin_object();
    json.integer("id", p.id);
    json.integer("level", p.level);
    json.integer("parent", p.parent);
    json.boolean("leaf", p.is_leaf());
    json.begin_array("rect");
    for (double x : {p.rect.u0, p.rect.v0, p.rect.u1, p.rect.v1}) json.number(x);
    json.end_array();
    json.begin_array("grid");
    json.number(p.grid.nu);
    json.number(p.grid.nv);
    json.end_array();
    json.integer("subcloud_points", static_cast<long long>(p.point_count));
    json.number("subcloud_mean_distance", p.mean_distance);
    json.number("subcloud_max_distance", p.max_distance);
    json.integer("iterations", p.iterations);
    json.integer("ceres_iterations", static_cast<long long>(p.ceres_iterations));
    json.boolean("accurate", p.accurate);
    if (p.is_leaf()) write_distances(json, "parameterized_points", distances.per_patch[p.id]);
    json.end_object();
  }
  json.end_array();
  json.begin_object("distances");
  json.number("tolerance", distances.tolerance);
  write_distances(json, "overall", distances.overall);
  json.end_object();
  json.begin_object("mesh");
  json.integer("vertices", static_cast<long long>(cloud.size() - result.cropped_points));
  json.integer("triangles", static_cast<long long>(mesh.triangles.size()));
  json.integer("suspicious", static_cast<long long>(mesh.suspicious.size()));
  json.number("suspicious_edge_factor", kSuspiciousEdgeFactor);
  json.integer("spacing_neighbour", static_cast<long long>(kSpacingNeighbour));
  json.end_object();
  // The reference-free fold measure of the result (no mesh; it does not trust the surface),
  // beside the mesh's own fold count in "distortion".
  json.begin_object("folds");
  json.integer("judged_points", static_cast<long long>(result.judged_points));
  json.integer("folded_points", static_cast<long long>(result.folded_points));
  json.integer("undecided_points", static_cast<long long>(result.undecided_points));
  json.integer("collapsed_points", static_cast<long long>(result.collapsed_points));
  json.integer("turned_points", static_cast<long long>(result.turned_points));
  json.number("turned_share", result.turned_share);
  json.integer("coincident_points", static_cast<long long>(result.coincident_points));
  json.number("folded_share", result.folded_share);
  json.integer("repaired_points", static_cast<long long>(result.repaired_points));
  json.integer("smoothed_points", static_cast<long long>(result.smoothed_points));
  json.integer("passes", result.passes);
  json.integer("coarse", result.coarse ? 1 : 0);
  json.end_object();
  // The inputs checked against each other (DBS_STAT_BOUNDARY_GAP and the five after it).
  json.begin_object("inputs");
  json.number("boundary_gap", result.boundary_gap);
  json.number("scale_ratio", result.scale_ratio);
  json.number("coverage", result.coverage);
  json.integer("clamped_points", static_cast<long long>(result.clamped_points));
  json.integer("far_points", static_cast<long long>(result.far_points));
  json.integer("cropped_points", static_cast<long long>(result.cropped_points));
  json.end_object();
  json.begin_object("distortion");
  write_distortion(json, "per_axis", per_axis.summary);
  write_distortion(json, "uniform", uniform.summary);
  json.end_object();
  json.begin_array("files");
  for (const char* name : {"mesh.obj", "mesh.mtl", "mesh_texture.png", "mesh.ply", "view.png", "domain.png", "distances.png", "summary.json"}) json.string(nullptr, name);
  json.end_array();
  json.end_object();
  write_text_file(base + "summary.json", json.text() + "\n");
}

}  // namespace dbs
