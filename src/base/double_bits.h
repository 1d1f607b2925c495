// double_bits.h: a double's bits as an integer, for comparing or hashing doubles exactly
// (-0 apart from 0, every NaN payload apart), as the trial model's identity and the tests'
// digests do.
#pragma once

#include <cstdint>
#include <cstring>

namespace pamsim {

inline std::uint64_t double_bits(double v) {
  std::uint64_t bits = 0;
  std::memcpy(&bits, &v, sizeof(bits));
  return bits;
}

}  // namespace pamsim
