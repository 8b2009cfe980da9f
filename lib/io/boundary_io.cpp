#include "boundary_io.hpp"

#include <array>
#include <cctype>

#include "error.hpp"
#include "text_io.hpp"

namespace dbs {

namespace {

constexpr const char* kSwappedHint = "was a cloud given where the boundary file belongs (CLOUD and BOUNDARY in the wrong order)?";

constexpr std::array<Side, 4> kSides = {Side::Bottom, Side::Right, Side::Top, Side::Left};

// The side a section line names (case-insensitive); false for any other word.
bool side_named(std::string_view word, Side& side) {
  std::string lower(word);
  for (char& c : lower) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  for (const Side s : kSides) {
    if (lower == side_name(s)) {
      side = s;
      return true;
    }
  }
  return false;
}

bool is_single_word(std::string_view line) { return line.find_first_of(" \t,") == std::string_view::npos; }

std::string first_token(std::string_view line) { return std::string(line.substr(0, line.find_first_of(" \t,"))); }

}  // namespace

bool is_boundary_section_name(std::string_view word) {
  Side side;
  return side_named(word, side);
}

Boundary load_boundary(const std::string& path) { return load_boundary(path, Boundary::CornerTolerance{Boundary::kCornerTolerance, true}); }

Boundary load_boundary(const std::string& path, Boundary::CornerTolerance tolerance) {
  const std::string text = read_file_bytes(path);
  std::array<std::vector<Vec3>, 4> points;
  std::array<std::size_t, 4> section_line{};  // 0: not seen
  int current = -1;
  ContentLines lines(text);
  std::string_view line;
  while (lines.next(line)) {
    const std::string at = file_line(path, lines.number());
    double number;
    if (!parse_number(first_token(line), number)) {
      Side side;
      if (!is_single_word(line))
        fail(ErrorCode::Parse, at + ": expected a section name (bottom, right, top, left) or 3 numbers, found '" + excerpt(line) + "'");
      if (!side_named(line, side)) fail(ErrorCode::Parse, at + ": unknown section '" + excerpt(line) + "' (expected bottom, right, top or left)");
      current = static_cast<int>(side);
      if (section_line[current] != 0)
        fail(ErrorCode::Parse, at + ": section '" + side_name(side) + "' given twice (first at line " + std::to_string(section_line[current]) + ")");
      section_line[current] = lines.number();
      continue;
    }
    if (current < 0) fail(ErrorCode::Parse, at + ": a point before any section name (bottom, right, top or left): " + kSwappedHint);
    Vec3 p;
    const XyzFields fields = parse_xyz_fields(line, p);
    if (fields.count < 3) fail(ErrorCode::Parse, at + ": " + fields.problem());
    const std::size_t extra = fields.rest.find_first_not_of(" \t,");
    if (extra != std::string_view::npos) fail(ErrorCode::Parse, at + ": expected 3 numbers, found more: '" + excerpt(fields.rest.substr(extra)) + "'");
    if (!is_finite(p)) fail(ErrorCode::NonFinite, at + ": non-finite coordinate in '" + excerpt(line) + "'");
    points[current].push_back(p);
  }
  if (section_line == std::array<std::size_t, 4>{}) fail(ErrorCode::Empty, path + ": no boundary sections (expected bottom, right, top and left)");
  for (const Side s : kSides) {
    const int i = static_cast<int>(s);
    if (section_line[i] == 0) fail(ErrorCode::Parse, path + ": section '" + side_name(s) + "' is missing");
    if (points[i].size() < 2)
      fail(ErrorCode::Parse, file_line(path, section_line[i]) + ": section '" + side_name(s) + "' has " + (points[i].empty() ? "no points" : "1 point") + ", needs at least 2");
  }
  try {
    return Boundary(std::move(points[0]), std::move(points[1]), std::move(points[2]), std::move(points[3]), tolerance);
  } catch (const Error& e) {
    throw Error(e.code(), path + ": " + e.what());
  }
}

void save_boundary(const Boundary& boundary, const std::string& path) {
  OutputFile file(path);
  file.write("# libdbs boundary: the sections bottom, right, top, left (docs/FORMATS.md)\n");
  std::string line;
  for (const Side s : kSides) {
    file.write(std::string(side_name(s)) + "\n");
    for (const Vec3& p : boundary.side(s).points()) {
      line.clear();
      for (int c = 0; c < 3; ++c) {
        if (c > 0) line += ' ';
        append_number(line, p[c]);
      }
      line += '\n';
      file.write(line);
    }
  }
  file.close();
}

}  // namespace dbs
