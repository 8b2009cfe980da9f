// dbs_report_write in a libdbs built with DBS_WITH_REPORT=OFF: exported all the same, it
// refuses with DBS_ERR_UNSUPPORTED. CMake compiles this file instead of validation_report.cpp.
#include "firewall.hpp"

using namespace dbs::capi;

int dbs_report_write(const dbs_result*, const dbs_cloud*, const dbs_options*, const char*) {
  return guarded(__func__, [] { fail_status(DBS_ERR_UNSUPPORTED, "this libdbs was built without the report (DBS_WITH_REPORT=OFF)"); });
}
