// The wall between the C API and the C++ core. Every C function runs its body through
// guarded(), which turns every exception into the documented status and records the message,
// prefixed with the function's name, as this thread's last error. Arguments are checked inside
// the body with the require_* helpers, so their failures take the same path.
#pragma once
#include <cstddef>
#include <string>

#include "handles.hpp"

namespace dbs::capi {

/// Records the exception in flight as this thread's last error and returns its status.
/// Call only from inside a catch block.
int status_of_current_exception(const char* function) noexcept;

/// Runs body(); returns DBS_OK, or the status of whatever it threw. Nothing escapes.
template <class Body>
int guarded(const char* function, Body&& body) noexcept {
  try {
    body();
    return DBS_OK;
  } catch (...) {
    return status_of_current_exception(function);
  }
}

/// This thread's last error message ("" before the first failure).
const char* last_error_message() noexcept;
/// The errno recorded with the last failure on this thread (I/O failures only), else 0.
int last_error_errno() noexcept;

/// A failure of the C layer itself: a status dbs::ErrorCode has no equivalent for.
[[noreturn]] void fail_status(int status, const std::string& message);

/// DBS_ERR_NULL_ARGUMENT naming `name` when `pointer` is NULL.
inline void require_non_null(const void* pointer, const char* name) {
  if (pointer == nullptr) fail_status(DBS_ERR_NULL_ARGUMENT, std::string("argument '") + name + "' is NULL");
}

/// DBS_ERR_BUFFER_TOO_SMALL when a caller's buffer `name` of `capacity` units cannot hold
/// `needed` of them (`unit`: "points", "pairs", "values").
void require_capacity(const char* name, std::size_t capacity, std::size_t needed, const char* unit);

/// DBS_ERR_OUT_OF_RANGE unless 0 <= value < count; the message names `what` and the range.
void require_index(const char* what, long long value, std::size_t count);
/// The same for a size_t index (printed unsigned).
void require_size_index(const char* what, std::size_t value, std::size_t count);

}  // namespace dbs::capi
