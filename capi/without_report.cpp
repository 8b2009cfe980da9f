// dbs_report_write and dbs_boundary_report_write in a libdbs built with DBS_WITH_REPORT=OFF:
// exported all the same, they refuse with DBS_ERR_UNSUPPORTED. CMake compiles this file instead of validation_report.cpp.
#include "firewall.hpp"

using namespace dbs::capi;

int dbs_report_write(const dbs_result*, const dbs_cloud*, const dbs_options*, const char*) {
  return guarded(__func__, [] { fail_status(DBS_ERR_UNSUPPORTED, "this libdbs was built without the report (DBS_WITH_REPORT=OFF)"); });
}

int dbs_boundary_report_write(const dbs_boundary*, const dbs_cloud*, const char*) {
  return guarded(__func__, [] { fail_status(DBS_ERR_UNSUPPORTED, "this libdbs was built without the report (DBS_WITH_REPORT=OFF)"); });
}
