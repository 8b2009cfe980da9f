#include "repair_snapshot.hpp"

#include "error.hpp"

namespace dbs {

RepairSnapshot::RepairSnapshot(const Result& result)
    : u_(result.u), v_(result.v), distance_(result.distance), patch_(result.patch), level_(result.level), repaired_(result.repaired), repaired_points_(result.repaired_points) {
  // Only leaves: the repair refits and judges no other patch.
  for (std::size_t k = 0; k < result.patches.size(); ++k) {
    const Patch& p = result.patches[k];
    if (p.is_leaf()) leaves_.push_back({k, p.surface, p.grid, p.mean_distance, p.max_distance, p.error, p.accurate});
  }
  patch_count_ = result.patches.size();
}

void RepairSnapshot::restore(Result& result) const {
  if (result.patches.size() != patch_count_ || result.u.size() != u_.size()) fail(ErrorCode::Internal, "RepairSnapshot: restored into another result");
  result.u = u_;
  result.v = v_;
  result.distance = distance_;
  result.patch = patch_;
  result.level = level_;
  result.repaired = repaired_;
  result.repaired_points = repaired_points_;
  for (const LeafState& s : leaves_) {
    Patch& p = result.patches[s.id];
    p.surface = s.surface;
    p.grid = s.grid;
    p.mean_distance = s.mean_distance;
    p.max_distance = s.max_distance;
    p.error = s.error;
    p.accurate = s.accurate;
  }
}

}  // namespace dbs
