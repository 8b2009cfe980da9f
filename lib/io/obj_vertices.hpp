// The vertex lines of a Wavefront OBJ file, checked and prepared for Draco's OBJ decoder.
// FORMATS.md reads only the `v` lines and ignores faces, while Draco's decoder also
// validates faces, normals and texture coordinates (and, without faces, rejects a file whose
// vt/vn counts differ from its v count), silently skips a `v` line written with a tab or
// without numbers, and reads "3abc" as 3. So the `v` lines are checked here, with errors
// naming the file and line, and Draco is given only them, normalized.
#pragma once
#include <cstddef>
#include <string>
#include <string_view>

namespace dbs {

/// One "v x y z..." line per vertex line of `obj`, in order (a tab after the `v` becomes a
/// space, '#' comments are dropped). Error(Parse) "PATH:LINE: vertex K: expected 3 numbers,
/// found 'abc'" for a `v` line not starting with 3 blank-separated numbers (vertices
/// numbered from 0),
/// Error(Empty) when there is no `v` line.
std::string obj_vertex_lines(std::string_view obj, const std::string& path);

/// The 1-based line of vertex `k` (0-based, in file order) of `obj`.
std::size_t obj_vertex_line(std::string_view obj, std::size_t k);

}  // namespace dbs
