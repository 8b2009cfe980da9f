// The whole method: index the cloud, evolve the root base surface, subdivide recursively
// where it is not accurate, and parameterize every point on its best leaf (algorithm A2).
#pragma once
#include "boundary.hpp"
#include "options.hpp"
#include "point_cloud.hpp"
#include "result.hpp"

namespace dbs {

/// Throws Error (Cancelled when a callback asks to stop). Options are assumed valid
/// (set_option checks them).
Result parameterize(const PointCloud& cloud, const Boundary& boundary, const Options& options);

}  // namespace dbs
