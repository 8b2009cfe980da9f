#include "textured_mesh.hpp"

#include "distortion.hpp"
#include "error.hpp"
#include "mesh_files.hpp"
#include "png_file.hpp"
#include "text_io.hpp"

namespace dbs {

void write_textured_obj(const std::string& obj_path, const std::vector<Vec3>& points, const std::vector<double>& u, const std::vector<double>& v, const std::vector<Triangle>& triangles, const RgbImage& texture) {
  if (lowercase_extension(obj_path) != ".obj") fail(ErrorCode::InvalidArgument, "textured mesh path '" + obj_path + "' does not end in .obj");
  const std::string stem = obj_path.substr(0, obj_path.size() - 4);
  const std::string texture_path = stem + "_texture.png";
  const std::size_t slash = texture_path.find_last_of("/\\");
  const std::string texture_file = slash == std::string::npos ? texture_path : texture_path.substr(slash + 1);
  write_obj_mesh(obj_path, points, u, v, triangles, texture_file);
  write_png(texture_path, texture);
}

void write_textured_obj(const std::string& obj_path, const std::vector<Vec3>& points, const std::vector<double>& u, const std::vector<double>& v, const std::vector<Triangle>& triangles, const std::vector<Vec3>& reference_normals) {
  const Distortion d = measure_distortion(points, u, v, triangles, DomainScaling::PerAxis, reference_normals);
  const CirclePattern pattern(d.summary.scale_u, d.summary.scale_v);
  write_textured_obj(obj_path, points, u, v, triangles, pattern.texture(kTexturePixels));
}

}  // namespace dbs
