#include "firewall.hpp"

#include <new>

#include "error.hpp"

namespace dbs::capi {
namespace {

/// A failure detected by the C layer, carrying its DBS_ERR_* status directly.
class StatusError : public std::runtime_error {
 public:
  StatusError(int status, const std::string& message) : std::runtime_error(message), status_(status) {}
  int status() const noexcept { return status_; }

 private:
  int status_;
};

thread_local std::string last_message_storage;
// Points into last_message_storage, or at a literal when even storing the message failed.
thread_local const char* last_message = "";
// The errno behind the last failure when it was an I/O error, else 0.
thread_local int last_errno = 0;

void record(const char* function, const char* prefix, const char* what) noexcept {
  try {
    last_message_storage.assign(function).append(": ").append(prefix).append(what);
    last_message = last_message_storage.c_str();
  } catch (...) {
    last_message = "libdbs: out of memory while recording an error message";
  }
}

int status_of(ErrorCode code) noexcept {
  switch (code) {
    case ErrorCode::InvalidArgument: return DBS_ERR_INVALID_ARGUMENT;
    case ErrorCode::OutOfRange: return DBS_ERR_OUT_OF_RANGE;
    case ErrorCode::NonFinite: return DBS_ERR_NON_FINITE;
    case ErrorCode::Empty: return DBS_ERR_EMPTY;
    case ErrorCode::Degenerate: return DBS_ERR_DEGENERATE;
    case ErrorCode::Io: return DBS_ERR_IO;
    case ErrorCode::Parse: return DBS_ERR_PARSE;
    case ErrorCode::Unsupported: return DBS_ERR_UNSUPPORTED;
    case ErrorCode::Cancelled: return DBS_ERR_CANCELLED;
    case ErrorCode::Numerical: return DBS_ERR_NUMERICAL;
    case ErrorCode::Internal: return DBS_ERR_INTERNAL;
  }
  return DBS_ERR_INTERNAL;
}

}  // namespace

int status_of_current_exception(const char* function) noexcept {
  last_errno = 0;
  try {
    throw;
  } catch (const StatusError& e) {
    record(function, "", e.what());
    return e.status();
  } catch (const Error& e) {
    record(function, "", e.what());
    if (e.code() == ErrorCode::Io) last_errno = e.system_errno();
    return status_of(e.code());
  } catch (const std::bad_alloc&) {
    record(function, "", "out of memory");
    return DBS_ERR_NO_MEMORY;
  } catch (const std::exception& e) {
    record(function, "internal error: ", e.what());
    return DBS_ERR_INTERNAL;
  } catch (...) {
    record(function, "internal error: ", "an exception of unknown type");
    return DBS_ERR_INTERNAL;
  }
}

const char* last_error_message() noexcept { return last_message; }

int last_error_errno() noexcept { return last_errno; }

void fail_status(int status, const std::string& message) { throw StatusError(status, message); }

void require_capacity(const char* name, std::size_t capacity, std::size_t needed, const char* unit) {
  if (capacity < needed)
    fail_status(DBS_ERR_BUFFER_TOO_SMALL, std::string("buffer '") + name + "' holds " + std::to_string(capacity) + " " + unit + " but " + std::to_string(needed) + " are needed");
}

void require_index(const char* what, long long value, std::size_t count) {
  if (value < 0 || static_cast<unsigned long long>(value) >= count)
    fail_status(DBS_ERR_OUT_OF_RANGE, std::string(what) + " " + std::to_string(value) + " is outside its range [0, " + std::to_string(count) + ")");
}

void require_size_index(const char* what, std::size_t value, std::size_t count) {
  // A size_t index is printed as the unsigned number it is (SIZE_MAX, not -1).
  if (value >= count) fail_status(DBS_ERR_OUT_OF_RANGE, std::string(what) + " " + std::to_string(value) + " is outside its range [0, " + std::to_string(count) + ")");
}

}  // namespace dbs::capi
