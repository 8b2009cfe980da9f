// Preparing a PLY file for Draco's PLY reader, which reads only what it is given and
// checks little (it reads past the end of a truncated binary file, and an ASCII row with a
// value missing shifts every later value): the header is parsed here, the data is checked
// up to the end of the vertex element (truncation; ASCII: values per row, each a number),
// big-endian data is turned little-endian
// (Draco reads only ascii and binary_little_endian) and the elements after the vertices
// (faces: FORMATS.md ignores them) are declared empty and cut off. Errors name the file
// and the line (ASCII) or the vertex (binary); vertices are numbered from 0.
#pragma once
#include <cstddef>
#include <cstdint>
#include <string>

namespace dbs {

struct PreparedPly {
  std::string text;              // a PLY file ending with the vertex element
  bool ascii = false;
  std::int64_t vertex_count = 0;  // > 0
};

/// Error(Parse) malformed header or data, Error(Unsupported) a PLY version other than 1.0,
/// Error(Empty) no vertices.
PreparedPly prepare_ply_vertices(std::string bytes, const std::string& path);

/// ASCII only: the 1-based line of vertex `k` (it is the same in the original file).
std::size_t ply_vertex_line(const PreparedPly& ply, std::int64_t k);

}  // namespace dbs
