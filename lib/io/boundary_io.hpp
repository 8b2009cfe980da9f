// Reading and writing boundary files (FORMATS.md): sections bottom/right/top/left, one point per line.
#pragma once
#include <string>
#include <string_view>

#include "boundary.hpp"

namespace dbs {

/// Errors name the file and line: unknown section name, a point before any section, a
/// section given twice or missing, a malformed or non-finite coordinate, fewer than 2
/// points; geometric problems as Boundary's constructor reports them.
Boundary load_boundary(const std::string& path);
/// The same with corners allowed to miss by `tolerance` (Boundary's constructor).
Boundary load_boundary(const std::string& path, Boundary::CornerTolerance tolerance);

/// Writes `boundary` in the boundary file format (FORMATS.md): a comment line, then the
/// sections bottom, right, top, left, each point as the shortest text that reads back to the
/// same double, so that load_boundary gives the same sides bit for bit. Error(Io) when the
/// file cannot be written.
void save_boundary(const Boundary& boundary, const std::string& path);

/// Whether `word` names a section of a boundary file (bottom, right, top, left; any case).
bool is_boundary_section_name(std::string_view word);

}  // namespace dbs
