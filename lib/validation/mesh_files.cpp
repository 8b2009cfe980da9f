#include "mesh_files.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <initializer_list>

#include "error.hpp"
#include "little_endian.hpp"
#include "text_io.hpp"

namespace dbs {
namespace {

/// Checks the mesh and numbers the vertices written: a point without a (u,v) (NaN: a cropped
/// point) is left out and the later ones move up; -1 for those left out.
std::vector<std::int32_t> check_mesh(const std::string& path, const std::vector<Vec3>& points, const std::vector<double>& u, const std::vector<double>& v, const std::vector<Triangle>& triangles) {
  if (u.size() != points.size() || v.size() != points.size()) fail(ErrorCode::InvalidArgument, "mesh file '" + path + "': " + std::to_string(points.size()) + " points but " + std::to_string(u.size()) + " u and " + std::to_string(v.size()) + " v values");
  std::vector<std::int32_t> written(points.size(), -1);
  std::int32_t next = 0;
  for (std::size_t i = 0; i < points.size(); ++i)
    if (!std::isnan(u[i]) && !std::isnan(v[i])) written[i] = next++;
  for (std::size_t t = 0; t < triangles.size(); ++t) {
    for (std::int32_t vertex : triangles[t]) {
      if (vertex < 0 || static_cast<std::size_t>(vertex) >= points.size()) fail(ErrorCode::OutOfRange, "mesh file '" + path + "': triangle " + std::to_string(t) + " has vertex index " + std::to_string(vertex) + " outside the " + std::to_string(points.size()) + " points");
      if (written[static_cast<std::size_t>(vertex)] < 0) fail(ErrorCode::NonFinite, "mesh file '" + path + "': triangle " + std::to_string(t) + " uses point " + std::to_string(vertex) + ", which has no (u,v)");
    }
  }
  return written;
}

std::string file_name_of(const std::string& path) {
  std::size_t slash = path.find_last_of("/\\");
  return slash == std::string::npos ? path : path.substr(slash + 1);
}

// Numbers go through append_number (std::to_chars), so the files do not depend on the locale.
void append_numbers(std::string& line, const char* tag, std::initializer_list<double> values) {
  line.clear();
  line += tag;
  for (double x : values) {
    line += ' ';
    append_number(line, x);
  }
  line += '\n';
}

}  // namespace

void write_obj_mesh(const std::string& obj_path, const std::vector<Vec3>& points, const std::vector<double>& u, const std::vector<double>& v, const std::vector<Triangle>& triangles, const std::string& texture_file) {
  if (lowercase_extension(obj_path) != ".obj") fail(ErrorCode::InvalidArgument, "textured mesh path '" + obj_path + "' does not end in .obj");
  const std::vector<std::int32_t> written = check_mesh(obj_path, points, u, v, triangles);
  const std::string stem = obj_path.substr(0, obj_path.size() - 4);
  const std::string mtl_path = stem + ".mtl";
  write_file_bytes(mtl_path, "# libdbs: black disks on white in the parameter domain\nnewmtl dbs_circles\nKa 1 1 1\nKd 1 1 1\nKs 0 0 0\nillum 1\nmap_Kd " + texture_file + "\n");

  OutputFile obj(obj_path);
  obj.write("# libdbs: a mesh of the cloud from the 2D Delaunay triangulation of its (u,v); vt = (u,v)\nmtllib " + file_name_of(mtl_path) + "\n");
  std::string line;
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (written[i] < 0) continue;
    append_numbers(line, "v", {points[i].x(), points[i].y(), points[i].z()});
    obj.write(line);
  }
  for (std::size_t i = 0; i < u.size(); ++i) {
    if (written[i] < 0) continue;
    append_numbers(line, "vt", {u[i], v[i]});
    obj.write(line);
  }
  obj.write("usemtl dbs_circles\n");
  for (const Triangle& t : triangles) {
    line = "f";
    for (std::int32_t vertex : t) {
      const std::int32_t number = written[static_cast<std::size_t>(vertex)] + 1;  // .obj counts from 1
      line += ' ';
      append_integer(line, number);
      line += '/';
      append_integer(line, number);
    }
    line += '\n';
    obj.write(line);
  }
  obj.close();
}

void write_ply_mesh(const std::string& path, const std::vector<Vec3>& points, const std::vector<double>& u, const std::vector<double>& v, const std::vector<Triangle>& triangles) {
  const std::vector<std::int32_t> written = check_mesh(path, points, u, v, triangles);
  const std::size_t vertices = static_cast<std::size_t>(std::count_if(written.begin(), written.end(), [](std::int32_t w) { return w >= 0; }));
  OutputFile ply(path);
  ply.write("ply\nformat binary_little_endian 1.0\ncomment libdbs: mesh of the cloud from the 2D Delaunay triangulation of its (u,v)\n"
            "element vertex " + std::to_string(vertices) + "\nproperty double x\nproperty double y\nproperty double z\nproperty double u\nproperty double v\n"
            "element face " + std::to_string(triangles.size()) + "\nproperty list uchar int vertex_indices\nend_header\n");
  std::string record;
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (written[i] < 0) continue;
    record.clear();
    for (double x : {points[i].x(), points[i].y(), points[i].z(), u[i], v[i]}) append_le_double(record, x);
    ply.write(record);
  }
  for (const Triangle& t : triangles) {
    record.assign(1, static_cast<char>(3));
    for (std::int32_t vertex : t) append_le32(record, static_cast<std::uint32_t>(written[static_cast<std::size_t>(vertex)]));
    ply.write(record);
  }
  ply.close();
}

}  // namespace dbs
