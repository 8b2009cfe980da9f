// CornerFrameBox: the box measured along a boundary's corners has the same diagonal after any
// rigid motion, where the axis-aligned box does not.
#include <cmath>

#include "analytic_clouds.hpp"
#include "corner_frame.hpp"

// cmocka last: its fail() macro would hide dbs::fail.
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
extern "C" {
#include <cmocka.h>
}

using namespace dbs;
using namespace dbs_test;

namespace {

/// A 3 x 2 rectangle with a bump of height 0.5 in the middle.
Vec3 bumped_rectangle(double a, double b) { return Vec3(3 * a, 2 * b, 0.5 * std::sin(M_PI * a) * std::sin(M_PI * b)); }

double frame_diagonal(const Surface& s) {
  CornerFrameBox box(boundary_of(s, 9));
  for (int j = 0; j <= 20; ++j)
    for (int i = 0; i <= 20; ++i) box.extend(s(i / 20.0, j / 20.0));
  return box.diagonal();
}

void aligned_frame_gives_the_axis_aligned_box(void**) {
  // The rectangle's corners lie along x and y: the box is the ordinary one, 3 x 2 x 0.5.
  assert_true(std::abs(frame_diagonal(bumped_rectangle) - std::sqrt(9.0 + 4.0 + 0.25)) < 1e-12);
}

void rigid_motion_keeps_the_diagonal(void**) {
  const double reference = frame_diagonal(bumped_rectangle);
  const Surface moved = [](double a, double b) { return move_and_scale(bumped_rectangle(a, b), 1.0); };
  assert_true(std::abs(frame_diagonal(moved) - reference) < 1e-12 * reference);
  // ... where the axis-aligned box of the moved points grows.
  Box3 aligned;
  for (int j = 0; j <= 20; ++j)
    for (int i = 0; i <= 20; ++i) aligned.extend(moved(i / 20.0, j / 20.0));
  assert_true(aligned.diagonal() > 1.05 * reference);
}

void skewed_corners_give_an_orthonormal_frame(void**) {
  // Sides at 63 degrees to each other: the frame is still orthonormal, so the box of two
  // points has their distance as its diagonal, in any frame.
  const Surface skewed = [](double a, double b) { return Vec3(a + 0.5 * b, b, 0.3 * a * b); };
  CornerFrameBox box(boundary_of(skewed, 9));
  box.extend(Vec3(0, 0, 0));
  box.extend(Vec3(1, -2, 3));
  assert_true(std::abs(box.diagonal() - std::sqrt(14.0)) < 1e-12);
}

}  // namespace

int main() {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(aligned_frame_gives_the_axis_aligned_box),
      cmocka_unit_test(rigid_motion_keeps_the_diagonal),
      cmocka_unit_test(skewed_corners_give_an_orthonormal_frame),
  };
  return cmocka_run_group_tests(tests, nullptr, nullptr);
}
