#include "mesh_files.hpp"

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <cstdio>
#include <cstring>

#include "error.hpp"

namespace dbs {
namespace {

void check_mesh(const std::string& path, const std::vector<Vec3>& points, const std::vector<double>& u, const std::vector<double>& v, const std::vector<Triangle>& triangles) {
  if (u.size() != points.size() || v.size() != points.size()) fail(ErrorCode::InvalidArgument, "mesh file '" + path + "': " + std::to_string(points.size()) + " points but " + std::to_string(u.size()) + " u and " + std::to_string(v.size()) + " v values");
  for (std::size_t t = 0; t < triangles.size(); ++t) {
    for (std::int32_t vertex : triangles[t]) {
      if (vertex < 0 || static_cast<std::size_t>(vertex) >= points.size()) fail(ErrorCode::OutOfRange, "mesh file '" + path + "': triangle " + std::to_string(t) + " has vertex index " + std::to_string(vertex) + " outside the " + std::to_string(points.size()) + " points");
    }
  }
}

// A file written through stdio; close() reports any write error with the file's name.
class OutputFile {
 public:
  OutputFile(const std::string& path, const char* mode) : path_(path), file_(std::fopen(path.c_str(), mode)) {
    if (!file_) fail(ErrorCode::Io, "cannot open '" + path + "' for writing");
  }
  ~OutputFile() {
    if (file_) std::fclose(file_);
  }
  OutputFile(const OutputFile&) = delete;
  OutputFile& operator=(const OutputFile&) = delete;
  std::FILE* get() { return file_; }
  void close() {
    bool failed = std::ferror(file_) != 0;
    failed = std::fclose(file_) != 0 || failed;
    file_ = nullptr;
    if (failed) fail(ErrorCode::Io, "cannot write '" + path_ + "'");
  }

 private:
  std::string path_;
  std::FILE* file_;
};

std::string file_name_of(const std::string& path) {
  std::size_t slash = path.find_last_of("/\\");
  return slash == std::string::npos ? path : path.substr(slash + 1);
}

void put_le32(std::FILE* f, std::uint32_t bits) {
  unsigned char b[4] = {static_cast<unsigned char>(bits), static_cast<unsigned char>(bits >> 8), static_cast<unsigned char>(bits >> 16), static_cast<unsigned char>(bits >> 24)};
  std::fwrite(b, 1, 4, f);
}

void put_float(std::FILE* f, double value) {
  float x = static_cast<float>(value);
  std::uint32_t bits;
  std::memcpy(&bits, &x, 4);
  put_le32(f, bits);
}

}  // namespace

void write_textured_obj(const std::string& obj_path, const std::vector<Vec3>& points, const std::vector<double>& u, const std::vector<double>& v, const std::vector<Triangle>& triangles, const RgbImage& texture) {
  const std::size_t ext_size = 4;
  std::string ext = obj_path.size() > ext_size ? obj_path.substr(obj_path.size() - ext_size) : "";
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (ext != ".obj") fail(ErrorCode::InvalidArgument, "textured mesh path '" + obj_path + "' does not end in .obj");
  check_mesh(obj_path, points, u, v, triangles);
  const std::string stem = obj_path.substr(0, obj_path.size() - ext_size);
  const std::string mtl_path = stem + ".mtl", texture_path = stem + "_texture.png";

  write_png(texture_path, texture);
  {
    OutputFile mtl(mtl_path, "w");
    std::fprintf(mtl.get(), "# libdbs: black disks on white in the parameter domain\nnewmtl dbs_circles\nKa 1 1 1\nKd 1 1 1\nKs 0 0 0\nillum 1\nmap_Kd %s\n", file_name_of(texture_path).c_str());
    mtl.close();
  }
  OutputFile obj(obj_path, "w");
  std::FILE* f = obj.get();
  std::fprintf(f, "# libdbs: a mesh of the cloud from the 2D Delaunay triangulation of its (u,v); vt = (u,v)\nmtllib %s\n", file_name_of(mtl_path).c_str());
  for (const Vec3& p : points) std::fprintf(f, "v %.9g %.9g %.9g\n", p.x(), p.y(), p.z());
  for (std::size_t i = 0; i < u.size(); ++i) std::fprintf(f, "vt %.9g %.9g\n", u[i], v[i]);
  std::fprintf(f, "usemtl dbs_circles\n");
  for (const Triangle& t : triangles) {
    std::int32_t a = t[0] + 1, b = t[1] + 1, c = t[2] + 1;
    std::fprintf(f, "f %d/%d %d/%d %d/%d\n", a, a, b, b, c, c);
  }
  obj.close();
}

void write_ply_mesh(const std::string& path, const std::vector<Vec3>& points, const std::vector<double>& u, const std::vector<double>& v, const std::vector<Triangle>& triangles) {
  check_mesh(path, points, u, v, triangles);
  OutputFile ply(path, "wb");
  std::FILE* f = ply.get();
  std::fprintf(f,
               "ply\nformat binary_little_endian 1.0\ncomment libdbs: mesh of the cloud from the 2D Delaunay triangulation of its (u,v)\n"
               "element vertex %zu\nproperty float x\nproperty float y\nproperty float z\nproperty float u\nproperty float v\n"
               "element face %zu\nproperty list uchar int vertex_indices\nend_header\n",
               points.size(), triangles.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    put_float(f, points[i].x());
    put_float(f, points[i].y());
    put_float(f, points[i].z());
    put_float(f, u[i]);
    put_float(f, v[i]);
  }
  for (const Triangle& t : triangles) {
    std::fputc(3, f);
    for (std::int32_t vertex : t) put_le32(f, static_cast<std::uint32_t>(vertex));
  }
  ply.close();
}

}  // namespace dbs
