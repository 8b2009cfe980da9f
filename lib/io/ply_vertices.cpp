#include "ply_vertices.hpp"

#include <algorithm>
#include <cmath>
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
  h.vertex = static_cast<std::size_t>(vertex - h.elements.begin());
  for (const char* axis : {"x", "y", "z"}) {
    const auto p = std::find_if(vertex->properties.begin(), vertex->properties.end(), [axis](const Property& q) { return q.name == axis; });
    if (p == vertex->properties.end() || p->is_list)
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

// Walks the binary data of elements 0..vertex, turning big-endian values little-endian in
// place; returns the byte offset where the vertex element ends.
std::size_t walk_binary(std::string& bytes, const Header& h, const std::string& path) {
  const bool swap = h.format == PlyFormat::BigEndian;
  std::size_t pos = h.data_begin;
  auto take = [&](std::size_t n, const Element& e, std::int64_t k) {
    if (bytes.size() - pos < n)
      fail(ErrorCode::Parse, path + ": the binary data ends inside " + entry_name(e, k) + " of " + std::to_string(e.count) + " (truncated file?)");
    char* p = &bytes[pos];
    pos += n;
    return p;
  };
  for (std::size_t ei = 0; ei <= h.vertex; ++ei) {
    const Element& e = h.elements[ei];
    for (std::int64_t k = 0; k < e.count; ++k) {
      for (const Property& p : e.properties) {
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
      }
    }
  }
  return pos;
}

// ---- ASCII data --------------------------------------------------------------------

// Calls row(element, k, line_number, values) for every entry of elements 0..vertex, one
// entry per non-blank line; returns the byte offset where the vertex element ends.
template <typename RowFn>
std::size_t walk_ascii(std::string_view bytes, const Header& h, const std::string& path, RowFn row) {
  std::size_t pos = h.data_begin;
  std::size_t line_number = h.lines.size();
  std::vector<std::string_view> values;
  for (std::size_t ei = 0; ei <= h.vertex; ++ei) {
    const Element& e = h.elements[ei];
    for (std::int64_t k = 0; k < e.count; ++k) {
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

std::string rebuilt_header(const Header& h) {
  std::string out;
  std::size_t next_element = 0;
  for (std::size_t i = 0; i < h.lines.size(); ++i) {
    const bool is_element_line = next_element < h.elements.size() && h.elements[next_element].header_line == i;
    if (is_element_line && next_element > h.vertex) {
      out += "element " + h.elements[next_element].name + " 0";  // same line count: line numbers hold
    } else if (h.format == PlyFormat::BigEndian && split_blanks(h.lines[i]).size() == 3 && split_blanks(h.lines[i])[0] == "format") {
      out += "format binary_little_endian 1.0";
    } else {
      out += h.lines[i];
    }
    if (is_element_line) ++next_element;
    out += '\n';
  }
  return out;
}

}  // namespace

PreparedPly prepare_ply_vertices(std::string bytes, const std::string& path) {
  const Header h = parse_header(bytes, path);
  std::size_t data_end;
  if (h.format == PlyFormat::Ascii) {
    data_end = walk_ascii(bytes, h, path, [&](const Element& e, std::int64_t k, std::size_t line, const std::vector<std::string_view>& values) {
      const std::int64_t expected = expected_values(e, values);
      if (expected < 0) fail(ErrorCode::Parse, file_line(path, line) + ": " + entry_name(e, k) + " has a list length that is not a count");
      if (expected != static_cast<std::int64_t>(values.size()))
        fail(ErrorCode::Parse, file_line(path, line) + ": " + entry_name(e, k) + " has " + std::to_string(values.size()) + " values, expected " + std::to_string(expected));
      double x;
      for (const std::string_view v : values) {
        if (!parse_number(v, x)) fail(ErrorCode::Parse, file_line(path, line) + ": " + entry_name(e, k) + ": '" + excerpt(v) + "' is not a number");
      }
      return true;
    });
  } else {
    data_end = walk_binary(bytes, h, path);
  }
  PreparedPly out;
  out.ascii = h.format == PlyFormat::Ascii;
  out.vertex_count = h.elements[h.vertex].count;
  out.text = rebuilt_header(h);
  out.text.append(bytes, h.data_begin, data_end - h.data_begin);
  return out;
}

std::size_t ply_vertex_line(const PreparedPly& ply, std::int64_t k) {
  const Header h = parse_header(ply.text, "");
  std::size_t found = 0;
  walk_ascii(ply.text, h, "", [&](const Element& e, std::int64_t entry, std::size_t line, const std::vector<std::string_view>&) {
    if (&e != &h.elements[h.vertex] || entry != k) return true;
    found = line;
    return false;
  });
  return found;
}

}  // namespace dbs
