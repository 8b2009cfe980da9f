// The validation mesh of a parameterization (method (a) of the paper's section 7): the 2D
// Delaunay triangulation of the result's (u,v) over the cloud's points, its suspicious
// (bridging) triangles, and per triangle the base surface's normal, which tells a triangle
// that the parameterization folded (its 3D normal then opposes the surface's) from one that
// is merely tilted.
#pragma once
#include <cstddef>
#include <vector>

#include "distortion.hpp"
#include "point_cloud.hpp"
#include "result.hpp"
#include "triangles.hpp"

namespace dbs {

struct ValidationMesh {
  std::vector<Triangle> triangles;            // counter-clockwise in (u,v)
  std::vector<std::size_t> suspicious;        // indices into triangles, ascending
  std::vector<Vec3> surface_normals;          // one per triangle
};

/// Throws Error(InvalidArgument) when the cloud's size differs from the result's, and the
/// errors of delaunay_triangulate. `threads` as Options::threads; the mesh does not depend on it.
ValidationMesh build_validation_mesh(const Result& result, const PointCloud& cloud, int threads);

/// The base surface's unit normal at the (u,v) centroid of each triangle (vertex indices
/// must be valid for the result's points).
std::vector<Vec3> surface_normals_at(const Result& result, const std::vector<Triangle>& triangles, int threads);

/// Distortion of `triangles` (any mesh over the result's points) judged against the base
/// surface's normals: measure_distortion with surface_normals_at. Errors as measure_distortion.
Distortion measure_result_distortion(const Result& result, const PointCloud& cloud, const std::vector<Triangle>& triangles, DomainScaling scaling, int threads);

}  // namespace dbs
