// Triangles of a mesh over a cloud that bridge across the surface: a 2D triangulation of the
// parameters that is wrong somewhere connects points that are far apart in 3D. A triangle is
// suspicious when one of its 3D edges is longer than `factor` times the local spacing of
// both of that edge's end points. The local spacing of a point is the distance to its
// kSpacingNeighbour-th nearest other point of the cloud (points at distance zero skipped),
// which a regular sample puts about one ring of neighbours away: a Delaunay edge of a
// correct mesh is at most a little longer than that. (The Delaunay triangulation spans the
// convex hull of the (u,v): where a sample's outline is ragged, the slivers along it are
// suspicious too, and rightly, as the mesh does bridge there.)
#pragma once
#include <cstddef>
#include <vector>

#include "cloud_index.hpp"
#include "triangles.hpp"

namespace dbs {

constexpr std::size_t kSpacingNeighbour = 6;
constexpr double kSuspiciousEdgeFactor = 4.0;

/// Local spacing of every indexed point (see above); 0 for a point whose neighbours all
/// coincide with it. `threads` as resolve_threads(); the result does not depend on it.
std::vector<double> local_spacing(const CloudIndex& index, int threads);

/// Indices (ascending) of the suspicious triangles; `spacing` from local_spacing(). Throws
/// Error(OutOfRange) naming a triangle with a vertex index outside the points.
std::vector<std::size_t> find_suspicious_triangles(const std::vector<Vec3>& points, const std::vector<Triangle>& triangles, const std::vector<double>& spacing, double factor = kSuspiciousEdgeFactor);

}  // namespace dbs
