// dbs_mesh_*: the Delaunay mesh of a result's (u,v) over its cloud, and its files.
#include <algorithm>
#include <limits>
#include <string>

#include "arrays.hpp"
#include "mesh_files.hpp"
#include "text_io.hpp"
#ifdef DBS_HAVE_REPORT
#include "textured_mesh.hpp"
#endif
#include "suspicious_triangles.hpp"
#include "validation_handles.hpp"

using namespace dbs::capi;

static_assert(DBS_MESH_SUSPICIOUS_FACTOR == dbs::kSuspiciousEdgeFactor, "dbs.h and the core disagree on the suspicious-edge factor");

namespace {

// The default thread count of a run (all hardware threads); the mesh does not depend on it.
constexpr int kAllThreads = 0;

}  // namespace

int dbs_mesh_create(const dbs_result* result, const dbs_cloud* cloud, dbs_mesh** out) {
  return guarded(__func__, [&] {
    require_non_null(result, "result");
    require_non_null(cloud, "cloud");
    require_non_null(out, "out");
    const dbs::Result& r = result->result;
    if (r.u.size() > static_cast<std::size_t>(std::numeric_limits<int32_t>::max())) fail_status(DBS_ERR_INVALID_ARGUMENT, "the result's " + std::to_string(r.u.size()) + " points exceed the 32-bit vertex index of a mesh");
    dbs::ValidationMesh mesh = dbs::build_validation_mesh(r, cloud->cloud, kAllThreads);
    *out = new dbs_mesh{cloud->cloud, r.u, r.v, std::move(mesh)};
  });
}

void dbs_mesh_destroy(dbs_mesh* mesh) { delete mesh; }

int dbs_mesh_vertex_count(const dbs_mesh* mesh, size_t* out) {
  return guarded(__func__, [&] {
    require_non_null(mesh, "mesh");
    require_non_null(out, "out");
    *out = mesh->cloud.size();
  });
}

int dbs_mesh_vertices(const dbs_mesh* mesh, double* out_xyz, size_t capacity) {
  return guarded(__func__, [&] {
    require_non_null(mesh, "mesh");
    require_non_null(out_xyz, "out_xyz");
    copy_points(mesh->cloud.points(), out_xyz, capacity, "out_xyz");
  });
}

int dbs_mesh_uv(const dbs_mesh* mesh, double* out_uv, size_t capacity) {
  return guarded(__func__, [&] {
    require_non_null(mesh, "mesh");
    require_non_null(out_uv, "out_uv");
    require_capacity("out_uv", capacity, mesh->u.size(), "pairs");
    for (size_t i = 0; i < mesh->u.size(); ++i) {
      out_uv[2 * i] = mesh->u[i];
      out_uv[2 * i + 1] = mesh->v[i];
    }
  });
}

int dbs_mesh_triangle_count(const dbs_mesh* mesh, size_t* out) {
  return guarded(__func__, [&] {
    require_non_null(mesh, "mesh");
    require_non_null(out, "out");
    *out = mesh->mesh.triangles.size();
  });
}

int dbs_mesh_triangles(const dbs_mesh* mesh, int32_t* out, size_t capacity) {
  return guarded(__func__, [&] {
    require_non_null(mesh, "mesh");
    require_non_null(out, "out");
    const std::vector<dbs::Triangle>& triangles = mesh->mesh.triangles;
    require_capacity("out", capacity, triangles.size(), "triangles");
    for (size_t t = 0; t < triangles.size(); ++t) std::copy(triangles[t].begin(), triangles[t].end(), out + 3 * t);
  });
}

int dbs_mesh_suspicious_count(const dbs_mesh* mesh, size_t* out) {
  return guarded(__func__, [&] {
    require_non_null(mesh, "mesh");
    require_non_null(out, "out");
    *out = mesh->mesh.suspicious.size();
  });
}

int dbs_mesh_suspicious(const dbs_mesh* mesh, int32_t* out, size_t capacity) {
  return guarded(__func__, [&] {
    require_non_null(mesh, "mesh");
    require_non_null(out, "out");
    const std::vector<size_t>& suspicious = mesh->mesh.suspicious;
    require_capacity("out", capacity, suspicious.size(), "values");
    std::transform(suspicious.begin(), suspicious.end(), out, [](size_t t) { return static_cast<int32_t>(t); });
  });
}

int dbs_mesh_save(const dbs_mesh* mesh, const char* path) {
  return guarded(__func__, [&] {
    require_non_null(mesh, "mesh");
    require_non_null(path, "path");
    const std::string file = path, ext = dbs::lowercase_extension(file);
    const dbs::ValidationMesh& m = mesh->mesh;
    if (ext == ".obj") {
#ifdef DBS_HAVE_REPORT
      dbs::write_textured_obj(file, mesh->cloud.points(), mesh->u, mesh->v, m.triangles, m.reference_normals);
#else
      fail_status(DBS_ERR_UNSUPPORTED, "cannot save the textured mesh '" + file + "': this libdbs was built without the report (DBS_WITH_REPORT=OFF); .ply works");
#endif
    } else if (ext == ".ply") {
      dbs::write_ply_mesh(file, mesh->cloud.points(), mesh->u, mesh->v, m.triangles);
    } else {
      fail_status(DBS_ERR_UNSUPPORTED, "cannot save a mesh as '" + file + "': the extension must be .obj or .ply");
    }
  });
}
