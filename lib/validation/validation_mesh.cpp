#include "validation_mesh.hpp"

#include <algorithm>
#include <string>

#include "cloud_index.hpp"
#include "delaunay_mesh.hpp"
#include "error.hpp"
#include "fold_measure.hpp"
#include "parallel.hpp"
#include "suspicious_triangles.hpp"

namespace dbs {
namespace {

void require_matching(const Result& result, const PointCloud& cloud) {
  if (result.u.size() != cloud.size()) fail(ErrorCode::InvalidArgument, "the result has " + std::to_string(result.u.size()) + " points but the cloud " + std::to_string(cloud.size()) + ": pass the cloud that was parameterized");
}

/// The Delaunay triangles of the points that have a (u,v): all, or all but the cropped ones
/// (their vertex indices are those of the cloud either way).
std::vector<Triangle> triangulate_kept(const Result& result) {
  if (result.cropped_points == 0) return delaunay_triangulate(result.u, result.v);
  std::vector<std::int32_t> kept;
  std::vector<double> u, v;
  for (std::size_t i = 0; i < result.u.size(); ++i) {
    if (result.is_cropped(i)) continue;
    kept.push_back(static_cast<std::int32_t>(i));
    u.push_back(result.u[i]);
    v.push_back(result.v[i]);
  }
  std::vector<Triangle> triangles = delaunay_triangulate(u, v);
  for (Triangle& t : triangles)
    for (std::int32_t& vertex : t) vertex = kept[static_cast<std::size_t>(vertex)];
  return triangles;
}

}  // namespace

std::vector<Vec3> oriented_cloud_normals(const Result& result, const PointCloud& cloud, int threads, std::size_t max_points) {
  require_matching(result, cloud);
  std::vector<std::size_t> kept;
  for (std::size_t i = 0; i < cloud.size(); ++i)
    if (!result.left_out(i)) kept.push_back(i);
  // The judged points: every kept one, or an even sample of max_points of them.
  const std::size_t n = kept.size(), count = std::min(n, std::max<std::size_t>(max_points, 1));
  std::vector<std::size_t> judged(count);
  std::vector<Vec3> points(count);
  std::vector<double> u(count), v(count);
  for (std::size_t k = 0; k < count; ++k) {
    judged[k] = kept[static_cast<std::size_t>(static_cast<unsigned long long>(k) * n / count)];
    points[k] = cloud.points()[judged[k]];
    u[k] = result.u[judged[k]];
    v[k] = result.v[judged[k]];
  }
  const FoldMeasure folds = measure_folds(points, u, v, result.noise, threads);
  if (count == n) {
    std::vector<Vec3> normals(cloud.size(), Vec3::Zero());
    for (std::size_t k = 0; k < count; ++k) normals[judged[k]] = folds.right_normal[k];
    return normals;
  }
  // The others take the normal of their nearest judged point; the points left out keep none.
  std::vector<Vec3> normals = spread_from_judged(cloud.points(), judged, folds.right_normal, resolve_threads(threads));
  for (std::size_t i = 0; i < cloud.size(); ++i)
    if (result.left_out(i)) normals[i] = Vec3::Zero();
  return normals;
}

std::vector<Vec3> reference_normals_at(const Result& result, const std::vector<Vec3>& cloud_normals, const std::vector<Triangle>& triangles, int threads) {
  if (cloud_normals.size() != result.u.size()) fail(ErrorCode::InvalidArgument, "reference_normals_at: " + std::to_string(cloud_normals.size()) + " cloud normals for " + std::to_string(result.u.size()) + " points");
  std::vector<Vec3> normals(triangles.size());
  parallel_for(triangles.size(), resolve_threads(threads), [&](std::size_t t) {
    const Triangle& tri = triangles[t];
    normals[t] = cloud_normals[tri[0]] + cloud_normals[tri[1]] + cloud_normals[tri[2]];
    if (normals[t] != Vec3::Zero()) return;
    double u = (result.u[tri[0]] + result.u[tri[1]] + result.u[tri[2]]) / 3.0;
    double v = (result.v[tri[0]] + result.v[tri[1]] + result.v[tri[2]]) / 3.0;
    result.evaluate(std::clamp(u, 0.0, 1.0), std::clamp(v, 0.0, 1.0), &normals[t]);
  });
  return normals;
}

ValidationMesh build_validation_mesh(const Result& result, const PointCloud& cloud, int threads) {
  require_matching(result, cloud);
  ValidationMesh mesh;
  mesh.triangles = triangulate_kept(result);
  const CloudIndex index(cloud.points());
  mesh.suspicious = find_suspicious_triangles(cloud.points(), mesh.triangles, local_spacing(index, threads));
  mesh.reference_normals = reference_normals_at(result, oriented_cloud_normals(result, cloud, threads), mesh.triangles, threads);
  return mesh;
}

Distortion measure_result_distortion(const Result& result, const PointCloud& cloud, const std::vector<Triangle>& triangles, DomainScaling scaling, int threads) {
  require_matching(result, cloud);
  for (std::size_t t = 0; t < triangles.size(); ++t) {
    for (std::int32_t vertex : triangles[t]) {
      if (vertex < 0 || static_cast<std::size_t>(vertex) >= cloud.size()) fail(ErrorCode::OutOfRange, "triangle " + std::to_string(t) + " has vertex index " + std::to_string(vertex) + " outside the " + std::to_string(cloud.size()) + " points");
    }
  }
  const std::vector<Vec3> cloud_normals = oriented_cloud_normals(result, cloud, threads);
  if (result.cropped_points == 0) return measure_distortion(cloud.points(), result.u, result.v, triangles, scaling, reference_normals_at(result, cloud_normals, triangles, threads));
  // Triangles with a cropped vertex have no (u,v) image: measured are the others, and the
  // result lists every triangle in the caller's order.
  std::vector<Triangle> measured;
  std::vector<std::size_t> position;
  for (std::size_t t = 0; t < triangles.size(); ++t) {
    const Triangle& tri = triangles[t];
    if (result.is_cropped(tri[0]) || result.is_cropped(tri[1]) || result.is_cropped(tri[2])) continue;
    measured.push_back(tri);
    position.push_back(t);
  }
  Distortion part = measure_distortion(cloud.points(), result.u, result.v, measured, scaling, reference_normals_at(result, cloud_normals, measured, threads));
  Distortion whole;
  whole.summary = part.summary;
  whole.summary.cropped = triangles.size() - measured.size();
  whole.triangles.resize(triangles.size());
  for (TriangleDistortion& d : whole.triangles) d.cropped = true;
  for (std::size_t k = 0; k < measured.size(); ++k) whole.triangles[position[k]] = part.triangles[k];
  return whole;
}

}  // namespace dbs
