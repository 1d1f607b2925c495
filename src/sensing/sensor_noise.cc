// sensor_noise.cc: see sensor_noise.h.
#include "sensing/sensor_noise.h"

#include <cassert>
#include <cmath>

namespace pamsim {

double standard_normal(std::mt19937_64& rng) {
  // a fresh distribution per draw: no cached second value carried between sensors
  std::normal_distribution<double> normal(0.0, 1.0);
  return normal(rng);
}

std::mt19937_64 derived_generator(std::uint64_t seed, std::uint32_t stream, std::uint32_t index) {
  std::seed_seq seq{static_cast<std::uint32_t>(seed & 0xffffffffu),
                    static_cast<std::uint32_t>(seed >> 32), stream, index};
  return std::mt19937_64(seq);
}

double quantise(double x, double step) {
  if (step == 0.0) return x;
  return std::round(x / step) * step;
}

GaussMarkov::GaussMarkov(double sigma, double tau_s, double dt_s, std::mt19937_64& rng)
    : phi_(std::exp(-dt_s / tau_s)) {
  assert(sigma >= 0.0 && tau_s > 0.0 && dt_s > 0.0);
  // 1 - phi^2 = -expm1(-2 dt / tau), exact for dt << tau
  drive_ = sigma * std::sqrt(-std::expm1(-2.0 * dt_s / tau_s));
  b_ = sigma * standard_normal(rng);
}

double GaussMarkov::step(std::mt19937_64& rng) {
  b_ = phi_ * b_ + drive_ * standard_normal(rng);
  return b_;
}

}  // namespace pamsim
