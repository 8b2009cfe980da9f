// Progress reporting with cancellation. Fractions reported are made monotone; a callback
// asking to cancel turns into Error(Cancelled), which unwinds the run and frees everything.
#pragma once
#include "options.hpp"

namespace dbs {

class Progress {
 public:
  explicit Progress(ProgressFn fn) : fn_(std::move(fn)) {}
  /// Reports max(fraction, last reported) clamped to [0,1]; throws Error(Cancelled) when the
  /// callback asks to cancel. Must be called on the caller's thread only.
  void report(double fraction, const char* stage);
  /// Reports exactly 1.0 with stage "done".
  void finish() { report(1.0, "done"); }

 private:
  ProgressFn fn_;
  double last_ = 0.0;
};

}  // namespace dbs
