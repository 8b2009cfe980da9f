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

/// The one exception type of the core: a code and a message naming what is wrong, and for
/// an I/O failure the operating system's errno behind it (0 when there is none).
class Error : public std::runtime_error {
 public:
  Error(ErrorCode code, const std::string& message, int system_errno = 0) : std::runtime_error(message), code_(code), system_errno_(system_errno) {}
  ErrorCode code() const noexcept { return code_; }
  int system_errno() const noexcept { return system_errno_; }

 private:
  ErrorCode code_;
  int system_errno_;
};

[[noreturn]] inline void fail(ErrorCode code, const std::string& message) { throw Error(code, message); }
/// An I/O failure with the errno that caused it (so a binding can tell a missing file from a
/// refused one).
[[noreturn]] inline void fail_io(const std::string& message, int system_errno) { throw Error(ErrorCode::Io, message, system_errno); }

}  // namespace dbs
