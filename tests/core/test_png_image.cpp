// PNG pictures: what is written decodes with libpng to the same size and pixels; files that
// are missing or not PNG are errors.
#include <cstdio>
#include <string>

#include "error.hpp"
#include "png_file.hpp"
#include "core_test_support.hpp"  // last of the dbs headers

namespace {

using core_test::error_code_of;

std::string temp_file(const std::string& name) { return core_test::tmp_path("png_image_" + name); }

void test_round_trip(void**) {
  dbs::RgbImage image(37, 21, {10, 20, 30});
  for (int x = 0; x < 37; ++x) image.set(x, 5, {255, 0, 0});
  image.set(36, 20, {1, 2, 3});
  image.plot(-1, 3, {0, 0, 0});  // outside: ignored
  image.plot(37, 3, {0, 0, 0});
  const std::string path = temp_file("round_trip.png");
  dbs::write_png(path, image);
  const dbs::RgbImage back = dbs::read_png(path);
  assert_int_equal(back.width(), 37);
  assert_int_equal(back.height(), 21);
  assert_true(back.bytes() == image.bytes());
  assert_true((back.at(36, 20) == dbs::Rgb{1, 2, 3}));
  assert_true((back.at(0, 5) == dbs::Rgb{255, 0, 0}));
  assert_true((back.at(0, 3) == dbs::Rgb{10, 20, 30}));
  std::remove(path.c_str());
}

void test_errors(void**) {
  assert_int_equal(error_code_of([] { dbs::read_png(temp_file("missing.png")); }), dbs::ErrorCode::Io);
  const std::string text = temp_file("not_a_png.png");
  std::FILE* f = std::fopen(text.c_str(), "w");
  assert_non_null(f);
  std::fputs("not a png\n", f);
  std::fclose(f);
  assert_int_equal(error_code_of([&] { dbs::read_png(text); }), dbs::ErrorCode::Parse);
  std::remove(text.c_str());
  const dbs::RgbImage image(4, 4);
  assert_int_equal(error_code_of([&] { dbs::write_png(std::string(DBS_TEST_TMP_DIR) + "/no/such/dir/x.png", image); }), dbs::ErrorCode::Io);
  assert_int_equal(error_code_of([] { dbs::RgbImage(0, 3); }), dbs::ErrorCode::InvalidArgument);
  assert_int_equal(error_code_of([] { dbs::RgbImage::from_bytes(2, 2, std::vector<std::uint8_t>(11)); }), dbs::ErrorCode::InvalidArgument);
}

}  // namespace

int main() {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(test_round_trip),
      cmocka_unit_test(test_errors),
  };
  return cmocka_run_group_tests(tests, nullptr, nullptr);
}
