#include "spatial_chunks.hpp"

#include <algorithm>

#include "work_meter.hpp"

namespace dbs {

namespace {

Box3 box_of(const std::vector<Vec3>& points, const std::vector<std::uint32_t>& slots, std::size_t begin, std::size_t end) {
  Box3 box;
  for (std::size_t k = begin; k < end; ++k) box.extend(points[slots[k]]);
  return box;
}

int widest_axis(const Box3& box) {
  const Vec3 extent = box.max - box.min;
  int axis = 0;
  for (int a = 1; a < 3; ++a)
    if (extent[a] > extent[axis]) axis = a;
  return axis;
}

}  // namespace

int halving_passes(std::size_t n, std::size_t max_points) {
  int passes = 0;
  for (std::size_t size = n; size > std::max<std::size_t>(max_points, 1); size = (size + 1) / 2) ++passes;
  return passes;
}

std::vector<ChunkRange> cut_into_chunks(const std::vector<Vec3>& points, std::vector<std::uint32_t>& slots, std::size_t max_points, int threads, WorkMeter* meter) {
  max_points = std::max<std::size_t>(max_points, 1);
  std::vector<ChunkRange> ranges;
  if (slots.empty()) return ranges;
  ranges.push_back({0, slots.size(), box_of(points, slots, 0, slots.size())});
  // Level by level, every range of a level halved in parallel (they own disjoint slots).
  for (;;) {
    std::vector<ChunkRange> next;
    std::vector<std::size_t> halved;  // positions in `next` of the first halves to fill
    for (const ChunkRange& r : ranges) {
      if (r.end - r.begin <= max_points) {
        next.push_back(r);
        continue;
      }
      halved.push_back(next.size());
      next.push_back({r.begin, r.begin + (r.end - r.begin) / 2, r.box});
      next.push_back({r.begin + (r.end - r.begin) / 2, r.end, r.box});
    }
    if (halved.empty()) return ranges;
    metered_for(meter, halved.size(), threads, [&](std::size_t h) {
      ChunkRange& low = next[halved[h]];
      ChunkRange& high = next[halved[h] + 1];
      const int axis = widest_axis(low.box);
      const auto first = slots.begin() + static_cast<std::ptrdiff_t>(low.begin);
      std::nth_element(first, slots.begin() + static_cast<std::ptrdiff_t>(low.end), slots.begin() + static_cast<std::ptrdiff_t>(high.end), [&](std::uint32_t a, std::uint32_t b) {
        const double pa = points[a][axis], pb = points[b][axis];
        return pa < pb || (pa == pb && a < b);
      });
      low.box = box_of(points, slots, low.begin, low.end);
      high.box = box_of(points, slots, high.begin, high.end);
      count_work(meter, index_units(low.begin, high.end));
    });
    ranges = std::move(next);
  }
}

}  // namespace dbs
