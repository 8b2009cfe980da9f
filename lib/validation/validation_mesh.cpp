#include "validation_mesh.hpp"

#include <algorithm>
#include <string>

#include "cloud_index.hpp"
#include "delaunay_mesh.hpp"
#include "error.hpp"
#include "parallel.hpp"
#include "suspicious_triangles.hpp"

namespace dbs {
namespace {

void require_matching(const Result& result, const PointCloud& cloud) {
  if (result.u.size() != cloud.size()) fail(ErrorCode::InvalidArgument, "the result has " + std::to_string(result.u.size()) + " points but the cloud " + std::to_string(cloud.size()) + ": pass the cloud that was parameterized");
}

}  // namespace

std::vector<Vec3> surface_normals_at(const Result& result, const std::vector<Triangle>& triangles, int threads) {
  std::vector<Vec3> normals(triangles.size());
  parallel_for(triangles.size(), resolve_threads(threads), [&](std::size_t t) {
    const Triangle& tri = triangles[t];
    double u = (result.u[tri[0]] + result.u[tri[1]] + result.u[tri[2]]) / 3.0;
    double v = (result.v[tri[0]] + result.v[tri[1]] + result.v[tri[2]]) / 3.0;
    result.evaluate(std::clamp(u, 0.0, 1.0), std::clamp(v, 0.0, 1.0), &normals[t]);
  });
  return normals;
}

ValidationMesh build_validation_mesh(const Result& result, const PointCloud& cloud, int threads) {
  require_matching(result, cloud);
  ValidationMesh mesh;
  mesh.triangles = delaunay_triangulate(result.u, result.v);
  const CloudIndex index(cloud.points());
  mesh.suspicious = find_suspicious_triangles(cloud.points(), mesh.triangles, local_spacing(index, threads));
  mesh.surface_normals = surface_normals_at(result, mesh.triangles, threads);
  return mesh;
}

Distortion measure_result_distortion(const Result& result, const PointCloud& cloud, const std::vector<Triangle>& triangles, DomainScaling scaling, int threads) {
  require_matching(result, cloud);
  for (std::size_t t = 0; t < triangles.size(); ++t) {
    for (std::int32_t vertex : triangles[t]) {
      if (vertex < 0 || static_cast<std::size_t>(vertex) >= cloud.size()) fail(ErrorCode::OutOfRange, "triangle " + std::to_string(t) + " has vertex index " + std::to_string(vertex) + " outside the " + std::to_string(cloud.size()) + " points");
    }
  }
  return measure_distortion(cloud.points(), result.u, result.v, triangles, scaling, surface_normals_at(result, triangles, threads));
}

}  // namespace dbs
