// Boundary files (FORMATS.md): sections in any order, comments, blank lines; every
// malformed file rejected with a message naming the file and the line.
#include <cmath>
#include <string>

#include "boundary_io.hpp"
#include "error.hpp"
#include "core_test_support.hpp"

using dbs::ErrorCode;
using dbs::Vec3;
using core_test::expect_error;
using core_test::write_tmp;

namespace {

// The example of FORMATS.md, verbatim.
const char* const kFormatsExample =
    "# boundary of a 100 x 50 mm panel\n"
    "bottom\n"
    "0 0 0\n"
    "100 0 0\n"
    "right\n"
    "100 0 0\n"
    "100 50 0\n"
    "top\n"
    "0 50 0\n"
    "100 50 0\n"
    "left\n"
    "0 0 0\n"
    "0 50 0\n";

void assert_vec_equal(const Vec3& a, const Vec3& b) {
  if (!(a == b)) fail_msg("(%.17g %.17g %.17g) != (%.17g %.17g %.17g)", a.x(), a.y(), a.z(), b.x(), b.y(), b.z());
}

void formats_example_loads(void**) {
  const dbs::Boundary b = dbs::load_boundary(write_tmp("boundary_io_formats.txt", kFormatsExample));
  for (dbs::Side s : {dbs::Side::Bottom, dbs::Side::Right, dbs::Side::Top, dbs::Side::Left}) assert_int_equal(b.side(s).size(), 2);
  assert_vec_equal(b.corner(0, 0), Vec3(0, 0, 0));
  assert_vec_equal(b.corner(1, 0), Vec3(100, 0, 0));
  assert_vec_equal(b.corner(0, 1), Vec3(0, 50, 0));
  assert_vec_equal(b.corner(1, 1), Vec3(100, 50, 0));
}

void sections_in_any_order_with_comments_commas_and_crlf(void**) {
  const std::string text =
      "\r\n"
      "left   # u = 0\r\n"
      "0, 0, 0\r\n"
      "\t-1.5\t25\t2   # bulges outwards\r\n"
      "0, 50, 0\r\n"
      "TOP\r\n"
      "0 50 0\r\n"
      "100 50 0\r\n"
      "\r\n"
      "bottom\r\n"
      "0 0 0\r\n"
      "50 -2 1e-1\r\n"
      "100 0 0\r\n"
      "right\r\n"
      "100 0 0\r\n"
      "100 50 0";  // no final newline
  const dbs::Boundary b = dbs::load_boundary(write_tmp("boundary_io_any_order.txt", text));
  assert_int_equal(b.left().size(), 3);
  assert_vec_equal(b.left().points()[1], Vec3(-1.5, 25, 2));
  assert_int_equal(b.bottom().size(), 3);
  assert_vec_equal(b.bottom().points()[1], Vec3(50, -2, 0.1));
  assert_int_equal(b.top().size(), 2);
  assert_int_equal(b.right().size(), 2);
}

void example_data_boundaries_load(void**) {
  const dbs::Boundary shoe = dbs::load_boundary(std::string(DBS_TEST_DATA_DIR) + "/shoe_last_boundary.txt");
  assert_int_equal(shoe.bottom().size(), 50);
  assert_int_equal(shoe.left().size(), 50);
  // the corners were written shared exactly
  assert_vec_equal(shoe.bottom().front(), shoe.left().front());
  assert_vec_equal(shoe.top().back(), shoe.right().back());
  assert_true(std::fabs(shoe.bottom().back().x() - 246.0) < 1e-9);
  const dbs::Boundary panel = dbs::load_boundary(std::string(DBS_TEST_DATA_DIR) + "/panel_boundary.txt");
  assert_int_equal(panel.top().size(), 21);
  assert_vec_equal(panel.corner(1, 1), Vec3(100, 50, panel.corner(1, 1).z()));
}

// The FORMATS.md example with line `line` (1-based) replaced by `replacement` (which may
// hold several lines, or none).
std::string example_with(int line, const std::string& replacement) {
  std::string text = kFormatsExample, out;
  int n = 0;
  std::size_t pos = 0;
  while (pos < text.size()) {
    const std::size_t eol = text.find('\n', pos);
    ++n;
    out += n == line ? replacement : text.substr(pos, eol - pos + 1);
    pos = eol + 1;
  }
  return out;
}

void malformed_files_name_file_and_line(void**) {
  const std::string unknown = write_tmp("boundary_io_unknown.txt", example_with(8, "front\n"));
  expect_error([&] { dbs::load_boundary(unknown); }, ErrorCode::Parse, {unknown + ":8:", "unknown section 'front'"});

  const std::string words = write_tmp("boundary_io_words.txt", example_with(8, "top side\n"));
  expect_error([&] { dbs::load_boundary(words); }, ErrorCode::Parse, {words + ":8:", "'top side'"});

  const std::string early = write_tmp("boundary_io_early.txt", "# no section yet\n\n1 2 3\n" + std::string(kFormatsExample));
  expect_error([&] { dbs::load_boundary(early); }, ErrorCode::Parse, {early + ":3:", "before any section"});

  const std::string twice = write_tmp("boundary_io_twice.txt", std::string(kFormatsExample) + "bottom\n5 5 5\n");
  expect_error([&] { dbs::load_boundary(twice); }, ErrorCode::Parse, {twice + ":14:", "'bottom' given twice", "line 2"});

  const std::string missing = write_tmp("boundary_io_missing.txt", std::string(kFormatsExample).substr(0, std::string(kFormatsExample).find("left\n")));
  expect_error([&] { dbs::load_boundary(missing); }, ErrorCode::Parse, {missing, "'left' is missing"});

  const std::string word = write_tmp("boundary_io_word.txt", example_with(6, "100 zero 0\n"));
  expect_error([&] { dbs::load_boundary(word); }, ErrorCode::Parse, {word + ":6:", "expected 3 numbers, found 'zero'"});

  const std::string two = write_tmp("boundary_io_two.txt", example_with(10, "100 50\n"));
  expect_error([&] { dbs::load_boundary(two); }, ErrorCode::Parse, {two + ":10:", "found only 2"});

  const std::string four = write_tmp("boundary_io_four.txt", example_with(3, "0 0 0 7\n"));
  expect_error([&] { dbs::load_boundary(four); }, ErrorCode::Parse, {four + ":3:", "found more: '7'"});

  const std::string truncated = write_tmp("boundary_io_truncated.txt", std::string(kFormatsExample) + "0 50");
  expect_error([&] { dbs::load_boundary(truncated); }, ErrorCode::Parse, {truncated + ":14:", "found only 2"});

  const std::string nan = write_tmp("boundary_io_nan.txt", example_with(9, "0 nan 0\n"));
  expect_error([&] { dbs::load_boundary(nan); }, ErrorCode::NonFinite, {nan + ":9:", "non-finite"});
  const std::string inf = write_tmp("boundary_io_inf.txt", example_with(9, "-inf 50 0\n"));
  expect_error([&] { dbs::load_boundary(inf); }, ErrorCode::NonFinite, {inf + ":9:"});

  const std::string one_point = write_tmp("boundary_io_one_point.txt", example_with(7, ""));
  expect_error([&] { dbs::load_boundary(one_point); }, ErrorCode::Parse, {one_point + ":5:", "'right' has 1 point"});

  const std::string no_points = write_tmp("boundary_io_no_points.txt", std::string(kFormatsExample).substr(0, std::string(kFormatsExample).find("left\n") + 5));
  expect_error([&] { dbs::load_boundary(no_points); }, ErrorCode::Parse, {no_points + ":11:", "'left' has no points"});

  const std::string empty = write_tmp("boundary_io_empty.txt", "# nothing\n\n");
  expect_error([&] { dbs::load_boundary(empty); }, ErrorCode::Empty, {empty});

  const std::string absent = core_test::tmp_path("boundary_io_absent.txt");
  expect_error([&] { dbs::load_boundary(absent); }, ErrorCode::Io, {absent, "No such file"});
}

void geometric_problems_name_the_file(void**) {
  // right starts 5 units away from where bottom ends: a corner miss, not silently fixed
  const std::string miss = write_tmp("boundary_io_corner_miss.txt", example_with(6, "105 0 0\n"));
  expect_error([&] { dbs::load_boundary(miss); }, ErrorCode::Degenerate, {miss});
}

}  // namespace

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(formats_example_loads),
      cmocka_unit_test(sections_in_any_order_with_comments_commas_and_crlf),
      cmocka_unit_test(example_data_boundaries_load),
      cmocka_unit_test(malformed_files_name_file_and_line),
      cmocka_unit_test(geometric_problems_name_the_file),
  };
  return cmocka_run_group_tests(tests, nullptr, nullptr);
}
