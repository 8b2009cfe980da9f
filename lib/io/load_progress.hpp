// Progress of loading a cloud file, with cancellation: the bytes read from the disk (stage
// "read", fractions 0 to 0.5), then the bytes parsed ("parse", 0.5 to 1), or a .drc file
// before and after Draco decodes it ("decode"), then 1 ("done"). A stage reports when it
// begins and then whenever another `step` bytes are done, so a big file reports every few MB
// and a small one only at its stage ends. A callback asking to cancel throws
// Error(Cancelled) (dbs::Progress).
#pragma once
#include <cstdint>
#include <optional>

#include "progress.hpp"

namespace dbs {

class LoadProgress {
 public:
  static constexpr std::uint64_t kStep = std::uint64_t{4} << 20;  // 4 MiB

  /// Reports nothing (dbs_cloud_load).
  LoadProgress() = default;
  explicit LoadProgress(ProgressFn fn, std::uint64_t step = kStep);

  /// A stage of `total` bytes covering fractions [from, to]; reports `from`.
  void begin(const char* stage, double from, double to, std::uint64_t total);
  /// `done` bytes of the stage are done.
  void at(std::uint64_t done) {
    if (progress_ && done >= next_) report(done);
  }
  /// Reports 1 ("done").
  void finish();

 private:
  void report(std::uint64_t done);

  std::optional<Progress> progress_;
  std::uint64_t step_ = kStep;
  const char* stage_ = "";
  double from_ = 0.0, to_ = 0.0;
  std::uint64_t total_ = 0, next_ = 0;
};

}  // namespace dbs
