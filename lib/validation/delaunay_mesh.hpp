// Method (a) of the paper's section 7: a 2D Delaunay triangulation of the parameters
// (u,v), whose triangles, taken over the 3D points, form a mesh of the cloud. Only
// delaunay_mesh.cpp knows Qhull (reentrant library, libqhull_r).
#pragma once
#include <vector>

#include "triangles.hpp"

namespace dbs {

/// Delaunay triangulation of the points (u[i], v[i]). Every triangle is counter-clockwise in
/// (u,v) and has non-zero (u,v) area; a point whose (u,v) coincides with another's (or lies
/// within Qhull's round-off of it) is the vertex of no triangle. Throws Error(InvalidArgument)
/// when u and v differ in size or hold more than INT32_MAX points, Error(NonFinite) naming
/// the first non-finite parameter, Error(Degenerate) when the points are fewer than three
/// distinct ones or all lie on one line.
std::vector<Triangle> delaunay_triangulate(const std::vector<double>& u, const std::vector<double>& v);

}  // namespace dbs
