// A hash of a point's index, for choices that must be spread evenly over a cloud whatever
// its order and the same for every thread count (samples of points).
#pragma once
#include <cstdint>

namespace dbs {

/// SplitMix64's finalizer: consecutive k map to unrelated values spread over all 64 bits.
inline std::uint64_t index_hash(std::uint64_t k) {
  k += 0x9e3779b97f4a7c15ULL;
  k = (k ^ (k >> 30)) * 0xbf58476d1ce4e5b9ULL;
  k = (k ^ (k >> 27)) * 0x94d049bb133111ebULL;
  return k ^ (k >> 31);
}

}  // namespace dbs
