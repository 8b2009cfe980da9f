// The points a patch's rays are cast against (eqs. 4-5, the grid and middle-curve
// projections). The weights of eq. (5) are measured in units of the length scale h, so a ray
// gathers about the same number of points at any density, and a section is densified to
// nodes 2 h apart: on a dense patch (a large cloud's upper levels) the rays alone cost in
// proportion to sqrt(n) per section, and the patch's index over all its points is built for
// them only. A patch whose subcloud holds more than `max_points` is evolved against an even
// sample of about max_points of its points instead, with the length scale of that sample,
// h sqrt(n / m): the same count of points per ray, each ray averaging over a wider patch of the
// surface, the grid (at most max_grid nodes a side) being far coarser still. Its distances are
// still measured on the whole subcloud, so a patch the sample fits too coarsely is split, and
// its children, with fewer points each, are sampled less or not at all.
//
// A point is kept when a hash of its index falls below m / n: the sample is spread evenly
// whatever order the cloud comes in (a scan's rows, the medians of a tree), it depends on
// neither the thread count nor the subcloud's order, and a subcloud within the bound is
// taken whole, so clouds up to that size are processed as before.
#pragma once
#include <cstddef>

#include "point_list.hpp"

namespace dbs {

/// Subclouds up to this many points are evolved against all of them.
constexpr std::size_t kMaxRayPoints = std::size_t{1} << 15;

struct RayCloud {
  PointList points;     // the sample, in the subcloud's order; empty when the subcloud is taken whole
  double length_scale;  // h of the points the rays see
  bool sampled() const { return !points.empty(); }
};

/// The sample of `subcloud` (cloud spacing h > 0) for a patch's rays; `max_points` 0: no bound.
RayCloud ray_cloud(const PointList& subcloud, double h, std::size_t max_points = kMaxRayPoints);

}  // namespace dbs
