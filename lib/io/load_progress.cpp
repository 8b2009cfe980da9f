#include "load_progress.hpp"

#include <algorithm>

namespace dbs {

LoadProgress::LoadProgress(ProgressFn fn, std::uint64_t step) : step_(std::max<std::uint64_t>(step, 1)) {
  if (fn) progress_.emplace(std::move(fn));
}

void LoadProgress::begin(const char* stage, double from, double to, std::uint64_t total) {
  stage_ = stage;
  from_ = from;
  to_ = to;
  total_ = total;
  next_ = step_;
  if (progress_) progress_->report(from_, stage_);
}

void LoadProgress::report(std::uint64_t done) {
  const double share = total_ > 0 ? static_cast<double>(std::min(done, total_)) / static_cast<double>(total_) : 1.0;
  progress_->report(from_ + share * (to_ - from_), stage_);
  next_ = done + step_;
}

void LoadProgress::finish() {
  if (progress_) progress_->finish();
}

}  // namespace dbs
