// dbs_report_write: the validation report of a result (files, pictures, summary.json);
// dbs_boundary_report_write: the picture of a boundary on its cloud.
#include "boundary_report.hpp"
#include "validation_handles.hpp"
#include "validation_report.hpp"

using namespace dbs::capi;

int dbs_report_write(const dbs_result* result, const dbs_cloud* cloud, const dbs_options* options, const char* dir) {
  return guarded(__func__, [&] {
    require_non_null(result, "result");
    require_non_null(cloud, "cloud");
    require_non_null(dir, "dir");
    const dbs::Options defaults;
    dbs::write_validation_report(result->result, cloud->cloud, options ? options->options : defaults, dir);
  });
}

int dbs_boundary_report_write(const dbs_boundary* boundary, const dbs_cloud* cloud, const char* dir) {
  return guarded(__func__, [&] {
    require_non_null(boundary, "boundary");
    require_non_null(cloud, "cloud");
    require_non_null(dir, "dir");
    dbs::write_boundary_report(cloud->cloud.points(), boundary->boundary, boundary->holes, dir);
  });
}
