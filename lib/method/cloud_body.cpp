#include "cloud_body.hpp"

#include <algorithm>
#include <cmath>

#include "corner_frame.hpp"

namespace dbs {

CloudBody cloud_body(const std::vector<Vec3>& points, const Boundary& boundary) {
  const std::size_t n = points.size();
  const CornerFrameBox frame(boundary);
  // The central box: per frame axis, the quantiles of a strided sample.
  const std::size_t samples = std::min(n, kBodySample);
  Vec3 low, high;
  for (int axis = 0; axis < 3; ++axis) {
    std::vector<double> values(samples);
    for (std::size_t k = 0; k < samples; ++k) values[k] = frame.local(points[static_cast<std::size_t>(static_cast<unsigned long long>(k) * n / samples)])[axis];
    const auto lo = values.begin() + static_cast<std::ptrdiff_t>(kBodyQuantile * static_cast<double>(samples - 1));
    std::nth_element(values.begin(), lo, values.end());
    low[axis] = *lo;
    const auto hi = values.begin() + static_cast<std::ptrdiff_t>((1.0 - kBodyQuantile) * static_cast<double>(samples - 1));
    std::nth_element(values.begin(), hi, values.end());
    high[axis] = *hi;
  }
  // The cloud's extent: the central box's largest side (its diagonal could be all in one
  // thin axis of a flat scan); a cloud whose central box is a point takes the boundary's size.
  double extent = (high - low).maxCoeff();
  if (!(extent > 0.0)) extent = boundary.size();
  const double reach = kFarOutside * extent;
  CloudBody out;
  out.far.assign(n, 0);
  out.body.reserve(n);  // every point but the rare far ones: no doubling of a list of them all
  Box3 box;
  for (std::size_t i = 0; i < n; ++i) {
    const Vec3 q = frame.local(points[i]);
    // Distance to the central box per axis; far when one exceeds the reach (no squares: the
    // coordinates may be near the largest doubles).
    const Vec3 outside = (low - q).cwiseMax(q - high).cwiseMax(0.0);
    if (outside.maxCoeff() > reach || !std::isfinite(outside.maxCoeff())) {
      out.far[i] = 1;
      continue;
    }
    out.body.push_back(i);
    box.extend(q);
  }
  out.diagonal = box.diagonal();
  return out;
}

}  // namespace dbs
