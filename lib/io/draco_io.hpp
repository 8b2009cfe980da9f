// The only part of libdbs that knows Draco: decoding positions from .drc files and
// encoding a point cloud with texture coordinates to .drc (.ply and .obj are read by
// ply_vertices and obj_vertices, to exact doubles, in every build).
#pragma once
#include <string>
#include <vector>

#include "geometry.hpp"

namespace dbs {

/// True when libdbs was built with Draco.
bool draco_available();
/// POSITION attribute of a .drc file. Throws Error(Io/Parse/NonFinite/Empty/Unsupported)
/// naming the file and the point (numbered from 0) at fault; Error(Parse) before decoding
/// when a point-cloud header claims more than 1024 points per byte of the file.
std::vector<Vec3> read_positions_with_draco(const std::string& path);
/// TEX_COORD (u,v) per point of a .drc file, in point order (what write_draco_point_cloud
/// wrote). Errors as read_positions_with_draco; Error(Parse) when there is no TEX_COORD.
std::vector<Vec2> read_tex_coords_with_draco(const std::string& path);
/// Writes a Draco point cloud with POSITION and TEX_COORD (u,v) attributes.
void write_draco_point_cloud(const std::string& path, const std::vector<Vec3>& points, const std::vector<double>& u, const std::vector<double>& v);

}  // namespace dbs
