// Reading point clouds from files (FORMATS.md). Text .xyz/.txt, .ply and .obj files are read
// by readers of our own, to exact doubles, in every build; .drc goes through Draco (draco_io).
#pragma once
#include <string>
#include <vector>

#include "load_progress.hpp"
#include "point_cloud.hpp"

namespace dbs {

/// By extension (case-insensitive): .xyz .txt .ply .obj .drc. Errors name the file, the line
/// (or element) and the problem: Error(Io) cannot open/read, Error(Parse) malformed or
/// truncated, Error(NonFinite), Error(Empty) no points, Error(Unsupported) unknown extension
/// or a .drc file in a build without Draco.
PointCloud load_cloud(const std::string& path);
/// The same, reporting through `progress` (see load_progress.hpp) and cancelled by it
/// (Error(Cancelled)).
PointCloud load_cloud(const std::string& path, LoadProgress& progress);

/// x y z per line, separated by spaces, tabs or commas; further columns ignored; '#' starts a
/// comment; blank lines ignored.
std::vector<Vec3> read_xyz_text(const std::string& path);
std::vector<Vec3> read_xyz_text(const std::string& path, LoadProgress& progress);

}  // namespace dbs
