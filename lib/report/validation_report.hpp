// A validation report of a parameterization on disk: the four methods of the paper's
// section 7 as files a user can open and numbers a script can test.
//
//   mesh.obj, mesh.mtl, mesh_texture.png  the Delaunay mesh of the (u,v) with the circle
//                                         texture (method (a), and (c) in any viewer)
//   mesh.ply                              the same mesh, binary PLY with u, v per vertex
//   view.png                              the mesh shaded and textured from the default view (c)
//   domain.png                            the parameter domain: leaf rectangles, triangles
//                                         coloured by conformal distortion (b)
//   distances.png                         histogram of the point-to-surface distances (d)
//   summary.json                          options, timings, quadtree, patches, distance
//                                         statistics, mesh and distortion figures
#pragma once
#include <string>

#include "options.hpp"
#include "point_cloud.hpp"
#include "result.hpp"

namespace dbs {

/// Writes the report into `dir`, creating it (and missing parents) if needed. `options` are
/// those the result was made with (reported, and their thread count used). The distance
/// tolerance is the result's accuracy target. Throws Error(InvalidArgument) when the cloud
/// does not match the result, Error(Io) naming a file or directory that cannot be written,
/// and the errors of the validation mesh.
void write_validation_report(const Result& result, const PointCloud& cloud, const Options& options, const std::string& dir);

}  // namespace dbs
