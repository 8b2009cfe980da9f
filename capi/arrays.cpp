#include "arrays.hpp"

#include <algorithm>
#include <string>

#include "firewall.hpp"

namespace dbs::capi {

std::vector<Vec3> points_from(const double* xyz, std::size_t count) {
  std::vector<Vec3> points;
  // A count no array can have is the caller's mistake; a merely huge one is a memory shortage.
  if (count > points.max_size()) fail_status(DBS_ERR_INVALID_ARGUMENT, "point count " + std::to_string(count) + " exceeds any addressable array");
  points.resize(count);
  for (std::size_t i = 0; i < count; ++i) points[i] = Vec3(xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2]);
  return points;
}

void copy_points(const std::vector<Vec3>& points, double* out_xyz, std::size_t capacity, const char* name) {
  require_capacity(name, capacity, points.size(), "points");
  for (std::size_t i = 0; i < points.size(); ++i) std::copy(points[i].data(), points[i].data() + 3, out_xyz + 3 * i);
}

}  // namespace dbs::capi
