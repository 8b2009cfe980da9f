// A point set cut into spatially compact chunks of bounded size: the top levels of a k-d
// tree, made by halving a range at the median of its widest axis until no range holds more
// than a given number of points. CloudIndex indexes a large cloud as one small tree per
// chunk, so that its build runs in parallel, reports progress after every chunk and can be
// cancelled, while a query visits only the chunks whose boxes can hold an answer.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "geometry.hpp"

namespace dbs {

class WorkMeter;

/// A contiguous range [begin, end) of the slots, and the box of its points.
struct ChunkRange {
  std::size_t begin = 0, end = 0;
  Box3 box;
};

/// Reorders `slots` (indices into `points`) so that every chunk is a contiguous range of it,
/// and returns the chunks in order (none for no slots; one, the slots unchanged, when they
/// are at most `max_points`). Deterministic: ties on an axis are broken by the index, so
/// the cut depends on the points and the slots only, not on `threads`. Counts one unit of
/// `meter` per kPointsPerIndexUnit points a halving pass reads.
std::vector<ChunkRange> cut_into_chunks(const std::vector<Vec3>& points, std::vector<std::uint32_t>& slots, std::size_t max_points, int threads, WorkMeter* meter);

/// Points of a build (a halving pass or a tree) per unit of work counted on a WorkMeter.
constexpr std::size_t kPointsPerIndexUnit = 32;
/// The units of a pass over the slots [begin, end): those of consecutive ranges add up to
/// the units of their union, so a pass over all n slots counts n / kPointsPerIndexUnit.
inline std::uint64_t index_units(std::size_t begin, std::size_t end) { return end / kPointsPerIndexUnit - begin / kPointsPerIndexUnit; }

/// The halving passes a range of n points goes through before its chunks are at most
/// max_points: ceil(log2(n / max_points)), 0 when n <= max_points.
int halving_passes(std::size_t n, std::size_t max_points);

}  // namespace dbs
