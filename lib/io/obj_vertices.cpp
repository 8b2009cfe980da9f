#include "obj_vertices.hpp"

#include "error.hpp"
#include "geometry.hpp"
#include "text_io.hpp"

namespace dbs {

namespace {

// True for a `v` line (ContentLines trimmed it); `fields` receives what follows the `v`.
bool vertex_fields(std::string_view line, std::string_view& fields) {
  if (line.size() < 1 || line[0] != 'v') return false;
  if (line.size() > 1 && line[1] != ' ' && line[1] != '\t') return false;  // vn, vt, vp, ...
  fields = line.substr(1);
  while (!fields.empty() && (fields.front() == ' ' || fields.front() == '\t')) fields.remove_prefix(1);
  return true;
}

// Calls fn(vertex index, line number, fields) for every `v` line until it returns false.
template <typename Fn>
void for_each_vertex_line(std::string_view obj, LoadProgress& progress, Fn fn) {
  ContentLines lines(obj);
  std::string_view line, fields;
  std::size_t k = 0;
  while (lines.next(line)) {
    progress.at(lines.offset());
    if (vertex_fields(line, fields) && !fn(k++, lines.number(), fields)) return;
  }
}

}  // namespace

std::vector<Vec3> read_obj_vertices(std::string_view obj, const std::string& path) {
  LoadProgress none;
  return read_obj_vertices(obj, path, none);
}

std::vector<Vec3> read_obj_vertices(std::string_view obj, const std::string& path, LoadProgress& progress) {
  std::vector<Vec3> points;
  for_each_vertex_line(obj, progress, [&](std::size_t k, std::size_t line, std::string_view fields) {
    Vec3 p;
    const XyzFields parsed = parse_xyz_fields(fields, p);
    const std::string at = file_line(path, line) + ": vertex " + std::to_string(k);
    if (parsed.count < 3) fail(ErrorCode::Parse, at + ": " + parsed.problem());
    if (fields.substr(0, fields.size() - parsed.rest.size()).find(',') != std::string_view::npos)
      fail(ErrorCode::Parse, at + ": expected 3 numbers separated by blanks, found a comma");
    if (!is_finite(p)) fail(ErrorCode::NonFinite, at + " has a non-finite coordinate");
    points.push_back(p);
    return true;
  });
  if (points.empty()) fail(ErrorCode::Empty, path + ": no points (the OBJ file has no 'v' lines)");
  return points;
}

}  // namespace dbs
