// Flat x0 y0 z0 x1 y1 z1 ... arrays of the C API to and from the core's points.
#pragma once
#include <cstddef>
#include <vector>

#include "geometry.hpp"

namespace dbs::capi {

/// The `count` points of `xyz` (3*count doubles, not NULL). Values are copied as given;
/// the core checks them.
std::vector<Vec3> points_from(const double* xyz, std::size_t count);

/// Copies `points` into `out_xyz`, a caller buffer named `name` of `capacity` points;
/// DBS_ERR_BUFFER_TOO_SMALL (nothing written) when it cannot hold them all.
void copy_points(const std::vector<Vec3>& points, double* out_xyz, std::size_t capacity, const char* name);

}  // namespace dbs::capi
