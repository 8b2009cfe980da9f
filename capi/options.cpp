// dbs_options_*: typed access to the core's options, and the C callbacks.
#include <type_traits>

#include "firewall.hpp"

using namespace dbs::capi;

static_assert(std::is_same<decltype(dbs_options::progress), dbs_progress_fn>::value, "dbs_options::progress must have dbs.h's type");
static_assert(std::is_same<decltype(dbs_options::level), dbs_level_fn>::value, "dbs_options::level must have dbs.h's type");

namespace {

/// The option's description, after checking that it has the type the caller used.
dbs::OptionInfo typed_option(int32_t option, bool integer) {
  dbs::OptionInfo info = dbs::option_info(option);
  if (info.is_integer != integer)
    fail_status(DBS_ERR_INVALID_ARGUMENT, "option " + std::to_string(option) + " (" + info.name + ") is " + (info.is_integer ? "an integer option; use dbs_options_set_int/get_int" : "a real option; use dbs_options_set_double/get_double"));
  return info;
}

}  // namespace

int dbs_options_create(dbs_options** out) {
  return guarded(__func__, [&] {
    require_non_null(out, "out");
    *out = new dbs_options();
  });
}

int dbs_options_clone(const dbs_options* options, dbs_options** out) {
  return guarded(__func__, [&] {
    require_non_null(options, "options");
    require_non_null(out, "out");
    *out = new dbs_options(*options);
  });
}

void dbs_options_destroy(dbs_options* options) { delete options; }

int dbs_options_set_int(dbs_options* options, int32_t option, int32_t value) {
  return guarded(__func__, [&] {
    require_non_null(options, "options");
    typed_option(option, true);
    dbs::set_option(options->options, option, value);
  });
}

int dbs_options_get_int(const dbs_options* options, int32_t option, int32_t* out) {
  return guarded(__func__, [&] {
    require_non_null(options, "options");
    require_non_null(out, "out");
    typed_option(option, true);
    *out = static_cast<int32_t>(dbs::get_option(options->options, option));
  });
}

int dbs_options_set_double(dbs_options* options, int32_t option, double value) {
  return guarded(__func__, [&] {
    require_non_null(options, "options");
    typed_option(option, false);
    dbs::set_option(options->options, option, value);
  });
}

int dbs_options_get_double(const dbs_options* options, int32_t option, double* out) {
  return guarded(__func__, [&] {
    require_non_null(options, "options");
    require_non_null(out, "out");
    typed_option(option, false);
    *out = dbs::get_option(options->options, option);
  });
}

int dbs_option_bounds(int32_t option, double* out_min, double* out_max) {
  return guarded(__func__, [&] {
    require_non_null(out_min, "out_min");
    require_non_null(out_max, "out_max");
    dbs::OptionInfo info = dbs::option_info(option);
    *out_min = info.min;
    *out_max = info.max;
  });
}

int dbs_options_set_progress(dbs_options* options, dbs_progress_fn fn, void* payload) {
  return guarded(__func__, [&] {
    require_non_null(options, "options");
    options->progress = fn;
    options->progress_payload = fn ? payload : nullptr;
  });
}

int dbs_options_set_warning(dbs_options* options, dbs_warning_fn fn, void* payload) {
  return guarded(__func__, [&] {
    require_non_null(options, "options");
    options->warning = fn;
    options->warning_payload = fn ? payload : nullptr;
  });
}

int dbs_options_set_level_callback(dbs_options* options, dbs_level_fn fn, void* payload) {
  return guarded(__func__, [&] {
    require_non_null(options, "options");
    options->level = fn;
    options->level_payload = fn ? payload : nullptr;
  });
}
