// Reading and writing one float or double at a byte offset of a buffer's contents (the bytes the
// harnesses hand to the runner and read back). Out-of-range accesses write nothing and read 0:
// planned sizes make them unreachable.
#pragma once

#include <cstdint>
#include <cstring>
#include <vector>

namespace doublet::verify {

inline uint32_t scalar_width(bool is_double) { return is_double ? 8 : 4; }

// An int/uint/bool value (scalar 'i', 'u', 'b') is stored as its 32-bit integer.
inline void write_value(std::vector<uint8_t>& bytes, size_t at, bool is_double, double v, char scalar = 'f') {
  if (at + scalar_width(is_double) > bytes.size()) return;
  if (is_double) {
    std::memcpy(bytes.data() + at, &v, 8);
  } else if (scalar == 'i') {
    const auto i = static_cast<int32_t>(v);
    std::memcpy(bytes.data() + at, &i, 4);
  } else if (scalar == 'u' || scalar == 'b') {
    const auto u = scalar == 'b' ? uint32_t{v != 0} : static_cast<uint32_t>(v);
    std::memcpy(bytes.data() + at, &u, 4);
  } else {
    const auto f = static_cast<float>(v);
    std::memcpy(bytes.data() + at, &f, 4);
  }
}

inline double read_value(const std::vector<uint8_t>& bytes, size_t at, bool is_double) {
  if (at + scalar_width(is_double) > bytes.size()) return 0;
  if (is_double) {
    double d;
    std::memcpy(&d, bytes.data() + at, 8);
    return d;
  }
  float f;
  std::memcpy(&f, bytes.data() + at, 4);
  return f;
}

}  // namespace doublet::verify
