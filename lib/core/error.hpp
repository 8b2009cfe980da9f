// Errors raised by the core. The C layer turns each ErrorCode into a DBS_ERR_* status;
// the core itself knows nothing of the C API.
#pragma once
#include <stdexcept>
#include <string>

namespace dbs {

enum class ErrorCode {
  InvalidArgument,
  OutOfRange,
  NonFinite,
  Empty,
  Degenerate,
  Io,
  Parse,
  Unsupported,
  Cancelled,
  Numerical,
  Internal,
};

/// The one exception type of the core: a code and a message naming what is wrong.
class Error : public std::runtime_error {
 public:
  Error(ErrorCode code, const std::string& message) : std::runtime_error(message), code_(code) {}
  ErrorCode code() const noexcept { return code_; }

 private:
  ErrorCode code_;
};

[[noreturn]] inline void fail(ErrorCode code, const std::string& message) { throw Error(code, message); }

}  // namespace dbs
