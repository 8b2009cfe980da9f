// Version and feature queries, status names and the last-error message.
#include "curve_refinement.hpp"
#include "draco_io.hpp"
#include "firewall.hpp"

namespace {
#ifdef DBS_HAVE_VALIDATION
constexpr int32_t kBuiltValidation = 1;
#else
constexpr int32_t kBuiltValidation = 0;
#endif
#ifdef DBS_HAVE_REPORT
constexpr int32_t kBuiltReport = 1;
#else
constexpr int32_t kBuiltReport = 0;
#endif
}  // namespace

#define DBS_STRINGIFY_(x) #x
#define DBS_STRINGIFY(x) DBS_STRINGIFY_(x)

int32_t dbs_version_number(void) { return DBS_VERSION_NUMBER; }

const char* dbs_version_string(void) {
  return DBS_STRINGIFY(DBS_VERSION_MAJOR) "." DBS_STRINGIFY(DBS_VERSION_MINOR) "." DBS_STRINGIFY(DBS_VERSION_PATCH);
}

int dbs_has_feature(int32_t feature, int32_t* out) {
  return dbs::capi::guarded(__func__, [&] {
    dbs::capi::require_non_null(out, "out");
    dbs::capi::require_index("feature", feature, 4);
    switch (feature) {
      case DBS_FEATURE_DRACO:
        *out = dbs::draco_available() ? 1 : 0;
        break;
      case DBS_FEATURE_VALIDATION:
        *out = kBuiltValidation;
        break;
      case DBS_FEATURE_CERES:
        *out = dbs::ceres_available() ? 1 : 0;
        break;
      default:  // DBS_FEATURE_REPORT
        *out = kBuiltReport;
        break;
    }
  });
}

const char* dbs_status_string(int status) {
  switch (status) {
    case DBS_OK: return "ok";
    case DBS_ERR_NULL_ARGUMENT: return "null argument";
    case DBS_ERR_INVALID_ARGUMENT: return "invalid argument";
    case DBS_ERR_OUT_OF_RANGE: return "out of range";
    case DBS_ERR_NON_FINITE: return "non-finite value";
    case DBS_ERR_EMPTY: return "empty";
    case DBS_ERR_DEGENERATE: return "degenerate geometry";
    case DBS_ERR_IO: return "input/output error";
    case DBS_ERR_PARSE: return "parse error";
    case DBS_ERR_UNSUPPORTED: return "unsupported";
    case DBS_ERR_CANCELLED: return "cancelled";
    case DBS_ERR_NO_MEMORY: return "out of memory";
    case DBS_ERR_BUFFER_TOO_SMALL: return "buffer too small";
    case DBS_ERR_NUMERICAL: return "numerical failure";
    case DBS_ERR_INTERNAL: return "internal error";
    default: return "unknown status";
  }
}

const char* dbs_last_error_message(void) { return dbs::capi::last_error_message(); }

int dbs_last_error_errno(void) { return dbs::capi::last_error_errno(); }
