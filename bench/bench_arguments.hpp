// Command-line helpers shared by the benchmark programs (dbs-bench, dbs-bench-folds).
#pragma once
#include <cstdlib>
#include <string>

namespace bench {

/// The value of `option` as an integer in [0, 1000]; `usage_error` (which does not return)
/// is called with a message naming the option and the text otherwise.
template <class UsageError>
int parse_small_int(const std::string& option, const std::string& text, UsageError usage_error) {
  char* end = nullptr;
  const long value = std::strtol(text.c_str(), &end, 10);
  if (end == text.c_str() || *end != '\0' || value < 0 || value > 1000) usage_error(option + ": '" + text + "' is not a small non-negative integer");
  return static_cast<int>(value);
}

/// The value of `option` as a number that `accept` takes; otherwise `usage_error` is called
/// with a message naming the option, the text and `what` it should be ("a number in (0, 1000]").
template <class Accept, class UsageError>
double parse_number(const std::string& option, const std::string& text, Accept accept, const char* what, UsageError usage_error) {
  char* end = nullptr;
  const double value = std::strtod(text.c_str(), &end);
  if (end == text.c_str() || *end != '\0' || !accept(value)) usage_error(option + ": '" + text + "' is not " + what);
  return value;
}

}  // namespace bench
