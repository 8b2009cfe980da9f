// The validation pictures: the circle pattern, the software rasterizer (fit, z-buffer,
// texture, background), the parameter-domain picture, the histogram, the JSON writer.
#include <cmath>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "bitmap_font.hpp"
#include "circle_pattern.hpp"
#include "error.hpp"
#include "json_writer.hpp"
#include "raster_view.hpp"
#include "report_pictures.hpp"

// cmocka last (its fail() macro would hide dbs::fail), with C linkage.
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
extern "C" {
#include <cmocka.h>
}

using dbs::Rgb;
using dbs::Triangle;
using dbs::Vec3;

namespace {

// The unit square at height z, an n x n grid with (u,v) = (x,y), triangles counter-clockwise
// seen from +z; vertex indices start at `first`.
void add_square(double z, int n, int first, std::vector<Vec3>& points, std::vector<double>& u, std::vector<double>& v, std::vector<Triangle>& triangles) {
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      points.emplace_back(static_cast<double>(i) / (n - 1), static_cast<double>(j) / (n - 1), z);
      u.push_back(points.back().x());
      v.push_back(points.back().y());
    }
  for (int j = 0; j + 1 < n; ++j)
    for (int i = 0; i + 1 < n; ++i) {
      int a = first + j * n + i, b = a + 1, c = a + n, d = c + 1;
      triangles.push_back({a, b, d});
      triangles.push_back({a, d, c});
    }
}

int brightness(Rgb c) { return (c[0] + c[1] + c[2]) / 3; }

void test_circle_pattern(void**) {
  const dbs::CirclePattern pattern(3.0, 1.0, 6);  // period 0.5 in scaled units
  double u = 0, v = 0;
  pattern.disk_centre(2, 1, u, v);
  assert_true(std::abs(u - 2.5 * 0.5 / 3.0) < 1e-15 && std::abs(v - 1.5 * 0.5) < 1e-15);
  assert_true(pattern.black(u, v));
  // radius 0.3 periods = 0.15 scaled units = 0.05 in u, 0.15 in v: round on the surface
  assert_true(pattern.black(u + 0.049, v) && !pattern.black(u + 0.051, v));
  assert_true(pattern.black(u, v + 0.149) && !pattern.black(u, v + 0.151));
  assert_false(pattern.black(0.0, 0.0));  // cell corners are white
  const dbs::RgbImage texture = pattern.texture(300);
  assert_int_equal(texture.width(), 300);
  assert_int_equal(texture.height(), 100);
}

void test_render_view(void**) {
  std::vector<Vec3> points;
  std::vector<double> u, v;
  std::vector<Triangle> triangles;
  add_square(0.0, 11, 0, points, u, v, triangles);
  const dbs::CirclePattern pattern(1.0, 1.0, 4);  // disks centred at 0.125 + 0.25 k
  dbs::ViewCamera camera;  // looking down -z, x right, y up
  const int size = 200;
  // fitted with a margin of 4 % of 200 = 8 pixels: x -> 8 + 184 x, y -> 192 - 184 y
  auto pixel = [&](const dbs::RgbImage& image, double x, double y) { return image.at(static_cast<int>(8 + 184 * x), static_cast<int>(192 - 184 * y)); };
  const dbs::RgbImage image = dbs::render_view(points, u, v, triangles, pattern, camera, size, size);
  assert_true(brightness(pixel(image, 0.375, 0.375)) < 60);   // a disk centre
  assert_true(brightness(pixel(image, 0.625, 0.875)) < 60);
  assert_true(brightness(pixel(image, 0.25, 0.25)) > 150);    // a cell corner
  assert_true((image.at(2, 2) == Rgb{236, 238, 242}));        // background outside the square
  assert_true((pixel(image, 0.5, 0.5) != Rgb{236, 238, 242}));

  // A second square in front (z = 1, nearer the camera) whose (u,v) all sit on a cell corner:
  // white everywhere, whichever square is drawn first.
  std::vector<Vec3> both = points;
  std::vector<double> bu = u, bv = v;
  std::vector<Triangle> front_last = triangles;
  std::vector<Vec3> front_points;
  std::vector<double> fu, fv;
  std::vector<Triangle> front;
  add_square(1.0, 11, static_cast<int>(points.size()), front_points, fu, fv, front);
  both.insert(both.end(), front_points.begin(), front_points.end());
  bu.insert(bu.end(), fu.size(), 0.25);
  bv.insert(bv.end(), fv.size(), 0.25);
  front_last.insert(front_last.end(), front.begin(), front.end());
  std::vector<Triangle> front_first = front;
  front_first.insert(front_first.end(), triangles.begin(), triangles.end());
  for (const std::vector<Triangle>* order : {&front_last, &front_first}) {
    const dbs::RgbImage layered = dbs::render_view(both, bu, bv, *order, pattern, camera, size, size);
    assert_true(brightness(pixel(layered, 0.375, 0.375)) > 150);
  }
}

void test_default_view(void**) {
  std::vector<Vec3> points;
  std::vector<double> u, v;
  std::vector<Triangle> triangles;
  add_square(0.0, 5, 0, points, u, v, triangles);
  for (Vec3& p : points) p.x() *= 3.0;  // the largest axis along x
  const dbs::ViewCamera c = dbs::default_view(points, triangles);
  assert_true(c.forward.z() < -0.7);  // looking against the normals (+z), turned a little
  assert_true(std::abs(c.forward.norm() - 1) < 1e-12 && std::abs(c.up.norm() - 1) < 1e-12 && std::abs(c.right.norm() - 1) < 1e-12);
  assert_true(std::abs(c.forward.dot(c.up)) < 1e-12 && std::abs(c.forward.dot(c.right)) < 1e-12 && std::abs(c.up.dot(c.right)) < 1e-12);
  assert_true((c.forward.cross(c.up) - c.right).norm() < 1e-12);
  assert_true(std::abs(c.right.x()) > 0.9);  // the largest axis horizontal
}

void test_parameter_domain(void**) {
  std::vector<Vec3> points;
  std::vector<double> u, v;
  std::vector<Triangle> triangles;
  add_square(0.0, 5, 0, points, u, v, triangles);
  std::vector<dbs::TriangleDistortion> distortion(triangles.size());
  for (dbs::TriangleDistortion& d : distortion) d.conformal = 1.0;
  distortion[0].conformal = dbs::kConformalColourLimit;  // the cell at the origin: darkest red
  const std::vector<dbs::Rect> leaves{{0, 0, 0.5, 1}, {0.5, 0, 1, 1}};
  const std::vector<std::size_t> suspicious{31};  // a triangle of the cell at (u,v) near (1,1)
  const int size = 400;
  const std::vector<std::size_t> turned{6};  // the point (1, 1) of the 5 x 5 grid, (u,v) = (0.25, 0.25)
  const dbs::RgbImage image = dbs::draw_parameter_domain(u, v, triangles, distortion, suspicious, turned, leaves, size);
  assert_int_equal(image.width(), size);
  assert_true(image.height() > size);
  // the plot: margin 16, title 24 -> (u,v) at (16 + 368 u, 40 + 368 (1 - v))
  auto at = [&](double pu, double pv) { return image.at(static_cast<int>(16 + 368 * pu), static_cast<int>(40 + 368 * (1 - pv))); };
  assert_true((at(0.3, 0.6) == dbs::ramp_colour(0.0)));
  assert_true((at(0.2, 0.05) == dbs::ramp_colour(1.0)));   // triangle 0 = (0, 1, 6): below the diagonal of cell (0,0)
  assert_true((at(0.8, 0.95) == Rgb{0, 0, 0}));            // triangle 31 = (18, 24, 23): above the diagonal of the last cell
  assert_true((at(0.95, 0.8) == dbs::ramp_colour(0.0)));  // its neighbour 30 below the diagonal
  assert_true(brightness(image.at(16 + 184, 40 + 100)) < 80);  // the leaves' shared side u = 0.5
  assert_true((image.at(2, 60) == Rgb{255, 255, 255}));     // outside the plot
  assert_true((at(0.25, 0.25) == Rgb{255, 140, 0}));          // the turned point, an orange dot
  assert_true((at(0.25 + 3.0 / 368, 0.25) != Rgb{255, 140, 0}));  // ... of 3 x 3 pixels only
}

void test_histogram(void**) {
  std::vector<double> d;
  for (int i = 0; i < 1000; ++i) d.push_back(0.001 * (i % 100));
  dbs::DistanceStats s;
  s.count = d.size();
  s.mean = 0.0495;
  s.p95 = 0.095;
  s.p99 = 0.099;
  s.max = 0.099;
  s.within = 0.51;
  const dbs::RgbImage image = dbs::draw_distance_histogram(d, s, 0.05, 400, 200);
  assert_int_equal(image.width(), 400);
  assert_int_equal(image.height(), 200);
  // uniform distances: every one of the 50 bars has the same height, up to the plot's top (y = 44)
  const int plot_w = 400 - 56 - 16;
  for (int b = 0; b < 50; ++b) {
    const int x = 56 + b * plot_w / 50 + 1;
    if (b == 25) continue;  // the tolerance line is drawn over this bar
    assert_true((image.at(x, 46) == Rgb{70, 110, 170}));
  }
}

void test_json_and_font(void**) {
  dbs::JsonWriter json;
  json.begin_object();
  json.integer("n", 3);
  json.number("x", 0.5);
  json.number("bad", std::nan(""));
  json.string("s", "a\"b\\c\n");
  json.begin_array("list");
  json.number(1.0);
  json.number(2.5);
  json.end_array();
  json.begin_object("empty");
  json.end_object();
  json.end_object();
  assert_string_equal(json.text().c_str(), "{\n  \"n\": 3,\n  \"x\": 0.5,\n  \"bad\": null,\n  \"s\": \"a\\\"b\\\\c\\n\",\n  \"list\": [\n    1,\n    2.5\n  ],\n  \"empty\": {}\n}");
  dbs::RgbImage image(20, 10);
  dbs::draw_text(image, 1, 1, "1", {0, 0, 0});
  // '1': its stem is the middle column (x = 1 + 2) from the top row to the bottom one
  for (int row = 0; row < 7; ++row) assert_true((image.at(3, 1 + row) == Rgb{0, 0, 0}));
  assert_true((image.at(1, 4) == Rgb{255, 255, 255}));
  assert_int_equal(dbs::text_width("abc", 2), 36);
}

}  // namespace

int main() {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(test_circle_pattern),
      cmocka_unit_test(test_render_view),
      cmocka_unit_test(test_default_view),
      cmocka_unit_test(test_parameter_domain),
      cmocka_unit_test(test_histogram),
      cmocka_unit_test(test_json_and_font),
  };
  return cmocka_run_group_tests(tests, nullptr, nullptr);
}
