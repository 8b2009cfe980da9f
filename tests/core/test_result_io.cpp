// Result files (FORMATS.md): the CSV has the exact header, one row per point in input order
// and numbers that read back bit-exactly; the PLY has the documented header and a binary
// payload that re-reads to the same numbers; the DRC keeps positions and (u,v) within its
// quantization; unwritable paths and mismatched sizes are rejected.
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "cloud_io.hpp"
#include "draco_io.hpp"
#include "error.hpp"
#include "result_io.hpp"
#include "core_test_support.hpp"

using dbs::ErrorCode;
using dbs::Vec3;
using core_test::expect_error;
using core_test::read_all;
using core_test::tmp_path;

namespace {

constexpr std::size_t kPoints = 3000;

dbs::PointCloud test_cloud() {
  std::vector<Vec3> pts;
  for (std::size_t i = 0; i < kPoints; ++i) {
    const double s = static_cast<double>(i) / (kPoints - 1);
    pts.emplace_back(246.0 * s + 1.0 / 3.0, 30.0 * std::sin(7.0 * s), 100.0 * s * s - 0.1);
  }
  return dbs::PointCloud(pts);
}

// Per-point fields with values whose shortest decimal form is long or unusual; (u,v) span
// [0,1].
dbs::Result test_result() {
  dbs::Result r;
  const double specials[] = {0.0, 1.0, 1.0 / 3.0, 0.1 + 0.2, 5e-324, 2.2250738585072014e-308, 1e-300, 0.99999999999999989};
  for (std::size_t i = 0; i < kPoints; ++i) {
    const double s = static_cast<double>(i) / (kPoints - 1);
    r.u.push_back(i < 8 ? specials[i] : s);
    r.v.push_back(std::fmod(std::sqrt(2.0) * static_cast<double>(i), 1.0));
    r.distance.push_back(i % 5 == 0 ? 0.0 : std::exp(-static_cast<double>(i % 97)) / 3.0);
    r.patch.push_back(static_cast<std::int32_t>(i % 21) + (i == 7 ? 2000000000 : 0));
    r.level.push_back(static_cast<std::int8_t>(i % 4));
  }
  return r;
}

std::vector<std::string> split(const std::string& s, char sep) {
  std::vector<std::string> parts;
  std::size_t pos = 0;
  while (true) {
    const std::size_t next = s.find(sep, pos);
    parts.push_back(s.substr(pos, next == std::string::npos ? std::string::npos : next - pos));
    if (next == std::string::npos) return parts;
    pos = next + 1;
  }
}

double exact_double(const std::string& text) {
  char* end = nullptr;
  const double x = std::strtod(text.c_str(), &end);
  if (*end != '\0') fail_msg("'%s' is not a number", text.c_str());
  return x;
}

void csv_has_header_rows_in_order_and_exact_numbers(void**) {
  const auto cloud = test_cloud();
  const auto result = test_result();
  const std::string path = tmp_path("result_io_result.CSV");
  dbs::save_result(result, cloud, path);
  const std::string text = read_all(path);
  assert_true(!text.empty() && text.back() == '\n');
  const auto lines = split(text.substr(0, text.size() - 1), '\n');
  assert_int_equal(lines.size(), kPoints + 1);
  assert_string_equal(lines[0].c_str(), "index,u,v,distance,patch,level");
  for (std::size_t i = 0; i < kPoints; ++i) {
    const auto f = split(lines[i + 1], ',');
    assert_int_equal(f.size(), 6);
    assert_int_equal(std::atoll(f[0].c_str()), i);
    // bit-exact round trip of every double
    assert_true(exact_double(f[1]) == result.u[i]);
    assert_true(exact_double(f[2]) == result.v[i]);
    assert_true(exact_double(f[3]) == result.distance[i]);
    assert_int_equal(std::atoll(f[4].c_str()), result.patch[i]);
    assert_int_equal(std::atoll(f[5].c_str()), result.level[i]);
  }
}

double le_double(const char* p) {
  std::uint64_t bits = 0;
  for (int i = 7; i >= 0; --i) bits = (bits << 8) | static_cast<unsigned char>(p[i]);
  double d;
  std::memcpy(&d, &bits, 8);
  return d;
}

std::int32_t le_int(const char* p) {
  std::uint32_t bits = 0;
  for (int i = 3; i >= 0; --i) bits = (bits << 8) | static_cast<unsigned char>(p[i]);
  return static_cast<std::int32_t>(bits);
}

void ply_has_documented_header_and_payload(void**) {
  const auto cloud = test_cloud();
  const auto result = test_result();
  const std::string path = tmp_path("result_io_result.ply");
  dbs::save_result(result, cloud, path);
  const std::string bytes = read_all(path);
  const std::string header =
      "ply\n"
      "format binary_little_endian 1.0\n"
      "element vertex 3000\n"
      "property double x\n"
      "property double y\n"
      "property double z\n"
      "property double u\n"
      "property double v\n"
      "property double distance\n"
      "property int patch\n"
      "end_header\n";
  assert_true(bytes.compare(0, header.size(), header) == 0);
  assert_int_equal(bytes.size(), header.size() + kPoints * 52);
  for (std::size_t i = 0; i < kPoints; ++i) {
    const char* rec = bytes.data() + header.size() + 52 * i;
    const Vec3& p = cloud.points()[i];
    const double expected[6] = {p.x(), p.y(), p.z(), result.u[i], result.v[i], result.distance[i]};
    for (int k = 0; k < 6; ++k) {
      if (le_double(rec + 8 * k) != expected[k]) fail_msg("point %zu field %d: %.17g, expected %.17g", i, k, le_double(rec + 8 * k), expected[k]);
    }
    assert_int_equal(le_int(rec + 48), result.patch[i]);
  }
  // and it is a PLY file that the cloud reader reads back, bit for bit
  const auto again = dbs::load_cloud(path);
  assert_int_equal(again.size(), kPoints);
  for (std::size_t i = 0; i < kPoints; ++i)
    for (int k = 0; k < 3; ++k) assert_true(again.points()[i][k] == cloud.points()[i][k]);
}

void drc_keeps_positions_and_parameters_within_quantization(void**) {
  const auto cloud = test_cloud();
  const auto result = test_result();
  const std::string path = tmp_path("result_io_result.drc");
  if (!dbs::draco_available()) {
    expect_error([&] { dbs::save_result(result, cloud, path); }, ErrorCode::Unsupported, {path});
    return;
  }
  dbs::save_result(result, cloud, path);
  const auto points = dbs::read_positions_with_draco(path);
  const auto uv = dbs::read_tex_coords_with_draco(path);
  assert_int_equal(points.size(), kPoints);
  assert_int_equal(uv.size(), kPoints);
  // 16 bits over the largest extent (and over the (u,v) spread of 1), plus float rounding
  const double extent = (cloud.bounds().max - cloud.bounds().min).maxCoeff();
  const double position_bound = extent / (2 * 65535.0) + 1e-5;
  const double uv_bound = 1.0 / (2 * 65535.0) + 1e-7;
  for (std::size_t i = 0; i < kPoints; ++i) {
    assert_true((points[i] - cloud.points()[i]).cwiseAbs().maxCoeff() <= position_bound);
    assert_true(std::fabs(uv[i].x() - result.u[i]) <= uv_bound);
    assert_true(std::fabs(uv[i].y() - result.v[i]) <= uv_bound);
  }
  assert_true(position_bound < 1e-4 * cloud.bounds().diagonal());
}

void bad_paths_and_sizes_are_rejected(void**) {
  const auto cloud = test_cloud();
  const auto result = test_result();
  for (const char* ext : {".csv", ".ply", ".drc"}) {
    const std::string path = tmp_path(std::string("result_io_no_such_directory/result") + ext);
    const bool via_draco = std::string(ext) == ".drc" && !dbs::draco_available();
    expect_error([&] { dbs::save_result(result, cloud, path); }, via_draco ? ErrorCode::Unsupported : ErrorCode::Io, {path});
    if (!via_draco) expect_error([&] { dbs::save_result(result, cloud, path); }, ErrorCode::Io, {"No such file or directory"});
  }
  const std::string unknown = tmp_path("result_io_result.txt");
  expect_error([&] { dbs::save_result(result, cloud, unknown); }, ErrorCode::Unsupported, {unknown, "'.txt'"});
  auto short_result = result;
  short_result.level.pop_back();
  const std::string csv = tmp_path("result_io_short.csv");
  expect_error([&] { dbs::save_result(short_result, cloud, csv); }, ErrorCode::InvalidArgument, {csv});
}

}  // namespace

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(csv_has_header_rows_in_order_and_exact_numbers),
      cmocka_unit_test(ply_has_documented_header_and_payload),
      cmocka_unit_test(drc_keeps_positions_and_parameters_within_quantization),
      cmocka_unit_test(bad_paths_and_sizes_are_rejected),
  };
  return cmocka_run_group_tests(tests, nullptr, nullptr);
}
