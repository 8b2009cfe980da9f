#include "number_text.hpp"

#include <algorithm>
#include <charconv>

namespace dbs {

void append_shortest(std::string& out, double x) {
  char buf[32];
  const auto end = std::to_chars(buf, buf + sizeof buf, x).ptr;
  out.append(buf, end);
}

std::string shortest_text(double x) {
  std::string out;
  append_shortest(out, x);
  return out;
}

std::string significant_text(double x, int digits) {
  char buf[40];
  const auto end = std::to_chars(buf, buf + sizeof buf, x, std::chars_format::general, std::clamp(digits, 1, 17)).ptr;
  std::string s(buf, end);
  for (const char* e : {"e-0", "e+0"}) {
    const std::size_t at = s.find(e);
    if (at != std::string::npos && at + 3 < s.size()) s.erase(at + 2, 1);
  }
  return s;
}

}  // namespace dbs
