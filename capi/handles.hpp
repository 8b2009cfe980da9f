// The real types behind the opaque handles of dbs.h. They are defined before dbs.h is
// included, so dbs.h's `typedef struct dbs_cloud dbs_cloud;` names these very structs and the
// compiler checks every prototype against its definition.
#pragma once
#include <cstdint>
#include <vector>

#include "boundary.hpp"
#include "options.hpp"
#include "point_cloud.hpp"
#include "result.hpp"

struct dbs_cloud {
  dbs::PointCloud cloud;
};

struct dbs_boundary {
  dbs::Boundary boundary;
  std::vector<std::vector<dbs::Vec3>> holes;  // of a boundary found from a cloud
};

/// A read-only view of patches owned elsewhere (a result, or the run in a level callback).
struct dbs_patches {
  std::vector<const dbs::Patch*> patches;
};

/// The core's options plus the C callbacks, which dbs_parameterize turns into dbs::ProgressFn
/// and dbs::LevelFn (the signatures are checked against dbs.h's typedefs in options.cpp).
struct dbs_options {
  dbs::Options options;
  int (*progress)(double fraction, const char* stage, void* payload) = nullptr;
  void* progress_payload = nullptr;
  int (*level)(int32_t level, const dbs_patches* patches, void* payload) = nullptr;
  void* level_payload = nullptr;
  void (*warning)(const char* message, void* payload) = nullptr;
  void* warning_payload = nullptr;
};

/// A result and the view of all its patches, which points into `result.patches` (so the
/// handle is never copied).
struct dbs_result {
  dbs::Result result;
  dbs_patches all;

  dbs_result() = default;
  dbs_result(const dbs_result&) = delete;
  dbs_result& operator=(const dbs_result&) = delete;
};

#include "dbs.h"
