// Writing a triangle mesh over a cloud's points with their parameters as texture
// coordinates: Wavefront .obj (+ .mtl naming a texture picture) and binary .ply. Vertices
// are all the points that have a (u,v) in input order, used by a triangle or not, so vertex i
// is cloud point i unless points were cropped (their u and v are NaN: they are left out and
// the later vertices move up).
#pragma once
#include <string>
#include <vector>

#include "geometry.hpp"
#include "triangles.hpp"

namespace dbs {

/// Writes `obj_path` (which must end in .obj, in any case) with one `v` and one `vt` (u, v) per point and
/// `f a/a b/b c/c` per triangle, `mtllib` naming the material file beside it (the same stem,
/// .mtl), whose `map_Kd` names `texture_file` (a file name beside them; the caller writes
/// it). Throws Error(InvalidArgument) for sizes that differ or a path without .obj,
/// Error(OutOfRange) naming a triangle with a vertex outside the points, Error(Io) naming the
/// file that cannot be written.
void write_obj_mesh(const std::string& obj_path, const std::vector<Vec3>& points, const std::vector<double>& u, const std::vector<double>& v, const std::vector<Triangle>& triangles, const std::string& texture_file);

/// Writes a binary little-endian PLY: vertex (float x, y, z, u, v), face (list uchar int
/// vertex_indices). Errors as write_obj_mesh.
void write_ply_mesh(const std::string& path, const std::vector<Vec3>& points, const std::vector<double>& u, const std::vector<double>& v, const std::vector<Triangle>& triangles);

}  // namespace dbs
