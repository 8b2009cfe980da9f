// Mesh files: the OBJ names its MTL, the MTL its texture, the texture decodes to the
// expected size with disks where the pattern puts them; one vt per v; the binary PLY has the
// announced elements and values.
#include <cstdio>
#include <cstring>
#include <sstream>
#include <string>
#include <vector>

#include "circle_pattern.hpp"
#include "error.hpp"
#include "mesh_files.hpp"
#include "png_file.hpp"
#include "textured_mesh.hpp"
#include "core_test_support.hpp"  // last of the dbs headers

using dbs::Triangle;
using dbs::Vec3;

namespace {

using core_test::error_code_of;

using core_test::read_all;

std::string temp_file(const std::string& name) { return core_test::tmp_path("mesh_files_" + name); }

std::size_t count_lines(const std::string& text, const std::string& prefix) {
  std::size_t count = 0;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) count += line.compare(0, prefix.size(), prefix) == 0;
  return count;
}

// A 3 x 2 grid of points, 4 triangles, plus one point no triangle uses.
struct SmallMesh {
  std::vector<Vec3> points{Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(2, 0, 0.5), Vec3(0, 1, 0), Vec3(1, 1, 0), Vec3(2, 1, 0.5), Vec3(9, 9, 9)};
  std::vector<double> u{0, 0.5, 1, 0, 0.5, 1, 0.25}, v{0, 0, 0, 1, 1, 1, 0.5};
  std::vector<Triangle> triangles{{0, 1, 4}, {0, 4, 3}, {1, 2, 5}, {1, 5, 4}};
};

void test_obj_mtl_texture(void**) {
  const SmallMesh m;
  const dbs::CirclePattern pattern(2.0, 1.0, 8);
  const std::string obj = temp_file("small.obj");
  dbs::write_textured_obj(obj, m.points, m.u, m.v, m.triangles, pattern.texture(256));
  const std::string text = read_all(obj);
  assert_true(text.find("\nmtllib mesh_files_small.mtl\n") != std::string::npos);
  assert_int_equal(count_lines(text, "v "), m.points.size());
  assert_int_equal(count_lines(text, "vt "), m.points.size());
  assert_int_equal(count_lines(text, "f "), m.triangles.size());
  assert_true(text.find("\nvt 0.25 0.5\n") != std::string::npos);  // the unused point's (u,v) too
  assert_true(text.find("\nf 2/2 3/3 6/6\n") != std::string::npos);  // triangle {1, 2, 5}, 1-based, vt = v
  assert_true(text.find("\nusemtl dbs_circles\n") != std::string::npos);
  const std::string mtl = read_all(temp_file("small.mtl"));
  assert_true(mtl.find("newmtl dbs_circles\n") != std::string::npos);
  assert_true(mtl.find("\nmap_Kd mesh_files_small_texture.png\n") != std::string::npos);
  // The texture: twice as wide as high (scale 2 : 1), 8 disks across.
  const dbs::RgbImage texture = dbs::read_png(temp_file("small_texture.png"));
  assert_int_equal(texture.width(), 256);
  assert_int_equal(texture.height(), 128);
  double cu = 0, cv = 0;
  pattern.disk_centre(3, 2, cu, cv);
  const int x = static_cast<int>(cu * 256), y = static_cast<int>((1.0 - cv) * 128);
  assert_true((texture.at(x, y) == dbs::Rgb{0, 0, 0}));
  assert_true((texture.at(32, 128 - 32) == dbs::Rgb{255, 255, 255}));  // a cell corner: (u,v) = (1/8, 1/4)
  for (const char* name : {"small.obj", "small.mtl", "small_texture.png"}) std::remove(temp_file(name).c_str());
}

void test_ply(void**) {
  const SmallMesh m;
  const std::string path = temp_file("small.ply");
  dbs::write_ply_mesh(path, m.points, m.u, m.v, m.triangles);
  const std::string data = read_all(path);
  const std::string end = "end_header\n";
  const std::size_t body = data.find(end) + end.size();
  const std::string header = data.substr(0, body);
  assert_true(header.rfind("ply\nformat binary_little_endian 1.0\n", 0) == 0);
  assert_true(header.find("element vertex 7\n") != std::string::npos);
  assert_true(header.find("property double x\nproperty double y\nproperty double z\nproperty double u\nproperty double v\n") != std::string::npos);
  assert_true(header.find("element face 4\nproperty list uchar int vertex_indices\n") != std::string::npos);
  assert_int_equal(data.size() - body, 7 * 40 + 4 * 13);
  // vertex 2: x y z u v = 2 0 0.5 1 0; face 2: 3 vertices 1 2 5 (little-endian on this host)
  double vertex[5];
  std::memcpy(vertex, data.data() + body + 2 * 40, sizeof vertex);
  assert_true(vertex[0] == 2.0 && vertex[1] == 0.0 && vertex[2] == 0.5 && vertex[3] == 1.0 && vertex[4] == 0.0);
  const char* face = data.data() + body + 7 * 40 + 2 * 13;
  std::int32_t indices[3];
  std::memcpy(indices, face + 1, sizeof indices);
  assert_int_equal(face[0], 3);
  assert_true(indices[0] == 1 && indices[1] == 2 && indices[2] == 5);
  std::remove(path.c_str());
}

void test_errors(void**) {
  SmallMesh m;
  const dbs::RgbImage texture(4, 4);
  assert_int_equal(error_code_of([&] { dbs::write_textured_obj(temp_file("x.ply"), m.points, m.u, m.v, m.triangles, texture); }), dbs::ErrorCode::InvalidArgument);
  assert_int_equal(error_code_of([&] { dbs::write_ply_mesh(std::string(DBS_TEST_TMP_DIR) + "/no/such/dir/x.ply", m.points, m.u, m.v, m.triangles); }), dbs::ErrorCode::Io);
  m.triangles.push_back({0, 1, 7});
  assert_int_equal(error_code_of([&] { dbs::write_ply_mesh(temp_file("bad.ply"), m.points, m.u, m.v, m.triangles); }), dbs::ErrorCode::OutOfRange);
  m.triangles.pop_back();
  m.u.pop_back();
  assert_int_equal(error_code_of([&] { dbs::write_ply_mesh(temp_file("bad.ply"), m.points, m.u, m.v, m.triangles); }), dbs::ErrorCode::InvalidArgument);
  assert_int_equal(error_code_of([] { dbs::CirclePattern(0.0, 1.0); }), dbs::ErrorCode::InvalidArgument);
}

}  // namespace

int main() {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(test_obj_mtl_texture),
      cmocka_unit_test(test_ply),
      cmocka_unit_test(test_errors),
  };
  return cmocka_run_group_tests(tests, nullptr, nullptr);
}
