// Reading boundary files (FORMATS.md): sections bottom/right/top/left, one point per line.
#pragma once
#include <string>

#include "boundary.hpp"

namespace dbs {

/// Errors name the file and line: unknown section name, a point before any section, a
/// section given twice or missing, a malformed or non-finite coordinate, fewer than 2
/// points; geometric problems as Boundary's constructor reports them.
Boundary load_boundary(const std::string& path);

}  // namespace dbs
