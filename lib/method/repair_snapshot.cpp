#include "repair_snapshot.hpp"

#include "error.hpp"

namespace dbs {

RepairSnapshot::RepairSnapshot(const Result& result)
    : u_(result.u), v_(result.v), distance_(result.distance), patch_(result.patch), level_(result.level), repaired_(result.repaired), repaired_points_(result.repaired_points) {
  patches_.reserve(result.patches.size());
  for (const Patch& p : result.patches) patches_.push_back({p.surface, p.grid, p.mean_distance, p.max_distance, p.error, p.accurate});
}

void RepairSnapshot::restore(Result& result) const {
  if (result.patches.size() != patches_.size() || result.u.size() != u_.size()) fail(ErrorCode::Internal, "RepairSnapshot: restored into another result");
  result.u = u_;
  result.v = v_;
  result.distance = distance_;
  result.patch = patch_;
  result.level = level_;
  result.repaired = repaired_;
  result.repaired_points = repaired_points_;
  for (std::size_t k = 0; k < patches_.size(); ++k) {
    Patch& p = result.patches[k];
    const PatchState& s = patches_[k];
    p.surface = s.surface;
    p.grid = s.grid;
    p.mean_distance = s.mean_distance;
    p.max_distance = s.max_distance;
    p.error = s.error;
    p.accurate = s.accurate;
  }
}

}  // namespace dbs
