// dbs_parameterize: the C callbacks become the core's observers, and the run's result a handle.
#include <memory>

#include "firewall.hpp"
#include "parameterize.hpp"

using namespace dbs::capi;

namespace {

/// The core's options for one run: the handle's values (or the defaults) with the C
/// callbacks wrapped. A C callback's non-zero return asks the core to cancel.
dbs::Options run_options(const dbs_options* handle) {
  if (handle == nullptr) return dbs::Options();
  dbs::Options options = handle->options;
  if (dbs_progress_fn progress = handle->progress) {
    void* payload = handle->progress_payload;
    options.progress = [progress, payload](double fraction, const char* stage) { return progress(fraction, stage, payload) != 0; };
  }
  if (dbs_level_fn level = handle->level) {
    void* payload = handle->level_payload;
    options.on_level = [level, payload](int number, const std::vector<const dbs::Patch*>& patches) {
      dbs_patches view{patches};
      return level(number, &view, payload) != 0;
    };
  }
  if (dbs_warning_fn warning = handle->warning) {
    void* payload = handle->warning_payload;
    options.warning = [warning, payload](const char* message) { warning(message, payload); };
  }
  return options;
}

}  // namespace

int dbs_parameterize(const dbs_cloud* cloud, const dbs_boundary* boundary, const dbs_options* options, dbs_result** out) {
  return guarded(__func__, [&] {
    require_non_null(cloud, "cloud");
    require_non_null(boundary, "boundary");
    require_non_null(out, "out");
    auto result = std::make_unique<dbs_result>();
    result->result = dbs::parameterize(cloud->cloud, boundary->boundary, run_options(options));
    for (const dbs::Patch& patch : result->result.patches) result->all.patches.push_back(&patch);
    *out = result.release();
  });
}
