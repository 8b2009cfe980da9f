// What the last-resort repair (and the smoothing of turned sheets) may change in a result,
// saved so that one repair can be tried and undone: every point's (u,v), distance, patch, level and flag, and every leaf's surface,
// grid and judged figures (a refit changes a leaf's grid; no other patch is touched). The subclouds, which the repair
// never touches and which hold most of a result's memory, are not copied.
#pragma once
#include <cstddef>
#include <cstdint>
#include <vector>

#include "result.hpp"

namespace dbs {

class RepairSnapshot {
 public:
  explicit RepairSnapshot(const Result& result);
  /// Puts `result` (the one the snapshot was taken of, repaired since) back as it was.
  void restore(Result& result) const;

 private:
  struct LeafState {
    std::size_t id;
    BaseSurface surface;
    Grid grid;
    double mean_distance, max_distance, error;
    bool accurate;
  };
  std::vector<double> u_, v_, distance_;
  std::vector<std::int32_t> patch_;
  std::vector<std::int8_t> level_;
  std::vector<char> repaired_;
  std::size_t repaired_points_;
  std::vector<LeafState> leaves_;
  std::size_t patch_count_ = 0;
};

}  // namespace dbs
