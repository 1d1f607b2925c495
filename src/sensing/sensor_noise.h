// sensor_noise.h: the noise primitives every sensor model draws on, in the parameter set
// simulators share for a sensor's errors (Gazebo's noise model, sdformat <noise> /
// ros_gz_interfaces/msg/SensorNoise: mean and stddev of white noise, a bias drawn once per
// instrument from bias_mean and bias_stddev, a dynamic bias driven with its stddev and
// correlation time, and a precision the output is rounded to):
//  - standard_normal: one N(0, 1) draw;
//  - derived_generator: an independent std::mt19937_64 for one source of one instrument,
//    seeded from a seed (the trial's, or sensors.instrument_seed) and the source's tags, so a
//    new error source never moves the random stream of the existing noise;
//  - quantise: rounding to a step (the ADC, an encoder's count, Gazebo's precision);
//  - GaussMarkov: the dynamic bias, a first-order Gauss-Markov process.
#pragma once

#include <cstdint>
#include <random>

namespace pamsim {

// One standard normal draw (the single noise primitive of all sensors).
double standard_normal(std::mt19937_64& rng);

// The generator of source `stream` of instrument `index`, from `seed`: a std::seed_seq of the
// seed's two 32-bit halves and the two tags. Different tags give unrelated streams.
std::mt19937_64 derived_generator(std::uint64_t seed, std::uint32_t stream, std::uint32_t index);

// x rounded to the nearest multiple of step: round(x / step) step; step = 0 returns x.
double quantise(double x, double step);

// A first-order Gauss-Markov process b with stationary standard deviation sigma and
// correlation time tau, db = -b / tau dt + sigma sqrt(2 / tau) dW, sampled every dt with its
// exact discretisation (no Euler error at any dt / tau):
//   b_{k+1} = phi b_k + sigma sqrt(1 - phi^2) w_k,   phi = exp(-dt / tau),  w_k ~ N(0, 1),
// started from its stationary law, b_0 ~ N(0, sigma^2). So E[b_k^2] = sigma^2 at every k and
// E[b_k b_{k+n}] = sigma^2 phi^n = sigma^2 exp(-n dt / tau).
// Gazebo's dynamic_bias_stddev is the driving noise's density sigma_b (stationary SD
// sigma_b sqrt(tau / 2)); here sigma is the stationary SD itself, the figure a datasheet's
// drift gives. Every step draws one normal, sigma = 0 included.
class GaussMarkov {
 public:
  // sigma >= 0, tau > 0, dt > 0 (asserted; the keys are checked by their validate()).
  // Draws b_0 from `rng`.
  GaussMarkov(double sigma, double tau_s, double dt_s, std::mt19937_64& rng);
  double value() const { return b_; }
  // Advance one dt; returns the new value.
  double step(std::mt19937_64& rng);
  double phi() const { return phi_; }

 private:
  double phi_ = 0.0;
  double drive_ = 0.0;  // sigma sqrt(1 - phi^2)
  double b_ = 0.0;
};

}  // namespace pamsim
