// Triangles over a point set: three vertex indices (into the points, or a cloud) each.
#pragma once
#include <array>
#include <cstdint>
#include <vector>

namespace dbs {

using Triangle = std::array<std::int32_t, 3>;

}  // namespace dbs
