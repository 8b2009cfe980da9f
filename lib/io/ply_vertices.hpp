// The vertices of a PLY file (ASCII, binary little- or big-endian, version 1.0), read by
// libdbs itself so that every coordinate is the exact double the file holds (an ASCII value
// as std::from_chars reads it, a binary one of any PLY type converted exactly). Only x, y, z
// of the `vertex` element are read; the elements before it are checked and skipped (one
// without properties at once, whatever its count), those after it (faces: FORMATS.md
// ignores them) are not read. A header whose vertex count the file's bytes cannot hold is
// refused before anything is allocated. Errors name the file, and the line (ASCII) or the
// vertex (binary); vertices are numbered from 0.
#pragma once
#include <string>
#include <vector>

#include "geometry.hpp"
#include "load_progress.hpp"

namespace dbs {

/// Error(Parse) a malformed header or data (a second `vertex` element among them),
/// Error(Unsupported) a PLY version other than 1.0, Error(NonFinite) a non-finite
/// coordinate, Error(Empty) an empty file or no vertices.
std::vector<Vec3> read_ply_vertices(std::string bytes, const std::string& path);
/// The same, reporting the bytes parsed through `progress` (whose stage the caller began).
std::vector<Vec3> read_ply_vertices(std::string bytes, const std::string& path, LoadProgress& progress);

}  // namespace dbs
