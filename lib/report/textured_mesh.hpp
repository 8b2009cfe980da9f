// A textured .obj of a validation mesh: the mesh files (validation/mesh_files) plus the
// circle-pattern texture PNG beside them, so any viewer shows how the (u,v) lie on the surface.
#pragma once
#include <string>
#include <vector>

#include "circle_pattern.hpp"
#include "geometry.hpp"
#include "triangles.hpp"

namespace dbs {

/// The texture's longer side in pixels.
constexpr int kTexturePixels = 1024;

/// Writes `obj_path` (.obj), STEM.mtl and STEM_texture.png with `pattern`'s texture.
/// Errors as write_obj_mesh and write_png.
void write_textured_obj(const std::string& obj_path, const std::vector<Vec3>& points, const std::vector<double>& u, const std::vector<double>& v, const std::vector<Triangle>& triangles, const RgbImage& texture);

/// The same with the texture whose disks are round on this mesh (its per-axis domain
/// scaling measured against `reference_normals`, one per triangle).
void write_textured_obj(const std::string& obj_path, const std::vector<Vec3>& points, const std::vector<double>& u, const std::vector<double>& v, const std::vector<Triangle>& triangles, const std::vector<Vec3>& reference_normals);

}  // namespace dbs
