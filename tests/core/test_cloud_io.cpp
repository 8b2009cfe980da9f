// Point-cloud files (FORMATS.md): .xyz/.txt text, ASCII/binary PLY, OBJ and DRC round-trip
// their coordinates; malformed, truncated, non-finite and empty files of every format are
// rejected with the right code and a message naming the file and the line or vertex.
#include <cmath>
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

#include <sys/stat.h>

#include "cloud_io.hpp"
#include "draco_io.hpp"
#include "error.hpp"
#include "text_io.hpp"
#include "core_test_support.hpp"

using dbs::ErrorCode;
using dbs::Vec3;
using core_test::expect_error;
using core_test::write_tmp;

namespace {

// Coordinates exactly representable as float, so Draco's float32 paths keep them exactly.
std::vector<Vec3> float_exact_points(int n) {
  std::vector<Vec3> pts;
  for (int i = 0; i < n; ++i) pts.emplace_back(0.25 * i - 3.5, -1.125 * i, 1024.0 + 0.0625 * (i % 7));
  return pts;
}

// Coordinates with full double precision.
std::vector<Vec3> awkward_points(int n) {
  std::vector<Vec3> pts;
  for (int i = 0; i < n; ++i) pts.emplace_back(std::sqrt(2.0 + i) * 100.0 / 3.0, -std::cbrt(1.0 + i) / 7.0, 1e-7 * i + 12345.6789);
  return pts;
}

void assert_same_points(const std::vector<Vec3>& got, const std::vector<Vec3>& expected, double relative_tolerance) {
  assert_int_equal(got.size(), expected.size());
  for (std::size_t i = 0; i < got.size(); ++i) {
    for (int k = 0; k < 3; ++k) {
      const double tol = relative_tolerance * std::fabs(expected[i][k]);
      if (!(std::fabs(got[i][k] - expected[i][k]) <= tol))
        fail_msg("point %zu coordinate %d: %.17g, expected %.17g", i, k, got[i][k], expected[i][k]);
    }
  }
}

std::string format_g17(double x) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.17g", x);
  return buf;
}

// ---- PLY builders ------------------------------------------------------------------------

std::string ply_header(const std::string& format, std::size_t n, const std::string& type, const std::string& extra = "") {
  return "ply\nformat " + format + " 1.0\ncomment made by test_cloud_io\nelement vertex " + std::to_string(n) + "\nproperty " + type + " x\nproperty " + type +
         " y\nproperty " + type + " z\n" + extra + "end_header\n";
}

template <typename T>
void append_binary(std::string& out, T value, bool big_endian) {
  char bytes[sizeof(T)];
  std::memcpy(bytes, &value, sizeof(T));
  if (big_endian)
    for (std::size_t i = 0; i < sizeof(T) / 2; ++i) std::swap(bytes[i], bytes[sizeof(T) - 1 - i]);
  out.append(bytes, sizeof(T));
}

// Binary PLY with double x y z, an extra uchar property per vertex and a face element after
// the vertices.
std::string binary_ply(const std::vector<Vec3>& pts, bool big_endian) {
  std::string out = ply_header(big_endian ? "binary_big_endian" : "binary_little_endian", pts.size(), "double",
                               "property uchar quality\nelement face 1\nproperty list uchar int vertex_indices\n");
  for (const Vec3& p : pts) {
    for (int k = 0; k < 3; ++k) append_binary<double>(out, p[k], big_endian);
    append_binary<std::uint8_t>(out, 200, big_endian);
  }
  append_binary<std::uint8_t>(out, 3, big_endian);
  for (std::int32_t i : {0, 1, 2}) append_binary<std::int32_t>(out, i, big_endian);
  return out;
}

std::string ascii_rows(const std::vector<Vec3>& pts) {
  std::string rows;
  for (const Vec3& p : pts) rows += format_g17(p.x()) + " " + format_g17(p.y()) + " " + format_g17(p.z()) + "\n";
  return rows;
}

// ---- .xyz text ---------------------------------------------------------------------------

void xyz_round_trips_every_accepted_spelling(void**) {
  const std::string text =
      "# x y z exported by a scanner\n"
      "\n"
      "1 2 3\n"
      "  4.5\t-5.25\t6e2   \r\n"
      "7,8,9\n"
      "1.0e-3 , +2 ,-3.5E+1  # trailing comment\n"
      "10 11 12 255 128 0\n"
      "\t\n"
      "13 14 15 a-label\n"
      "0.1 0.2 0.30000000000000004";  // no final newline
  // a UTF-8 byte-order mark (some Windows editors) is skipped
  const auto pts = dbs::read_xyz_text(write_tmp("cloud_io_spellings.xyz", "\xEF\xBB\xBF" + text));
  const std::vector<Vec3> expected = {{1, 2, 3}, {4.5, -5.25, 600}, {7, 8, 9}, {1e-3, 2, -35}, {10, 11, 12}, {13, 14, 15}, {0.1, 0.2, 0.30000000000000004}};
  assert_same_points(pts, expected, 0.0);
}

void xyz_keeps_full_double_precision(void**) {
  const auto expected = awkward_points(5000);
  const auto cloud = dbs::load_cloud(write_tmp("cloud_io_precise.XYZ", ascii_rows(expected)));
  assert_same_points(cloud.points(), expected, 0.0);
  // .txt is the same format, the extension is case-insensitive
  assert_same_points(dbs::load_cloud(write_tmp("cloud_io_precise.Txt", ascii_rows(expected))).points(), expected, 0.0);
}

void numbers_beyond_the_double_range(void**) {
  // Overflow is +-inf, underflow +-0, decided without strtod (which follows the locale).
  const struct {
    const char* text;
    double value;
  } cases[] = {{"1e999", HUGE_VAL}, {"-1.5e400", -HUGE_VAL}, {"+10000e305", HUGE_VAL}, {"1e-999", 0.0}, {"-123456e-400", -0.0},
               {"0.000001e-330", 0.0}, {"1e99999999999999999999", HUGE_VAL}, {"1e-99999999999999999999", 0.0}, {"2e308", HUGE_VAL}};
  for (const auto& c : cases) {
    double x = 7.0;
    assert_true(dbs::parse_number(c.text, x));
    assert_true(x == c.value && std::signbit(x) == std::signbit(c.value));
  }
  double x = 0.0;
  assert_true(dbs::parse_number("1.7976931348623157e308", x) && x == 1.7976931348623157e308);
  assert_true(dbs::parse_number("4e-320", x) && x > 0.0 && x < 1e-310);  // a subnormal, in range
}

void xyz_rejects_malformed_truncated_nonfinite_and_empty(void**) {
  const std::string bad = write_tmp("cloud_io_bad.xyz", "# header\n1 2 3\n\n4 abc 6\n7 8 9\n");
  expect_error([&] { dbs::read_xyz_text(bad); }, ErrorCode::Parse, {bad + ":4:", "expected 3 numbers, found 'abc'"});

  const std::string glued = write_tmp("cloud_io_glued.xyz", "1 2 3\n4 5 6.5x\n");
  expect_error([&] { dbs::read_xyz_text(glued); }, ErrorCode::Parse, {glued + ":2:", "'6.5x'"});
  // A NUL byte in the file is shown, not allowed to end the message (a C string) there.
  const std::string nul = write_tmp("cloud_io_nul.xyz", std::string("1 2 3\n4 5 a\0b\n", 15));
  expect_error([&] { dbs::read_xyz_text(nul); }, ErrorCode::Parse, {nul + ":2:", "'a\\x00b'"});

  const std::string empty_field = write_tmp("cloud_io_empty_field.xyz", "1,,2,3\n");
  expect_error([&] { dbs::read_xyz_text(empty_field); }, ErrorCode::Parse, {empty_field + ":1:", "found ','"});

  const std::string truncated = write_tmp("cloud_io_truncated.xyz", "1 2 3\n4 5 6\n7 8");
  expect_error([&] { dbs::read_xyz_text(truncated); }, ErrorCode::Parse, {truncated + ":3:", "found only 2"});

  const std::string nan = write_tmp("cloud_io_nan.xyz", "1 2 3\n4 nan 6\n");
  expect_error([&] { dbs::read_xyz_text(nan); }, ErrorCode::NonFinite, {nan + ":2:", "non-finite"});

  const std::string overflow = write_tmp("cloud_io_overflow.xyz", "1 2 3\n\n\n1 2 1e999\n");
  expect_error([&] { dbs::read_xyz_text(overflow); }, ErrorCode::NonFinite, {overflow + ":4:"});

  const std::string comments = write_tmp("cloud_io_comments.xyz", "# nothing\n\n   # here\n");
  expect_error([&] { dbs::read_xyz_text(comments); }, ErrorCode::Empty, {comments, "no points"});
  const std::string empty = write_tmp("cloud_io_empty.xyz", "");
  expect_error([&] { dbs::load_cloud(empty); }, ErrorCode::Empty, {empty});

  const std::string missing = core_test::tmp_path("cloud_io_does_not_exist.xyz");
  expect_error([&] { dbs::load_cloud(missing); }, ErrorCode::Io, {missing, "No such file"});
  const std::string directory = core_test::tmp_path("cloud_io_directory.xyz");
  mkdir(directory.c_str(), 0755);
  expect_error([&] { dbs::load_cloud(directory); }, ErrorCode::Io, {directory, "Is a directory"});
}

void unknown_extension_is_unsupported(void**) {
  const std::string path = write_tmp("cloud_io_points.las", "1 2 3\n");
  expect_error([&] { dbs::load_cloud(path); }, ErrorCode::Unsupported, {path, "'.las'"});
  const std::string bare = write_tmp("cloud_io_points", "1 2 3\n");
  expect_error([&] { dbs::load_cloud(bare); }, ErrorCode::Unsupported, {bare, "no extension"});
}

void example_data_loads(void**) {
  const auto shoe = dbs::load_cloud(std::string(DBS_TEST_DATA_DIR) + "/shoe_last.xyz");
  assert_int_equal(shoe.size(), 20000);
  const Vec3 extent = shoe.bounds().max - shoe.bounds().min;
  assert_true(std::fabs(extent.x() - 246) < 2 && std::fabs(extent.y() - 38) < 2 && std::fabs(extent.z() - 102) < 2);
  assert_int_equal(dbs::load_cloud(std::string(DBS_TEST_DATA_DIR) + "/panel.xyz").size(), 2000);
}

// ---- PLY -----------------------------------------------------------------------------------

void ascii_ply_round_trips(void**) {
  // float properties, values exact in float: exact
  const auto exact = float_exact_points(300);
  const std::string f = write_tmp("cloud_io_ascii_float.PLY", ply_header("ascii", exact.size(), "float") + ascii_rows(exact));
  assert_same_points(dbs::load_cloud(f).points(), exact, 0.0);
  // double properties with further properties and a face list: exact doubles (libdbs
  // reads PLY itself since 0.4; through Draco they were 32-bit floats)
  const auto precise = awkward_points(300);
  std::string rows;
  for (const Vec3& p : precise) rows += format_g17(p.x()) + " " + format_g17(p.y()) + "\t" + format_g17(p.z()) + " 7\r\n";
  const std::string d = write_tmp("cloud_io_ascii_double.ply",
                                  ply_header("ascii", precise.size(), "double", "property int label\nelement face 2\nproperty list uchar int vertex_indices\n") +
                                      rows + "3 0 1 2\n3 2 1 oops\n");  // faces are ignored, even malformed ones
  assert_same_points(dbs::load_cloud(d).points(), precise, 0.0);
}

void binary_ply_round_trips_both_byte_orders(void**) {
  const auto pts = awkward_points(1000);
  assert_same_points(dbs::load_cloud(write_tmp("cloud_io_le.ply", binary_ply(pts, false))).points(), pts, 0.0);
  assert_same_points(dbs::load_cloud(write_tmp("cloud_io_be.ply", binary_ply(pts, true))).points(), pts, 0.0);
  // float32 and int coordinates are read too
  const auto exact = float_exact_points(50);
  std::string floats = ply_header("binary_little_endian", exact.size(), "float");
  for (const Vec3& p : exact)
    for (int k = 0; k < 3; ++k) append_binary<float>(floats, static_cast<float>(p[k]), false);
  assert_same_points(dbs::load_cloud(write_tmp("cloud_io_f32.ply", floats)).points(), exact, 0.0);
  std::string ints = ply_header("binary_little_endian", 2, "short");
  for (std::int16_t v : {-3, 4, 5, 300, -32768, 32767}) append_binary<std::int16_t>(ints, v, false);
  assert_same_points(dbs::load_cloud(write_tmp("cloud_io_i16.ply", ints)).points(), {{-3, 4, 5}, {300, -32768, 32767}}, 0.0);
}

void ply_rejects_malformed_truncated_nonfinite_and_empty(void**) {
  const std::string header = ply_header("ascii", 5, "float");  // 8 lines
  // ASCII: vertex 2 (line 11) holds a word
  const std::string bad = write_tmp("cloud_io_bad.ply", header + "1 2 3\n4 5 6\n7 abc 9\n10 11 12\n13 14 15\n");
  expect_error([&] { dbs::load_cloud(bad); }, ErrorCode::Parse, {bad + ":11:", "vertex 2", "'abc'"});
  // ASCII: vertex 3 (line 12) has only two values
  const std::string short_row = write_tmp("cloud_io_short_row.ply", header + "1 2 3\n4 5 6\n7 8 9\n10 11\n13 14 15\n");
  expect_error([&] { dbs::load_cloud(short_row); }, ErrorCode::Parse, {short_row + ":12:", "vertex 3", "2 values, expected 3"});
  // ASCII: the file ends after 4 of 5 vertices
  const std::string truncated = write_tmp("cloud_io_truncated.ply", header + "1 2 3\n4 5 6\n7 8 9\n10 11 12\n");
  expect_error([&] { dbs::load_cloud(truncated); }, ErrorCode::Parse, {truncated + ":12:", "before vertex 4 of 5"});
  // ASCII: a value Draco would read as 0 ("0x10") or as 3 ("3abc")
  const std::string hex = write_tmp("cloud_io_hex.ply", header + "1 2 3\n4 5 6\n7 8 9\n10 11 12\n13 14 0x10\n");
  expect_error([&] { dbs::load_cloud(hex); }, ErrorCode::Parse, {hex + ":13:", "vertex 4", "'0x10'"});
  const std::string glued = write_tmp("cloud_io_glued.ply", header + "1 2 3\n4 5 6abc\n7 8 9\n10 11 12\n13 14 15\n");
  expect_error([&] { dbs::load_cloud(glued); }, ErrorCode::Parse, {glued + ":10:", "vertex 1", "'6abc'"});
  // ASCII: non-finite vertex 1 on line 10
  const std::string nan = write_tmp("cloud_io_nan.ply", header + "1 2 3\n4 nan 6\n7 8 9\n10 11 12\n13 14 15\n");
  expect_error([&] { dbs::load_cloud(nan); }, ErrorCode::NonFinite, {nan + ":10:", "vertex 1"});

  // binary: cut inside vertex 600 of 1000
  const auto many = awkward_points(1000);
  const std::string full = binary_ply(many, false);
  const std::size_t data_begin = full.find("end_header\n") + 11;
  const std::string cut = write_tmp("cloud_io_cut.ply", full.substr(0, data_begin + 600 * 25 + 10));
  expect_error([&] { dbs::load_cloud(cut); }, ErrorCode::Parse, {cut, "vertex 600 of 1000", "truncated"});
  // binary: non-finite vertex 17
  auto with_inf = many;
  with_inf[17].z() = INFINITY;
  const std::string inf = write_tmp("cloud_io_inf.ply", binary_ply(with_inf, true));
  expect_error([&] { dbs::load_cloud(inf); }, ErrorCode::NonFinite, {inf, "vertex 17"});

  // header problems
  const std::string not_ply = write_tmp("cloud_io_not.ply", "plyx\nformat ascii 1.0\n");
  expect_error([&] { dbs::load_cloud(not_ply); }, ErrorCode::Parse, {not_ply + ":1:", "not a PLY file"});
  const std::string no_end = write_tmp("cloud_io_no_end.ply", "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\n");
  expect_error([&] { dbs::load_cloud(no_end); }, ErrorCode::Parse, {no_end, "end_header"});
  const std::string bad_type = write_tmp("cloud_io_bad_type.ply", "ply\nformat ascii 1.0\nelement vertex 1\nproperty real x\nend_header\n1\n");
  expect_error([&] { dbs::load_cloud(bad_type); }, ErrorCode::Parse, {bad_type + ":4:", "'real'"});
  const std::string no_z = write_tmp("cloud_io_no_z.ply", "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\nend_header\n1 2\n");
  expect_error([&] { dbs::load_cloud(no_z); }, ErrorCode::Parse, {no_z + ":3:", "'z'"});
  const std::string no_vertex = write_tmp("cloud_io_no_vertex.ply", "ply\nformat ascii 1.0\nelement point 1\nproperty float x\nend_header\n1\n");
  expect_error([&] { dbs::load_cloud(no_vertex); }, ErrorCode::Parse, {no_vertex, "no 'vertex' element"});
  const std::string version = write_tmp("cloud_io_version.ply", "ply\nformat ascii 2.0\nend_header\n");
  expect_error([&] { dbs::load_cloud(version); }, ErrorCode::Unsupported, {version + ":2:", "'2.0'"});

  const std::string zero = write_tmp("cloud_io_zero.ply", ply_header("binary_little_endian", 0, "float"));
  expect_error([&] { dbs::load_cloud(zero); }, ErrorCode::Empty, {zero, "0 vertices"});
  const std::string empty = write_tmp("cloud_io_empty.ply", "");
  expect_error([&] { dbs::load_cloud(empty); }, ErrorCode::Empty, {empty});
}

void ply_values_are_exact_doubles(void**) {
  // Values a float cannot hold, map coordinates and magnitudes beyond float, in ASCII (a list
  // property before x, and x, y, z out of order) and in big-endian binary of mixed types.
  const std::string ascii = write_tmp("cloud_io_exact.ply",
                                      "ply\nformat ascii 1.0\nelement vertex 2\nproperty list uchar int ids\nproperty double z\nproperty double x\nproperty float y\n"
                                      "end_header\n2 7 8 1e300 500000.123 1.000000001\n0 -2.5e-300 -4321987.654321 0.1\n");
  assert_same_points(dbs::load_cloud(ascii).points(), {{500000.123, 1.000000001, 1e300}, {-4321987.654321, 0.1, -2.5e-300}}, 0.0);
  std::string binary = "ply\nformat binary_big_endian 1.0\nelement vertex 2\nproperty int x\nproperty uint y\nproperty double z\nend_header\n";
  for (const Vec3& p : std::vector<Vec3>{{-2147483648.0, 4294967295.0, 1e300}, {7, 0, -0.1}}) {
    append_binary<std::int32_t>(binary, static_cast<std::int32_t>(p.x()), true);
    append_binary<std::uint32_t>(binary, static_cast<std::uint32_t>(p.y()), true);
    append_binary<double>(binary, p.z(), true);
  }
  assert_same_points(dbs::load_cloud(write_tmp("cloud_io_exact_be.ply", binary)).points(), {{-2147483648.0, 4294967295.0, 1e300}, {7, 0, -0.1}}, 0.0);
}

void ply_header_claims_are_checked_before_reading(void**) {
  // Elements without properties hold nothing: 2^31 - 1 of them before the vertices cost no
  // time, in binary and in ASCII.
  for (const char* format : {"binary_little_endian", "ascii"}) {
    std::string text = std::string("ply\nformat ") + format + " 1.0\nelement junk 2147483647\nelement vertex 1\nproperty float x\nproperty float y\nproperty float z\nend_header\n";
    if (std::string(format) == "ascii") text += "1 2 3\n";
    else
      for (float v : {1.0f, 2.0f, 3.0f}) append_binary<float>(text, v, false);
    assert_same_points(dbs::load_cloud(write_tmp("cloud_io_junk.ply", text)).points(), {{1, 2, 3}}, 0.0);
  }
  // A vertex count the data cannot hold: memory is reserved only for what the data can hold,
  // and the file is refused where its data ends (100 bytes: 4 doubles x y z and a bit).
  const std::string huge_binary = write_tmp("cloud_io_huge_binary.ply", ply_header("binary_little_endian", 2147483647, "double") + std::string(100, '\0'));
  expect_error([&] { dbs::load_cloud(huge_binary); }, ErrorCode::Parse, {huge_binary, "inside vertex 4 of 2147483647", "truncated"});
  const std::string huge_ascii = write_tmp("cloud_io_huge_ascii.ply", ply_header("ascii", 2147483647, "double") + "1 2 3\n");
  expect_error([&] { dbs::load_cloud(huge_ascii); }, ErrorCode::Parse, {huge_ascii, "before vertex 1 of 2147483647"});
  // Two vertex elements: which one is meant? Refused, naming both lines.
  const std::string two = write_tmp("cloud_io_two_vertex.ply", ply_header("ascii", 1, "float", "element vertex 1\nproperty float x\nproperty float y\nproperty float z\n") + "1 2 3\n4 5 6\n");
  expect_error([&] { dbs::load_cloud(two); }, ErrorCode::Parse, {two + ":8:", "second 'vertex' element", "line 4"});
}

// ---- OBJ -----------------------------------------------------------------------------------

void obj_reads_every_v_line_and_ignores_the_rest(void**) {
  const std::string text =
      "# exported mesh\n"
      "mtllib missing.mtl\n"
      "o part\n"
      "v 1 2 3\n"
      "v\t4.5\t-5\t6\n"         // tab after the v
      "vn 0 0 1\n"              // one normal for three vertices
      "v 1 2 3 0.5 0.5 0.5\n"   // duplicate position (kept), vertex colour ignored
      "vt 0 1\n"
      "  v 7 8 9 # comment\r\n"
      "usemtl steel\n"
      "f 1 2 3\n"
      "f 1/1/1 2/1/1 99\n"      // faces are ignored, even broken ones
      "g group\n";
  const auto pts = dbs::load_cloud(write_tmp("cloud_io_mixed.Obj", text)).points();
  assert_same_points(pts, {{1, 2, 3}, {4.5, -5, 6}, {1, 2, 3}, {7, 8, 9}}, 0.0);

  const auto many = float_exact_points(2000);
  std::string big;
  for (const Vec3& p : many) big += "v " + format_g17(p.x()) + " " + format_g17(p.y()) + " " + format_g17(p.z()) + "\n";
  assert_same_points(dbs::load_cloud(write_tmp("cloud_io_many.obj", big)).points(), many, 0.0);
  // exact doubles, also where a float would round (since 0.4; through Draco they were floats)
  assert_same_points(dbs::load_cloud(write_tmp("cloud_io_exact.obj", "v 500000.123 1.000000001 1e300\nv -4321987.654321 0.1 -2.5e-300\n")).points(),
                     {{500000.123, 1.000000001, 1e300}, {-4321987.654321, 0.1, -2.5e-300}}, 0.0);
}

void obj_rejects_malformed_truncated_nonfinite_and_empty(void**) {
  const std::string bad = write_tmp("cloud_io_bad.obj", "# c\nv 1 2 3\nvn 0 0 1\nv 4 abc 6\nv 7 8 9\n");
  expect_error([&] { dbs::load_cloud(bad); }, ErrorCode::Parse, {bad + ":4:", "vertex 1", "'abc'"});
  const std::string truncated = write_tmp("cloud_io_truncated.obj", "v 1 2 3\nv 4 5 6\nv 7 8");
  expect_error([&] { dbs::load_cloud(truncated); }, ErrorCode::Parse, {truncated + ":3:", "vertex 2", "found only 2"});
  const std::string glued = write_tmp("cloud_io_glued.obj", "v 1 2 3\nv 4 5 6abc\n");
  expect_error([&] { dbs::load_cloud(glued); }, ErrorCode::Parse, {glued + ":2:", "vertex 1", "'6abc'"});
  const std::string commas = write_tmp("cloud_io_commas.obj", "v 1 2 3\nv 4 5 6\nv 7,8,9\n");
  expect_error([&] { dbs::load_cloud(commas); }, ErrorCode::Parse, {commas + ":3:", "vertex 2", "comma"});
  const std::string bare_v = write_tmp("cloud_io_bare_v.obj", "v 1 2 3\nv\nv 7 8 9\n");
  expect_error([&] { dbs::load_cloud(bare_v); }, ErrorCode::Parse, {bare_v + ":2:", "vertex 1"});
  const std::string nan = write_tmp("cloud_io_nan.obj", "v 1 2 3\n\nf 1 1 1\nv 4 5 inf\n");
  expect_error([&] { dbs::load_cloud(nan); }, ErrorCode::NonFinite, {nan + ":4:", "vertex 1"});
  const std::string no_v = write_tmp("cloud_io_no_v.obj", "# only normals\nvn 0 0 1\n");
  expect_error([&] { dbs::load_cloud(no_v); }, ErrorCode::Empty, {no_v, "no 'v' lines"});
}

// ---- DRC -----------------------------------------------------------------------------------

void drc_round_trips_within_quantization(void**) {
  if (!dbs::draco_available()) {
    expect_error([] { dbs::load_cloud(core_test::tmp_path("cloud_io_any.drc")); }, ErrorCode::Unsupported, {"without Draco"});
    return;
  }
  const auto pts = awkward_points(20000);
  std::vector<double> u(pts.size()), v(pts.size());
  for (std::size_t i = 0; i < pts.size(); ++i) {
    u[i] = static_cast<double>(i) / (pts.size() - 1);
    v[i] = 1.0 - u[i] * u[i];
  }
  const std::string path = core_test::tmp_path("cloud_io_points.DRC");
  dbs::write_draco_point_cloud(path, pts, u, v);
  const auto got = dbs::load_cloud(path).points();
  assert_int_equal(got.size(), pts.size());
  // 16-bit quantization over the largest extent E: every coordinate within E / (2 * 65535),
  // plus the float32 rounding of the stored coordinates (about 1e-3 here, at 12345.7)
  const dbs::Box3 box = dbs::bounds_of(pts);
  const double extent = (box.max - box.min).maxCoeff();
  double max_error = 0.0;
  for (std::size_t i = 0; i < pts.size(); ++i) max_error = std::max(max_error, (got[i] - pts[i]).cwiseAbs().maxCoeff());
  assert_true(max_error <= extent / (2 * 65535.0) + 1e-3);
  assert_true(max_error < 1e-4 * box.diagonal());
  // point order is kept: the k-th point is nearer the k-th input point than its neighbour
  // (> 0.1 apart, several times the quantization error)
  for (std::size_t i = 1; i < pts.size(); ++i) assert_true((got[i] - pts[i]).norm() < (got[i] - pts[i - 1]).norm());
  // (u,v) travel with their points
  const auto uv = dbs::read_tex_coords_with_draco(path);
  assert_int_equal(uv.size(), pts.size());
  for (std::size_t i = 0; i < pts.size(); ++i) assert_true(std::fabs(uv[i].x() - u[i]) <= 1.0 / (2 * 65535.0) + 1e-7 && std::fabs(uv[i].y() - v[i]) <= 1.0 / (2 * 65535.0) + 1e-7);
}

void drc_rejects_garbage_truncated_and_empty(void**) {
  if (!dbs::draco_available()) skip();  // reported as skipped, not passed
  const std::string garbage = write_tmp("cloud_io_garbage.drc", "this is not a Draco file at all\n");
  expect_error([&] { dbs::load_cloud(garbage); }, ErrorCode::Parse, {garbage, "not a valid Draco file"});
  const auto pts = awkward_points(500);
  const std::vector<double> uv(pts.size(), 0.5);
  const std::string whole = core_test::tmp_path("cloud_io_whole.drc");
  dbs::write_draco_point_cloud(whole, pts, uv, uv);
  const std::string bytes = core_test::read_all(whole);
  for (const std::size_t keep : {bytes.size() / 2, std::size_t{12}}) {
    const std::string cut = write_tmp("cloud_io_cut.drc", bytes.substr(0, keep));
    expect_error([&] { dbs::load_cloud(cut); }, ErrorCode::Parse, {cut, "not a valid Draco file"});
  }
  const std::string empty = write_tmp("cloud_io_empty.drc", "");
  // A point-cloud header claiming 2^31 points in a file of a few hundred bytes: refused before
  // Draco allocates for them.
  std::string lying = bytes;
  const std::uint32_t claim = 0x80000000u;
  for (int i = 0; i < 4; ++i) lying[11 + static_cast<std::size_t>(i)] = static_cast<char>((claim >> (8 * i)) & 0xff);
  const std::string liar = write_tmp("cloud_io_lying.drc", lying);
  expect_error([&] { dbs::load_cloud(liar); }, ErrorCode::Parse, {liar, "claims 2147483648 points"});
  expect_error([&] { dbs::load_cloud(empty); }, ErrorCode::Empty, {empty});
  const std::string missing = core_test::tmp_path("cloud_io_missing.drc");
  expect_error([&] { dbs::load_cloud(missing); }, ErrorCode::Io, {missing});
  // writing checks its input
  expect_error([&] { dbs::write_draco_point_cloud(whole, pts, uv, {}); }, ErrorCode::InvalidArgument, {whole});
  auto with_nan = pts;
  with_nan[3].x() = NAN;
  expect_error([&] { dbs::write_draco_point_cloud(whole, with_nan, uv, uv); }, ErrorCode::NonFinite, {whole, "point 3"});
  auto huge = pts;
  huge[4].y() = 1e300;
  expect_error([&] { dbs::write_draco_point_cloud(whole, huge, uv, uv); }, ErrorCode::OutOfRange, {whole, "point 4"});
}

}  // namespace

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(xyz_round_trips_every_accepted_spelling),
      cmocka_unit_test(xyz_keeps_full_double_precision),
      cmocka_unit_test(numbers_beyond_the_double_range),
      cmocka_unit_test(xyz_rejects_malformed_truncated_nonfinite_and_empty),
      cmocka_unit_test(unknown_extension_is_unsupported),
      cmocka_unit_test(example_data_loads),
      cmocka_unit_test(ascii_ply_round_trips),
      cmocka_unit_test(binary_ply_round_trips_both_byte_orders),
      cmocka_unit_test(ply_rejects_malformed_truncated_nonfinite_and_empty),
      cmocka_unit_test(ply_values_are_exact_doubles),
      cmocka_unit_test(ply_header_claims_are_checked_before_reading),
      cmocka_unit_test(obj_reads_every_v_line_and_ignores_the_rest),
      cmocka_unit_test(obj_rejects_malformed_truncated_nonfinite_and_empty),
      cmocka_unit_test(drc_round_trips_within_quantization),
      cmocka_unit_test(drc_rejects_garbage_truncated_and_empty),
  };
  return cmocka_run_group_tests(tests, nullptr, nullptr);
}
