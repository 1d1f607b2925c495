// portable_random.h: random draws that are the same bits with any standard library (the
// std::*_distribution classes are implementation-defined, std::mt19937_64 is not): a
// uniform double in [0, 1) from the top 53 bits of one draw (exact), and a standard normal by
// Box-Muller on two of them. For what must be reproducible wherever pamsim runs: a sweep's
// random and Latin-hypercube points, its [[randomize]] draws, an instrument's resistors.
#pragma once

#include <cmath>
#include <random>

namespace pamsim {

inline double unit_uniform(std::mt19937_64& rng) {
  return static_cast<double>(rng() >> 11) * 0x1.0p-53;
}

inline double portable_standard_normal(std::mt19937_64& rng) {
  const double u1 = unit_uniform(rng), u2 = unit_uniform(rng);
  return std::sqrt(-2.0 * std::log1p(-u1)) * std::cos(2.0 * M_PI * u2);
}

}  // namespace pamsim
