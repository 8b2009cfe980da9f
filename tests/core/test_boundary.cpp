// Boundary: validation (codes and messages naming the side, point or corner at fault),
// exact repair of small corner misses, the exact-corner constructor for split sides.
#include <cmath>
#include <cstring>
#include <limits>
#include <string>
#include <vector>

#include "boundary.hpp"
#include "error.hpp"

// cmocka last (its fail() macro would hide dbs::fail), with C linkage (its header does
// not declare it).
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
extern "C" {
#include <cmocka.h>
}

using dbs::Boundary;
using dbs::ErrorCode;
using dbs::Polyline;
using dbs::Side;
using dbs::Vec3;

namespace {

using Points = std::vector<Vec3>;

// A 10 x 10 square with a bump in z; sides with 2 to 4 points.
struct Sides {
  Points bottom = {Vec3(0, 0, 0), Vec3(4, 0, 1), Vec3(10, 0, 0)};
  Points right = {Vec3(10, 0, 0), Vec3(10, 10, 0)};
  Points top = {Vec3(0, 10, 0), Vec3(3, 10, 0.5), Vec3(7, 10, 0.5), Vec3(10, 10, 0)};
  Points left = {Vec3(0, 0, 0), Vec3(0, 5, 2), Vec3(0, 10, 0)};
  Boundary make() const { return Boundary(bottom, right, top, left); }
};

// Runs f, which must throw dbs::Error with `code`; checks that every `needles` entry
// appears in the message.
template <class F>
void expect_error(F f, ErrorCode code, std::initializer_list<const char*> needles) {
  try {
    f();
  } catch (const dbs::Error& e) {
    if (e.code() != code) print_error("unexpected code %d: %s\n", static_cast<int>(e.code()), e.what());
    assert_int_equal(e.code(), code);
    for (const char* n : needles) {
      if (!std::strstr(e.what(), n)) print_error("message \"%s\" lacks \"%s\"\n", e.what(), n);
      assert_non_null(std::strstr(e.what(), n));
    }
    return;
  }
  fail_msg("no error thrown");
}

void test_valid_boundary(void**) {
  const Sides s;
  const Boundary b = s.make();
  assert_true(b.corner(0, 0) == Vec3(0, 0, 0));
  assert_true(b.corner(1, 0) == Vec3(10, 0, 0));
  assert_true(b.corner(0, 1) == Vec3(0, 10, 0));
  assert_true(b.corner(1, 1) == Vec3(10, 10, 0));
  assert_true(b.bottom().points() == s.bottom);
  assert_true(b.left().points() == s.left);
  // Bounding box (0,0,0)-(10,10,2): diagonal sqrt(204).
  assert_true(std::fabs(b.size() - std::sqrt(204.0)) < 1e-13);
  assert_true(b.bounds().max == Vec3(10, 10, 2));
  assert_true(&b.side(Side::Top) == &b.top());
  assert_string_equal(dbs::side_name(Side::Bottom), "bottom");
  assert_string_equal(dbs::side_name(Side::Right), "right");
  assert_string_equal(dbs::side_name(Side::Top), "top");
  assert_string_equal(dbs::side_name(Side::Left), "left");
}

void test_too_few_points(void**) {
  Sides s;
  s.right = {Vec3(10, 0, 0)};
  expect_error([&] { s.make(); }, ErrorCode::InvalidArgument, {"right", "1 point"});
  s = Sides();
  s.top.clear();
  expect_error([&] { s.make(); }, ErrorCode::InvalidArgument, {"top", "0 point"});
}

void test_non_finite(void**) {
  Sides s;
  s.top[2].z() = std::nan("");
  expect_error([&] { s.make(); }, ErrorCode::NonFinite, {"top", "point 2"});
  s = Sides();
  s.left[0].x() = std::numeric_limits<double>::infinity();
  expect_error([&] { s.make(); }, ErrorCode::NonFinite, {"left", "point 0"});
}

void test_corner_miss_rejected(void**) {
  Sides s;
  s.right[0] = Vec3(10, 0.3, 0);  // 0.3 away from bottom's end
  expect_error([&] { s.make(); }, ErrorCode::Degenerate,
               {"corner (u=1,v=0)", "bottom ends at (10, 0, 0)", "right starts at (10, 0.3, 0)", "0.3 apart", "(tolerance 1e-6 of the boundary size 14.28"});
  s = Sides();
  s.top[0] = Vec3(0, 10, 0.01);
  expect_error([&] { s.make(); }, ErrorCode::Degenerate, {"corner (u=0,v=1)", "top starts at", "left ends at", "0.01 apart"});
  s = Sides();
  s.left[0] = Vec3(-1e-4, 0, 0);
  expect_error([&] { s.make(); }, ErrorCode::Degenerate, {"corner (u=0,v=0)", "bottom starts at", "left starts at"});
  s = Sides();
  s.top.back() = Vec3(10, 10, 1);
  expect_error([&] { s.make(); }, ErrorCode::Degenerate, {"corner (u=1,v=1)", "top ends at", "right ends at"});
}

void test_small_corner_miss_repaired(void**) {
  Sides s;
  // Size ~14.28, tolerance ~1.43e-5: misses of 1e-6 and 1e-5 are repaired at the mean.
  s.right[0] = Vec3(10, 1e-6, 0);
  s.top.back() = Vec3(10, 10, 1e-5);
  const Boundary b = s.make();
  assert_true(b.bottom().back() == b.right().front());
  assert_true(b.bottom().back() == Vec3(10, 0.5e-6, 0));
  assert_true(b.top().back() == b.right().back());
  assert_true(b.top().back() == Vec3(10, 10, 0.5e-5));
  assert_true(b.corner(1, 1) == Vec3(10, 10, 0.5e-5));
  // Untouched corners stay exactly as given.
  assert_true(b.corner(0, 0) == Vec3(0, 0, 0));
  // Just above the tolerance (1.43e-5) it is an error.
  s.top.back() = Vec3(10, 10, 1.5e-5);
  expect_error([&] { s.make(); }, ErrorCode::Degenerate, {"corner (u=1,v=1)"});
}

void test_zero_length_side(void**) {
  // Left collapsed to a point: bottom and top start at the same point.
  Sides s;
  s.top = {Vec3(0, 0, 0), Vec3(5, 10, 0), Vec3(10, 10, 0)};
  s.left = {Vec3(0, 0, 0), Vec3(0, 0, 0)};
  expect_error([&] { s.make(); }, ErrorCode::Degenerate, {"side 'left'", "zero length"});
  // Shorter than the corner tolerance counts as collapsed too.
  s.left = {Vec3(0, 0, 0), Vec3(0, 0, 1e-9)};
  s.top[0] = Vec3(0, 0, 1e-9);
  expect_error([&] { s.make(); }, ErrorCode::Degenerate, {"side 'left'", "below the corner tolerance"});
}

void test_zero_area(void**) {
  // All four sides on the x axis: bottom and top run 0 -> 10, left and right go out and back.
  const Points line = {Vec3(0, 0, 0), Vec3(10, 0, 0)};
  expect_error([&] { Boundary(line, {Vec3(10, 0, 0), Vec3(12, 0, 0), Vec3(10, 0, 0)}, line, {Vec3(0, 0, 0), Vec3(-3, 0, 0), Vec3(0, 0, 0)}); },
               ErrorCode::Degenerate, {"area"});
  // A strip 1e-7 wide over a length of 10 (its ends bulge out, so no side is short):
  // mean width below 1e-6 of the size.
  expect_error([&] {
    Boundary({Vec3(0, 0, 0), Vec3(10, 0, 0)}, {Vec3(10, 0, 0), Vec3(11, 0.5e-7, 0), Vec3(10, 1e-7, 0)},
             {Vec3(0, 1e-7, 0), Vec3(10, 1e-7, 0)}, {Vec3(0, 0, 0), Vec3(-1, 0.5e-7, 0), Vec3(0, 1e-7, 0)});
  }, ErrorCode::Degenerate, {"area", "boundary size squared"});
  // A strip 1e-4 wide is thin but valid.
  const Boundary thin({Vec3(0, 0, 0), Vec3(10, 0, 0)}, {Vec3(10, 0, 0), Vec3(10, 1e-4, 0)}, {Vec3(0, 1e-4, 0), Vec3(10, 1e-4, 0)},
                      {Vec3(0, 0, 0), Vec3(0, 1e-4, 0)});
  assert_true(thin.size() > 10);
  // A closed tube (left and right the same seam) spans area although its loop's vector
  // area is zero.
  Points bottom, top;
  for (int k = 0; k <= 12; ++k) {
    const double a = 2 * 3.14159265358979323846 * k / 12;
    bottom.push_back(k == 12 ? Vec3(1, 0, 0) : Vec3(std::cos(a), std::sin(a), 0));
    top.push_back(k == 12 ? Vec3(1, 0, 3) : Vec3(std::cos(a), std::sin(a), 3));
  }
  const Points seam = {Vec3(1, 0, 0), Vec3(1, 0, 3)};
  const Boundary tube(bottom, seam, top, seam);
  assert_true(tube.corner(0, 0) == tube.corner(1, 0));
}

void test_zero_size(void**) {
  const Points dot = {Vec3(1, 1, 1), Vec3(1, 1, 1)};
  expect_error([&] { Boundary(dot, dot, dot, dot); }, ErrorCode::Degenerate, {"zero size"});
}

void test_polyline_constructor(void**) {
  const Sides s;
  const Boundary b = s.make();
  // Halves of the sides, as in a subdivision: corners coincide exactly.
  const auto bottom = b.bottom().split(0.5), top = b.top().split(0.5);
  const Polyline middle({bottom.first.back(), Vec3(5, 5, 3), top.first.back()});
  const Boundary child(bottom.first, middle, top.first, b.left());
  assert_true(child.corner(1, 0) == b.bottom().at(0.5));
  assert_true(child.corner(1, 1) == b.top().at(0.5));
  // A corner missing by one ulp is not repaired here.
  const Polyline off = middle.with_ends(Vec3(std::nextafter(middle.front().x(), 10.0), middle.front().y(), middle.front().z()), middle.back());
  expect_error([&] { Boundary(bottom.first, off, top.first, b.left()); }, ErrorCode::Degenerate,
               {"corner (u=1,v=0)", "bottom ends at", "right starts at", "exactly"});
  expect_error([&] { Boundary(bottom.first, Polyline(), top.first, b.left()); }, ErrorCode::InvalidArgument, {"right"});
  // Degenerate children are rejected as well: all sides on one line.
  const Polyline ab({Vec3(0, 0, 0), Vec3(1, 0, 0)}), ba({Vec3(0, 0, 0), Vec3(-1, 0, 0), Vec3(0, 0, 0)}), bb({Vec3(1, 0, 0), Vec3(2, 0, 0), Vec3(1, 0, 0)});
  expect_error([&] { Boundary(ab, bb, ab, ba); }, ErrorCode::Degenerate, {"area"});
}

}  // namespace

int main() {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(test_valid_boundary),
      cmocka_unit_test(test_too_few_points),
      cmocka_unit_test(test_non_finite),
      cmocka_unit_test(test_corner_miss_rejected),
      cmocka_unit_test(test_small_corner_miss_repaired),
      cmocka_unit_test(test_zero_length_side),
      cmocka_unit_test(test_zero_area),
      cmocka_unit_test(test_zero_size),
      cmocka_unit_test(test_polyline_constructor),
  };
  return cmocka_run_group_tests(tests, nullptr, nullptr);
}
