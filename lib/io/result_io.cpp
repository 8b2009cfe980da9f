#include "result_io.hpp"

#include <cstdint>

#include "draco_io.hpp"
#include "error.hpp"
#include "little_endian.hpp"
#include "text_io.hpp"

namespace dbs {

namespace {

void write_csv(const Result& result, const std::string& path) {
  OutputFile file(path);
  file.write("index,u,v,distance,patch,level\n");
  std::string row;
  for (std::size_t i = 0; i < result.u.size(); ++i) {
    row.clear();
    append_integer(row, static_cast<long long>(i));
    row += ',';
    append_number(row, result.u[i]);
    row += ',';
    append_number(row, result.v[i]);
    row += ',';
    append_number(row, result.distance[i]);
    row += ',';
    append_integer(row, result.patch[i]);
    row += ',';
    append_integer(row, result.level[i]);
    row += '\n';
    file.write(row);
  }
  file.close();
}

// Written by hand: Draco's PLY encoder writes only the attributes it knows (positions,
// normals, colors, texture coordinates), not custom properties such as distance and patch.
// Doubles (since 0.4; floats before), so that map coordinates read back bit for bit.
void write_ply(const Result& result, const PointCloud& cloud, const std::string& path) {
  OutputFile file(path);
  file.write("ply\nformat binary_little_endian 1.0\nelement vertex " + std::to_string(cloud.size()) +
             "\nproperty double x\nproperty double y\nproperty double z\nproperty double u\nproperty double v\n"
             "property double distance\nproperty int patch\nend_header\n");
  std::string row;
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    row.clear();
    const Vec3& p = cloud.points()[i];
    for (const double x : {p.x(), p.y(), p.z(), result.u[i], result.v[i], result.distance[i]}) append_le_double(row, x);
    append_le32(row, static_cast<std::uint32_t>(result.patch[i]));
    file.write(row);
  }
  file.close();
}

}  // namespace

void save_result(const Result& result, const PointCloud& cloud, const std::string& path) {
  const std::size_t n = cloud.size();
  if (result.u.size() != n || result.v.size() != n || result.distance.size() != n || result.patch.size() != n || result.level.size() != n)
    fail(ErrorCode::InvalidArgument, "cannot write '" + path + "': the result holds " + std::to_string(result.u.size()) + " points, the cloud " + std::to_string(n));
  const std::string ext = lowercase_extension(path);
  if (ext == ".csv") return write_csv(result, path);
  if (ext == ".ply") return write_ply(result, cloud, path);
  if (ext == ".drc") {
    if (result.cropped_points == 0) return write_draco_point_cloud(path, cloud.points(), result.u, result.v);
    std::vector<Vec3> points;
    std::vector<double> u, v;
    for (std::size_t i = 0; i < n; ++i) {
      if (result.is_cropped(i)) continue;
      points.push_back(cloud.points()[i]);
      u.push_back(result.u[i]);
      v.push_back(result.v[i]);
    }
    return write_draco_point_cloud(path, points, u, v);
  }
  const std::string what = ext.empty() ? "no extension" : "unknown extension '" + ext + "'";
  fail(ErrorCode::Unsupported, path + ": " + what + " for a result (expected .csv, .ply or .drc)");
}

}  // namespace dbs
