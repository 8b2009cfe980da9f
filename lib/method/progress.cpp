#include "progress.hpp"

#include <algorithm>

#include "error.hpp"

namespace dbs {

void Progress::report(double fraction, const char* stage) {
  if (!(fraction >= last_)) fraction = last_;  // also catches NaN
  fraction = std::min(fraction, 1.0);
  last_ = fraction;
  if (fn_ && fn_(fraction, stage)) fail(ErrorCode::Cancelled, std::string("cancelled by the progress callback during \"") + stage + "\"");
}

}  // namespace dbs
