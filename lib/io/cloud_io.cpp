#include "cloud_io.hpp"

#include "boundary_io.hpp"
#include "draco_io.hpp"
#include "error.hpp"
#include "obj_vertices.hpp"
#include "ply_vertices.hpp"
#include "text_io.hpp"

namespace dbs {

std::vector<Vec3> read_xyz_text(const std::string& path) {
  LoadProgress none;
  return read_xyz_text(path, none);
}

std::vector<Vec3> read_xyz_text(const std::string& path, LoadProgress& progress) {
  const std::string text = read_file_bytes(path, progress);
  progress.begin("parse", 0.5, 1.0, text.size());
  std::vector<Vec3> points;
  // a scanned "x y z" line holds 24 bytes or more: reserve once (trimmed below) instead of
  // growing a large cloud step by step
  points.reserve(text.size() / 24 + 1);
  ContentLines lines(text);
  std::string_view line;
  Vec3 p;
  while (lines.next(line)) {
    progress.at(lines.offset());
    const XyzFields fields = parse_xyz_fields(line, p);
    if (fields.count < 3) {
      // A section name: the boundary file was given where the cloud belongs.
      const std::string hint = is_boundary_section_name(line) ? ": this is a boundary file, not a cloud (CLOUD and BOUNDARY in the wrong order?)" : "";
      fail(ErrorCode::Parse, file_line(path, lines.number()) + ": " + fields.problem() + hint);
    }
    if (!is_finite(p)) fail(ErrorCode::NonFinite, file_line(path, lines.number()) + ": non-finite coordinate in '" + excerpt(line) + "'");
    points.push_back(p);
  }
  if (points.empty()) fail(ErrorCode::Empty, path + ": no points");
  points.shrink_to_fit();
  return points;
}

PointCloud load_cloud(const std::string& path) {
  LoadProgress none;
  return load_cloud(path, none);
}

namespace {

std::vector<Vec3> read_points(const std::string& path, LoadProgress& progress) {
  const std::string ext = lowercase_extension(path);
  if (ext == ".xyz" || ext == ".txt") return read_xyz_text(path, progress);
  if (ext == ".ply" || ext == ".obj") {
    std::string bytes = read_file_bytes(path, progress);
    progress.begin("parse", 0.5, 1.0, bytes.size());
    if (ext == ".ply") return read_ply_vertices(std::move(bytes), path, progress);
    if (bytes.empty()) fail(ErrorCode::Empty, path + ": no points (the file is empty)");
    return read_obj_vertices(bytes, path, progress);
  }
  if (ext == ".drc") {
    // Draco decodes in one call: reported before and after it.
    progress.begin("decode", 0.0, 1.0, 1);
    return read_positions_with_draco(path);
  }
  const std::string what = ext.empty() ? "no extension" : "unknown extension '" + ext + "'";
  fail(ErrorCode::Unsupported, path + ": " + what + " for a point cloud (expected .xyz, .txt, .ply, .obj or .drc)");
}

}  // namespace

PointCloud load_cloud(const std::string& path, LoadProgress& progress) {
  PointCloud cloud(read_points(path, progress));
  progress.finish();
  return cloud;
}

}  // namespace dbs
