// dbs_patches_*: read access to a set of quadtree patches.
#include "arrays.hpp"
#include "firewall.hpp"

using namespace dbs::capi;

namespace {

/// The i-th patch of the view, after the NULL and range checks.
const dbs::Patch& patch_at(const dbs_patches* patches, size_t i) {
  require_non_null(patches, "patches");
  require_size_index("patch index", i, patches->patches.size());
  return *patches->patches[i];
}

}  // namespace

int dbs_patches_count(const dbs_patches* patches, size_t* out) {
  return guarded(__func__, [&] {
    require_non_null(patches, "patches");
    require_non_null(out, "out");
    *out = patches->patches.size();
  });
}

int dbs_patches_id(const dbs_patches* patches, size_t i, int32_t* out) {
  return guarded(__func__, [&] {
    require_non_null(out, "out");
    *out = patch_at(patches, i).id;
  });
}

int dbs_patches_level(const dbs_patches* patches, size_t i, int32_t* out) {
  return guarded(__func__, [&] {
    require_non_null(out, "out");
    *out = patch_at(patches, i).level;
  });
}

int dbs_patches_is_leaf(const dbs_patches* patches, size_t i, int32_t* out) {
  return guarded(__func__, [&] {
    require_non_null(out, "out");
    *out = patch_at(patches, i).is_leaf() ? 1 : 0;
  });
}

int dbs_patches_parent(const dbs_patches* patches, size_t i, int32_t* out) {
  return guarded(__func__, [&] {
    require_non_null(out, "out");
    *out = patch_at(patches, i).parent;
  });
}

int dbs_patches_rect(const dbs_patches* patches, size_t i, double* out_rect) {
  return guarded(__func__, [&] {
    require_non_null(out_rect, "out_rect");
    const dbs::Rect& rect = patch_at(patches, i).rect;
    out_rect[0] = rect.u0;
    out_rect[1] = rect.v0;
    out_rect[2] = rect.u1;
    out_rect[3] = rect.v1;
  });
}

int dbs_patches_grid_size(const dbs_patches* patches, size_t i, int32_t* out_nu, int32_t* out_nv) {
  return guarded(__func__, [&] {
    require_non_null(out_nu, "out_nu");
    require_non_null(out_nv, "out_nv");
    const dbs::Grid& grid = patch_at(patches, i).grid;
    *out_nu = grid.nu;
    *out_nv = grid.nv;
  });
}

int dbs_patches_grid_points(const dbs_patches* patches, size_t i, double* out_xyz, size_t capacity) {
  return guarded(__func__, [&] {
    require_non_null(out_xyz, "out_xyz");
    copy_points(patch_at(patches, i).grid.points, out_xyz, capacity, "out_xyz");
  });
}

int dbs_patches_boundary_count(const dbs_patches* patches, size_t i, int32_t side, size_t* out) {
  return guarded(__func__, [&] {
    require_non_null(out, "out");
    const dbs::Patch& patch = patch_at(patches, i);
    require_index("side", side, 4);
    *out = patch.surface.boundary().side(static_cast<dbs::Side>(side)).size();
  });
}

int dbs_patches_boundary_points(const dbs_patches* patches, size_t i, int32_t side, double* out_xyz, size_t capacity) {
  return guarded(__func__, [&] {
    require_non_null(out_xyz, "out_xyz");
    const dbs::Patch& patch = patch_at(patches, i);
    require_index("side", side, 4);
    copy_points(patch.surface.boundary().side(static_cast<dbs::Side>(side)).points(), out_xyz, capacity, "out_xyz");
  });
}

int dbs_patches_stats(const dbs_patches* patches, size_t i, size_t* out_points, double* out_mean, double* out_max, int32_t* out_iterations) {
  return guarded(__func__, [&] {
    require_non_null(out_points, "out_points");
    require_non_null(out_mean, "out_mean");
    require_non_null(out_max, "out_max");
    require_non_null(out_iterations, "out_iterations");
    const dbs::Patch& patch = patch_at(patches, i);
    *out_points = patch.point_count;
    *out_mean = patch.mean_distance;
    *out_max = patch.max_distance;
    *out_iterations = patch.iterations;
  });
}

int dbs_patches_solver(const dbs_patches* patches, size_t i, int32_t* out_solver, size_t* out_ceres_iterations) {
  return guarded(__func__, [&] {
    require_non_null(out_solver, "out_solver");
    require_non_null(out_ceres_iterations, "out_ceres_iterations");
    const dbs::Patch& patch = patch_at(patches, i);
    *out_solver = patch.solver;
    *out_ceres_iterations = patch.ceres_iterations;
  });
}
