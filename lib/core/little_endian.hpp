// Little-endian bytes of the binary files libdbs writes (PLY), whatever the host's byte
// order.
#pragma once
#include <cstdint>
#include <cstring>
#include <string>

namespace dbs {

inline void append_le32(std::string& out, std::uint32_t bits) {
  for (int k = 0; k < 4; ++k) out += static_cast<char>((bits >> (8 * k)) & 0xff);
}

inline void append_le64(std::string& out, std::uint64_t bits) {
  for (int k = 0; k < 8; ++k) out += static_cast<char>((bits >> (8 * k)) & 0xff);
}

/// The double's 8 bytes as they are (IEEE 754 binary64): a PLY `double` reads back bit for bit.
inline void append_le_double(std::string& out, double x) {
  std::uint64_t bits;
  std::memcpy(&bits, &x, 8);
  append_le64(out, bits);
}

}  // namespace dbs
