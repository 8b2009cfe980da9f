// The validation functions of a libdbs built with DBS_WITH_VALIDATION=OFF: every one is
// still exported (so bindings keep loading) and refuses with DBS_ERR_UNSUPPORTED.
// CMake compiles this file instead of validation_*.cpp in such a build.
#include <string>

#include "firewall.hpp"

using namespace dbs::capi;

namespace {

int unsupported(const char* function) {
  return guarded(function, [] { fail_status(DBS_ERR_UNSUPPORTED, "this libdbs was built without validation (DBS_WITH_VALIDATION=OFF)"); });
}

}  // namespace

// The handles are never created here; their destroy functions accept NULL like any other.
struct dbs_mesh {};
struct dbs_distortion {};
struct dbs_distances {};

int dbs_mesh_create(const dbs_result*, const dbs_cloud*, dbs_mesh**) { return unsupported(__func__); }
void dbs_mesh_destroy(dbs_mesh* mesh) { delete mesh; }
int dbs_mesh_vertex_count(const dbs_mesh*, size_t*) { return unsupported(__func__); }
int dbs_mesh_vertices(const dbs_mesh*, double*, size_t) { return unsupported(__func__); }
int dbs_mesh_uv(const dbs_mesh*, double*, size_t) { return unsupported(__func__); }
int dbs_mesh_triangle_count(const dbs_mesh*, size_t*) { return unsupported(__func__); }
int dbs_mesh_triangles(const dbs_mesh*, int32_t*, size_t) { return unsupported(__func__); }
int dbs_mesh_suspicious_count(const dbs_mesh*, size_t*) { return unsupported(__func__); }
int dbs_mesh_suspicious(const dbs_mesh*, int32_t*, size_t) { return unsupported(__func__); }
int dbs_mesh_save(const dbs_mesh*, const char*) { return unsupported(__func__); }
int dbs_mesh_distortion(const dbs_mesh*, int32_t, dbs_distortion**) { return unsupported(__func__); }
int dbs_distortion_create(const dbs_result*, const dbs_cloud*, const int32_t*, size_t, int32_t, dbs_distortion**) { return unsupported(__func__); }
void dbs_distortion_destroy(dbs_distortion* distortion) { delete distortion; }
int dbs_distortion_stat(const dbs_distortion*, int32_t, double*) { return unsupported(__func__); }
int dbs_distortion_summary(const dbs_distortion*, int32_t, int32_t, double*) { return unsupported(__func__); }
int dbs_distortion_values(const dbs_distortion*, int32_t, double*, size_t) { return unsupported(__func__); }
int dbs_distances_create(const dbs_result*, double, dbs_distances**) { return unsupported(__func__); }
void dbs_distances_destroy(dbs_distances* distances) { delete distances; }
int dbs_distances_stat(const dbs_distances*, int32_t, int32_t, double*) { return unsupported(__func__); }
