// The boundary's picture (lib/report/boundary_report): on a plate with a round hole whose
// boundary is found from the cloud, each side shows in its colour, the hole in magenta and the
// corners in black, in both views; the picture written reads back the same.
#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <random>
#include <string>
#include <vector>

#include "boundary_detect.hpp"
#include "boundary_report.hpp"
#include "error.hpp"
#include "png_file.hpp"

#include "core_test_support.hpp"

namespace {

using dbs::Vec3;

/// A 1.2 x 1 plate, gently curved, 6,000 random points with a round hole of radius 0.15.
std::vector<Vec3> holed_plate() {
  std::mt19937_64 random(7);
  std::uniform_real_distribution<double> x(0.0, 1.2), y(0.0, 1.0);
  std::vector<Vec3> points;
  while (points.size() < 6000) {
    const double a = x(random), b = y(random);
    if (std::hypot(a - 0.6, b - 0.5) < 0.15) continue;
    points.emplace_back(a, b, 0.05 * std::sin(2.0 * a));
  }
  return points;
}

/// Pixels of each colour in columns [x0, x1).
std::map<dbs::Rgb, int> colours(const dbs::RgbImage& image, int x0, int x1) {
  std::map<dbs::Rgb, int> count;
  for (int y = 0; y < dbs::kBoundaryViewSize; ++y)
    for (int x = x0; x < x1; ++x) ++count[image.at(x, y)];
  return count;
}

void shows_sides_corners_and_holes(void**) {
  const std::vector<Vec3> points = holed_plate();
  const dbs::DetectedBoundary found = dbs::detect_boundary(points, 24, 1);
  assert_int_equal(found.holes.size(), 1);
  const dbs::RgbImage image = dbs::draw_boundary_picture(points, found.boundary, found.holes);
  assert_int_equal(image.width(), 2 * dbs::kBoundaryViewSize);
  assert_int_equal(image.height(), dbs::kBoundaryViewSize + dbs::kBoundaryLegendHeight);
  const std::array<dbs::Rgb, 4> sides{{{205, 35, 35}, {30, 150, 40}, {40, 80, 210}, {235, 140, 20}}};
  const dbs::Rgb magenta{190, 40, 190}, black{0, 0, 0}, grey{175, 175, 175};
  const std::map<dbs::Rgb, int> above = colours(image, 0, dbs::kBoundaryViewSize), side = colours(image, dbs::kBoundaryViewSize + 1, 2 * dbs::kBoundaryViewSize);
  for (const dbs::Rgb& c : sides) {
    // From above each side runs across about a third of the view, 3 pixels wide.
    std::printf("side colour (%d,%d,%d): %d pixels from above, %d from the side\n", c[0], c[1], c[2], above.count(c) ? above.at(c) : 0, side.count(c) ? side.at(c) : 0);
    assert_true(above.count(c) && above.at(c) > 3 * 200);
    assert_true(side.count(c) && side.at(c) > 0);
  }
  // The hole: a circle of radius 0.15 of 1.2 across 424 pixels, 3 wide: about 1,000 pixels.
  assert_true(above.count(magenta) && above.at(magenta) > 600);
  assert_true(above.count(black) && above.at(black) >= 4 * 49);
  assert_true(above.count(grey) && above.at(grey) > 1000);

  const std::string dir = "test_boundary_report_dir";
  dbs::write_boundary_report(points, found.boundary, found.holes, dir);
  const dbs::RgbImage back = dbs::read_png(dir + "/boundary.png");
  assert_true(back.bytes() == image.bytes());
  assert_true(std::filesystem::file_size(dir + "/boundary.json") > 100);
  std::filesystem::remove_all(dir);
  // A glitch far outside the scan (1e6, then 1e200 away) is left out of the framing: the
  // scan still fills its views, and the legend says what was not drawn.
  for (double far : {1e6, 1e200}) {
    std::vector<Vec3> glitched = points;
    glitched.emplace_back(far, 0.0, 0.0);
    const dbs::RgbImage framed = dbs::draw_boundary_picture(glitched, found.boundary, found.holes);
    const std::map<dbs::Rgb, int> seen = colours(framed, 0, dbs::kBoundaryViewSize);
    assert_true(seen.count(grey) && std::abs(seen.at(grey) - above.at(grey)) < above.at(grey) / 10);
  }
  // No points: refused with a message.
  bool refused = false;
  try {
    dbs::draw_boundary_picture({}, found.boundary, {});
  } catch (const dbs::Error& e) {
    refused = e.code() == dbs::ErrorCode::InvalidArgument && std::string(e.what()).find("the cloud is empty") != std::string::npos;
  }
  assert_true(refused);
}

}  // namespace

int main() {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(shows_sides_corners_and_holes),
  };
  return cmocka_run_group_tests(tests, nullptr, nullptr);
}
