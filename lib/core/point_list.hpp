// A list of points of a cloud, as indices into it: 4 bytes a point, which halves the
// largest lists of a run (a patch's subcloud holds up to the whole cloud) against size_t.
// Clouds are limited to 2^32 - 1 points, as CloudIndex is.
#pragma once

#include <cstdint>
#include <vector>

namespace dbs {

using PointList = std::vector<std::uint32_t>;

}  // namespace dbs
