// The validation mesh of a parameterization (method (a) of the paper's section 7): the 2D
// Delaunay triangulation of the result's (u,v) over the cloud's points, its suspicious
// (bridging) triangles, and per triangle a reference normal, which tells a triangle that the
// parameterization folded (its 3D normal then opposes the reference) from one that is merely
// tilted. The reference is the cloud's own normal, oriented by the fold measure
// (FoldMeasure::right_normal), not the base surface's: where the surface turned its back on
// the cloud (a pleat, a turned sheet) its normals flip with it, and every well-ordered
// triangle over that sheet would count as folded while the folds of the sheet itself hid.
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
  std::vector<Vec3> reference_normals;        // one per triangle (reference_normals_at)
};

/// Throws Error(InvalidArgument) when the cloud's size differs from the result's, and the
/// errors of delaunay_triangulate. `threads` as Options::threads; the mesh does not depend on it.
ValidationMesh build_validation_mesh(const Result& result, const PointCloud& cloud, int threads);

/// The most points oriented_cloud_normals judges: the fold measure costs about 7 us a point,
/// so on a larger cloud it judges an even sample of this many (about 1.4 s), and the others
/// take the normal of their nearest judged point.
constexpr std::size_t kMaxNormalPoints = 200000;

/// Per point of the cloud, the normal towards which a surface agreeing with the result's
/// (u,v) turns: FoldMeasure::right_normal of the fold measure of the points not left out
/// (Result::left_out), or of an even sample of `max_points` (>= 1) of them, at the result's
/// noise level; a point not judged takes its nearest judged point's. Zero where the measure
/// gives none and for the points left out.
std::vector<Vec3> oriented_cloud_normals(const Result& result, const PointCloud& cloud, int threads, std::size_t max_points = kMaxNormalPoints);

/// Per triangle (vertex indices valid for the result's points), the normal its orientation is
/// judged against: the sum of its vertices' `cloud_normals` (oriented_cloud_normals), or the
/// base surface's unit normal at the triangle's (u,v) centroid where that sum is zero (no
/// vertex has a cloud normal).
std::vector<Vec3> reference_normals_at(const Result& result, const std::vector<Vec3>& cloud_normals, const std::vector<Triangle>& triangles, int threads);

/// Distortion of `triangles` (any mesh over the result's points) judged against the reference
/// normals (reference_normals_at). Errors as measure_distortion.
Distortion measure_result_distortion(const Result& result, const PointCloud& cloud, const std::vector<Triangle>& triangles, DomainScaling scaling, int threads);

}  // namespace dbs
