// dbs_cloud_*: point clouds from arrays and files.
#include <algorithm>

#include "arrays.hpp"
#include "cloud_io.hpp"
#include "firewall.hpp"
#include "handles.hpp"
#include "load_progress.hpp"

using namespace dbs::capi;

int dbs_cloud_create(const double* xyz, size_t count, dbs_cloud** out) {
  return guarded(__func__, [&] {
    require_non_null(xyz, "xyz");
    require_non_null(out, "out");
    *out = new dbs_cloud{dbs::PointCloud(points_from(xyz, count))};
  });
}

int dbs_cloud_load(const char* path, dbs_cloud** out) {
  return guarded(__func__, [&] {
    require_non_null(path, "path");
    require_non_null(out, "out");
    *out = new dbs_cloud{dbs::load_cloud(path)};
  });
}

int dbs_cloud_load_with_options(const char* path, const dbs_options* options, dbs_cloud** out) {
  return guarded(__func__, [&] {
    require_non_null(path, "path");
    require_non_null(out, "out");
    dbs::ProgressFn report;
    if (options && options->progress) {
      const dbs_progress_fn progress = options->progress;
      void* payload = options->progress_payload;
      report = [progress, payload](double fraction, const char* stage) { return progress(fraction, stage, payload) != 0; };
    }
    dbs::LoadProgress load_progress(std::move(report));
    *out = new dbs_cloud{dbs::load_cloud(path, load_progress)};
  });
}

void dbs_cloud_destroy(dbs_cloud* cloud) { delete cloud; }

int dbs_cloud_count(const dbs_cloud* cloud, size_t* out) {
  return guarded(__func__, [&] {
    require_non_null(cloud, "cloud");
    require_non_null(out, "out");
    *out = cloud->cloud.size();
  });
}

int dbs_cloud_bounds(const dbs_cloud* cloud, double* out_min, double* out_max) {
  return guarded(__func__, [&] {
    require_non_null(cloud, "cloud");
    require_non_null(out_min, "out_min");
    require_non_null(out_max, "out_max");
    const dbs::Box3& box = cloud->cloud.bounds();
    std::copy(box.min.data(), box.min.data() + 3, out_min);
    std::copy(box.max.data(), box.max.data() + 3, out_max);
  });
}

int dbs_cloud_points(const dbs_cloud* cloud, double* out_xyz, size_t capacity) {
  return guarded(__func__, [&] {
    require_non_null(cloud, "cloud");
    require_non_null(out_xyz, "out_xyz");
    copy_points(cloud->cloud.points(), out_xyz, capacity, "out_xyz");
  });
}
