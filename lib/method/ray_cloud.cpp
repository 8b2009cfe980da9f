#include "ray_cloud.hpp"

#include <cmath>
#include <cstdint>

#include "index_hash.hpp"

namespace dbs {

RayCloud ray_cloud(const PointList& subcloud, double h, std::size_t max_points) {
  const std::size_t n = subcloud.size();
  if (n <= max_points || max_points == 0) return RayCloud{PointList(), h};
  const double fraction = static_cast<double>(max_points) / static_cast<double>(n);
  // Compared on the top 53 bits, which a double holds exactly.
  const std::uint64_t below = static_cast<std::uint64_t>(std::ldexp(fraction, 53));
  RayCloud sample{PointList(), h};
  sample.points.reserve(max_points + max_points / 8);
  for (std::uint32_t i : subcloud)
    if ((index_hash(i) >> 11) < below) sample.points.push_back(i);
  // Nothing kept (a tiny fraction of a small list): the subcloud is taken whole.
  if (sample.points.empty()) return RayCloud{PointList(), h};
  sample.length_scale = h * std::sqrt(static_cast<double>(n) / static_cast<double>(sample.points.size()));
  return sample;
}

}  // namespace dbs
