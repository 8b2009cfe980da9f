// The vertices of a Wavefront OBJ file, read by libdbs itself so that every coordinate is
// the exact double the file holds (std::from_chars). FORMATS.md reads only the `v` lines
// (a tab after the `v` is a blank, '#' starts a comment); faces, normals, texture
// coordinates and the rest are ignored, even malformed ones.
#pragma once
#include <string>
#include <string_view>
#include <vector>

#include "geometry.hpp"
#include "load_progress.hpp"

namespace dbs {

/// The `v` lines' first three numbers, in file order. Error(Parse) "PATH:LINE: vertex K:
/// expected 3 numbers, found 'abc'" for a `v` line not starting with 3 blank-separated
/// numbers (vertices numbered from 0), Error(NonFinite) for a non-finite coordinate,
/// Error(Empty) when there is no `v` line.
std::vector<Vec3> read_obj_vertices(std::string_view obj, const std::string& path);
/// The same, reporting the bytes parsed through `progress` (whose stage the caller began).
std::vector<Vec3> read_obj_vertices(std::string_view obj, const std::string& path, LoadProgress& progress);

}  // namespace dbs
