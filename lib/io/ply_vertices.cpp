#include "ply_vertices.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <string_view>
#include <vector>

#include "error.hpp"
#include "text_io.hpp"

namespace dbs {

namespace {

enum class PlyFormat { Ascii, LittleEndian, BigEndian };

struct ScalarType {
  int bytes = 0;
  bool is_signed = false;
  bool is_float = false;
};

struct Property {
  std::string name;
  ScalarType type;
  bool is_list = false;
  ScalarType count_type;  // lists only
};

struct Element {
  std::string name;
  std::int64_t count = 0;
  std::vector<Property> properties;
  std::size_t header_line = 0;  // index into Header::lines
};

struct Header {
  PlyFormat format = PlyFormat::Ascii;
  std::vector<std::string_view> lines;  // "ply" .. "end_header", without '\n'
  std::size_t data_begin = 0;           // byte offset of the data
  std::vector<Element> elements;
  std::size_t vertex = 0;  // index of the vertex element
};

bool is_blank(char c) { return c == ' ' || c == '\t' || c == '\r'; }

void split_blanks(std::string_view line, std::vector<std::string_view>& words) {
  words.clear();
  std::size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && is_blank(line[i])) ++i;
    const std::size_t start = i;
    while (i < line.size() && !is_blank(line[i])) ++i;
    if (i > start) words.push_back(line.substr(start, i - start));
  }
}

std::vector<std::string_view> split_blanks(std::string_view line) {
  std::vector<std::string_view> words;
  split_blanks(line, words);
  return words;
}

bool scalar_type(std::string_view name, ScalarType& type) {
  static const struct {
    const char* name;
    ScalarType type;
  } kTypes[] = {
      {"char", {1, true, false}},   {"int8", {1, true, false}},     {"uchar", {1, false, false}},  {"uint8", {1, false, false}},
      {"short", {2, true, false}},  {"int16", {2, true, false}},    {"ushort", {2, false, false}}, {"uint16", {2, false, false}},
      {"int", {4, true, false}},    {"int32", {4, true, false}},    {"uint", {4, false, false}},   {"uint32", {4, false, false}},
      {"float", {4, true, true}},   {"float32", {4, true, true}},   {"double", {8, true, true}},   {"float64", {8, true, true}},
  };
  for (const auto& t : kTypes) {
    if (name == t.name) {
      type = t.type;
      return true;
    }
  }
  return false;
}

[[noreturn]] void header_error(const std::string& path, std::size_t line_index, const std::string& what) {
  fail(ErrorCode::Parse, file_line(path, line_index + 1) + ": " + what);
}

Header parse_header(std::string_view bytes, const std::string& path) {
  Header h;
  bool have_format = false;
  std::size_t pos = 0;
  while (true) {
    if (pos >= bytes.size()) fail(ErrorCode::Parse, path + ": the PLY header has no end_header line");
    const std::size_t eol = bytes.find('\n', pos);
    const std::string_view line = bytes.substr(pos, eol == std::string_view::npos ? std::string_view::npos : eol - pos);
    pos = eol == std::string_view::npos ? bytes.size() : eol + 1;
    const std::size_t index = h.lines.size();
    h.lines.push_back(line);
    const std::vector<std::string_view> words = split_blanks(line);
    if (index == 0) {
      if (words.size() != 1 || words[0] != "ply") header_error(path, index, "not a PLY file (the first line is not 'ply')");
      continue;
    }
    if (words.empty() || words[0] == "comment" || words[0] == "obj_info") continue;
    if (words[0] == "end_header") break;
    if (words[0] == "format") {
      if (words.size() != 3) header_error(path, index, "malformed format line '" + excerpt(line) + "'");
      if (words[1] == "ascii") h.format = PlyFormat::Ascii;
      else if (words[1] == "binary_little_endian") h.format = PlyFormat::LittleEndian;
      else if (words[1] == "binary_big_endian") h.format = PlyFormat::BigEndian;
      else header_error(path, index, "unknown PLY format '" + excerpt(words[1]) + "'");
      if (words[2] != "1.0") fail(ErrorCode::Unsupported, file_line(path, index + 1) + ": unsupported PLY version '" + excerpt(words[2]) + "' (expected 1.0)");
      have_format = true;
    } else if (words[0] == "element") {
      double count = -1;
      if (words.size() != 3 || !parse_number(words[2], count) || !(count >= 0) || count != std::floor(count) || count > 2147483647.0)
        header_error(path, index, "malformed element line '" + excerpt(line) + "'");
      Element e;
      e.name = std::string(words[1]);
      e.count = static_cast<std::int64_t>(count);
      e.header_line = index;
      h.elements.push_back(std::move(e));
    } else if (words[0] == "property") {
      if (h.elements.empty()) header_error(path, index, "property before any element");
      Property p;
      const bool list = words.size() == 5 && words[1] == "list";
      if (list) {
        p.is_list = true;
        if (!scalar_type(words[2], p.count_type) || p.count_type.is_float) header_error(path, index, "unknown list count type '" + excerpt(words[2]) + "'");
        if (!scalar_type(words[3], p.type)) header_error(path, index, "unknown property type '" + excerpt(words[3]) + "'");
        p.name = std::string(words[4]);
      } else {
        if (words.size() != 3) header_error(path, index, "malformed property line '" + excerpt(line) + "'");
        if (!scalar_type(words[1], p.type)) header_error(path, index, "unknown property type '" + excerpt(words[1]) + "'");
        p.name = std::string(words[2]);
      }
      h.elements.back().properties.push_back(std::move(p));
    } else {
      header_error(path, index, "unexpected header line '" + excerpt(line) + "'");
    }
  }
  h.data_begin = pos;
  if (!have_format) fail(ErrorCode::Parse, path + ": the PLY header has no format line");
  const auto vertex = std::find_if(h.elements.begin(), h.elements.end(), [](const Element& e) { return e.name == "vertex"; });
  if (vertex == h.elements.end()) fail(ErrorCode::Parse, path + ": the PLY file has no 'vertex' element");
  const auto second = std::find_if(vertex + 1, h.elements.end(), [](const Element& e) { return e.name == "vertex"; });
  if (second != h.elements.end()) header_error(path, second->header_line, "a second 'vertex' element (the first is on line " + std::to_string(vertex->header_line + 1) + ")");
  h.vertex = static_cast<std::size_t>(vertex - h.elements.begin());
  for (const char* axis : {"x", "y", "z"}) {
    // the same rule as property_index(): the first scalar property of that name
    const auto p = std::find_if(vertex->properties.begin(), vertex->properties.end(), [axis](const Property& q) { return q.name == axis && !q.is_list; });
    if (p == vertex->properties.end())
      header_error(path, vertex->header_line, std::string("the vertex element has no scalar '") + axis + "' property");
  }
  if (vertex->count == 0) fail(ErrorCode::Empty, path + ": no points (the PLY file declares 0 vertices)");
  return h;
}

std::string entry_name(const Element& e, std::int64_t k) { return e.name + " " + std::to_string(k); }

// ---- binary data -------------------------------------------------------------------

std::uint64_t read_unsigned(const char* p, int bytes) {
  std::uint64_t v = 0;
  for (int i = bytes - 1; i >= 0; --i) v = (v << 8) | static_cast<unsigned char>(p[i]);  // little-endian
  return v;
}

// Value of a list count (little-endian by now); negative counts come back negative.
std::int64_t read_count(const char* p, const ScalarType& t) {
  const std::uint64_t raw = read_unsigned(p, t.bytes);
  if (!t.is_signed) return static_cast<std::int64_t>(raw);
  const std::uint64_t sign = std::uint64_t{1} << (8 * t.bytes - 1);
  return static_cast<std::int64_t>(raw ^ sign) - static_cast<std::int64_t>(sign);
}

// A scalar of type t at p (little-endian by now) as a double: exact for every PLY type.
double scalar_value(const char* p, const ScalarType& t) {
  const std::uint64_t raw = read_unsigned(p, t.bytes);
  if (t.is_float) {
    if (t.bytes == 4) {
      const std::uint32_t bits = static_cast<std::uint32_t>(raw);
      float f;
      std::memcpy(&f, &bits, sizeof f);
      return static_cast<double>(f);
    }
    double d;
    std::memcpy(&d, &raw, sizeof d);
    return d;
  }
  if (!t.is_signed) return static_cast<double>(raw);
  const std::uint64_t sign = std::uint64_t{1} << (8 * t.bytes - 1);
  return static_cast<double>(static_cast<std::int64_t>(raw ^ sign) - static_cast<std::int64_t>(sign));
}

// Index of the scalar property `name` of e (parse_header checked it exists).
std::size_t property_index(const Element& e, const char* name) {
  return static_cast<std::size_t>(std::find_if(e.properties.begin(), e.properties.end(), [name](const Property& q) { return q.name == name && !q.is_list; }) - e.properties.begin());
}

// Walks the binary data of elements 0..vertex (turning big-endian values little-endian in
// place) and reads the vertices' x, y, z. An element without properties holds no data and
// is skipped at once, whatever its count.
std::vector<Vec3> read_binary(std::string& bytes, const Header& h, const std::string& path, LoadProgress& progress) {
  const bool swap = h.format == PlyFormat::BigEndian;
  std::size_t pos = h.data_begin;
  auto take = [&](std::size_t n, const Element& e, std::int64_t k) {
    if (bytes.size() - pos < n)
      fail(ErrorCode::Parse, path + ": the binary data ends inside " + entry_name(e, k) + " of " + std::to_string(e.count) + " (truncated file?)");
    char* p = &bytes[pos];
    pos += n;
    return p;
  };
  const Element& vertex = h.elements[h.vertex];
  const std::size_t axis[3] = {property_index(vertex, "x"), property_index(vertex, "y"), property_index(vertex, "z")};
  // Each vertex takes at least the bytes of its scalars and list counts: memory is reserved
  // for no more vertices than the file's data can hold, whatever the header claims (a
  // truncated or lying file fails at the vertex where its data ends).
  std::uint64_t vertex_bytes = 0;
  for (const Property& q : vertex.properties) vertex_bytes += static_cast<std::uint64_t>(q.is_list ? q.count_type.bytes : q.type.bytes);
  std::vector<Vec3> points;
  points.reserve(static_cast<std::size_t>(std::min<std::uint64_t>(static_cast<std::uint64_t>(vertex.count), (bytes.size() - h.data_begin) / vertex_bytes)));
  for (std::size_t ei = 0; ei <= h.vertex; ++ei) {
    const Element& e = h.elements[ei];
    if (e.properties.empty()) continue;
    const bool is_vertex = ei == h.vertex;
    for (std::int64_t k = 0; k < e.count; ++k) {
      progress.at(pos);
      Vec3 point = Vec3::Zero();
      for (std::size_t pi = 0; pi < e.properties.size(); ++pi) {
        const Property& p = e.properties[pi];
        std::int64_t values = 1;
        if (p.is_list) {
          char* c = take(static_cast<std::size_t>(p.count_type.bytes), e, k);
          if (swap) std::reverse(c, c + p.count_type.bytes);
          values = read_count(c, p.count_type);
          if (values < 0) fail(ErrorCode::Parse, path + ": " + entry_name(e, k) + " has a negative list length");
        }
        char* v = take(static_cast<std::size_t>(values) * static_cast<std::size_t>(p.type.bytes), e, k);
        if (swap)
          for (std::int64_t i = 0; i < values; ++i) std::reverse(v + i * p.type.bytes, v + (i + 1) * p.type.bytes);
        if (is_vertex)
          for (int a = 0; a < 3; ++a)
            if (pi == axis[a]) point[a] = scalar_value(v, p.type);
      }
      if (!is_vertex) continue;
      if (!is_finite(point)) fail(ErrorCode::NonFinite, path + ": vertex " + std::to_string(k) + " has a non-finite coordinate");
      points.push_back(point);
    }
  }
  return points;
}

// ---- ASCII data --------------------------------------------------------------------

// Calls row(element, k, line_number, values) for every entry of elements 0..vertex, one
// entry per non-blank line; returns the byte offset where the vertex element ends.
template <typename RowFn>
std::size_t walk_ascii(std::string_view bytes, const Header& h, const std::string& path, LoadProgress& progress, RowFn row) {
  std::size_t pos = h.data_begin;
  std::size_t line_number = h.lines.size();
  std::vector<std::string_view> values;
  for (std::size_t ei = 0; ei <= h.vertex; ++ei) {
    const Element& e = h.elements[ei];
    if (e.properties.empty()) continue;  // its entries hold no values and take no lines
    for (std::int64_t k = 0; k < e.count; ++k) {
      progress.at(pos);
      do {
        if (pos >= bytes.size())
          fail(ErrorCode::Parse, file_line(path, line_number) + ": the file ends before " + entry_name(e, k) + " of " + std::to_string(e.count) + " (truncated file?)");
        const std::size_t eol = bytes.find('\n', pos);
        split_blanks(bytes.substr(pos, eol == std::string_view::npos ? std::string_view::npos : eol - pos), values);
        pos = eol == std::string_view::npos ? bytes.size() : eol + 1;
        ++line_number;
      } while (values.empty());
      if (!row(e, k, line_number, values)) return pos;
    }
  }
  return pos;
}

// Number of values an ASCII row of `e` must hold, given its values (list lengths are read
// from the row); -1 when a list length is not a count (or absurdly large).
std::int64_t expected_values(const Element& e, const std::vector<std::string_view>& values) {
  std::size_t i = 0;
  for (const Property& p : e.properties) {
    if (!p.is_list) {
      ++i;
      continue;
    }
    double n = 0;
    if (i >= values.size()) return static_cast<std::int64_t>(i) + 1;
    if (!parse_number(values[i], n) || !(n >= 0 && n <= 1e9) || n != std::floor(n)) return -1;
    i += 1 + static_cast<std::size_t>(n);
  }
  return static_cast<std::int64_t>(i);
}

// Index in an ASCII row of `e` of the value of property `wanted` (list lengths read from
// the row, which expected_values() has checked).
std::size_t value_index(const Element& e, const std::vector<std::string_view>& values, std::size_t wanted) {
  std::size_t i = 0;
  for (std::size_t pi = 0; pi < wanted; ++pi) {
    if (!e.properties[pi].is_list) {
      ++i;
      continue;
    }
    double n = 0;
    parse_number(values[i], n);
    i += 1 + static_cast<std::size_t>(n);
  }
  return i;
}

std::vector<Vec3> read_ascii(std::string_view bytes, const Header& h, const std::string& path, LoadProgress& progress) {
  const Element& vertex = h.elements[h.vertex];
  const std::size_t axis[3] = {property_index(vertex, "x"), property_index(vertex, "y"), property_index(vertex, "z")};
  // An ASCII vertex takes at least 6 bytes ("0 0 0\n"): memory is reserved for no more
  // vertices than the file's data can hold (a truncated or lying file fails at the line
  // where its data ends).
  std::vector<Vec3> points;
  points.reserve(static_cast<std::size_t>(std::min<std::uint64_t>(static_cast<std::uint64_t>(vertex.count), (bytes.size() - h.data_begin) / 6 + 1)));
  walk_ascii(bytes, h, path, progress, [&](const Element& e, std::int64_t k, std::size_t line, const std::vector<std::string_view>& values) {
    const std::int64_t expected = expected_values(e, values);
    if (expected < 0) fail(ErrorCode::Parse, file_line(path, line) + ": " + entry_name(e, k) + " has a list length that is not a count");
    if (expected != static_cast<std::int64_t>(values.size()))
      fail(ErrorCode::Parse, file_line(path, line) + ": " + entry_name(e, k) + " has " + std::to_string(values.size()) + " values, expected " + std::to_string(expected));
    double x;
    for (const std::string_view v : values) {
      if (!parse_number(v, x)) fail(ErrorCode::Parse, file_line(path, line) + ": " + entry_name(e, k) + ": '" + excerpt(v) + "' is not a number");
    }
    if (&e == &vertex) {
      Vec3 p;
      for (int a = 0; a < 3; ++a) parse_number(values[value_index(e, values, axis[a])], p[a]);
      if (!is_finite(p)) fail(ErrorCode::NonFinite, file_line(path, line) + ": vertex " + std::to_string(k) + " has a non-finite coordinate");
      points.push_back(p);
    }
    return true;
  });
  return points;
}

}  // namespace

std::vector<Vec3> read_ply_vertices(std::string bytes, const std::string& path) {
  LoadProgress none;
  return read_ply_vertices(std::move(bytes), path, none);
}

std::vector<Vec3> read_ply_vertices(std::string bytes, const std::string& path, LoadProgress& progress) {
  if (bytes.empty()) fail(ErrorCode::Empty, path + ": no points (the file is empty)");
  const Header h = parse_header(bytes, path);
  return h.format == PlyFormat::Ascii ? read_ascii(bytes, h, path, progress) : read_binary(bytes, h, path, progress);
}

}  // namespace dbs
