// board_vibration.cc: see board_vibration.h.
#include "sensing/board_vibration.h"

#include <cmath>
#include <stdexcept>

namespace pamsim {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kLambda1 = 1.8751040687119611;  // first root of 1 + cos x cosh x = 0

}  // namespace

double board_first_mode_hz(const GaugeBoardParams& board, const BoardVibrationParams& v) {
  const double length = board_free_length_m(board);
  const double area = board.width_m * board.thickness_m;
  const double second_moment = board.width_m * std::pow(board.thickness_m, 3) / 12.0;
  return kLambda1 * kLambda1 / (2.0 * kPi * length * length) *
         std::sqrt(board.youngs_modulus_pa * second_moment / (v.density_kg_m3 * area));
}

BoardVibration::BoardVibration(double natural_hz, double damping_ratio, double dt_s) : dt_s_(dt_s) {
  if (!(natural_hz > 0.0 && std::isfinite(natural_hz) && damping_ratio > 0.0 &&
        damping_ratio < 1.0 && dt_s > 0.0)) {
    throw std::invalid_argument("BoardVibration: needs a finite f > 0, 0 < zeta < 1, dt > 0");
  }
  // the damped oscillator's free response over dt, about the held pull's equilibrium
  const double w = 2.0 * kPi * natural_hz;
  const double sigma = damping_ratio * w;
  const double wd = w * std::sqrt(1.0 - damping_ratio * damping_ratio);
  const double decay = std::exp(-sigma * dt_s);
  const double c = std::cos(wd * dt_s), s = std::sin(wd * dt_s);
  p11_ = decay * (c + sigma * s / wd);
  p12_ = decay * s / wd;
  p21_ = -decay * w * w * s / wd;
  p22_ = decay * (c - sigma * s / wd);
  lag_s_ = 2.0 * damping_ratio / w;
}

void BoardVibration::step(double f_n) {
  if (!started_) {
    force_n_ = input_n_ = f_n;
    rate_n_s_ = 0.0;
    started_ = true;
  }
  // the input u = u0 + k t over the step: particular solution u - lag k, free response about it
  const double k = (f_n - input_n_) / dt_s_;
  const double e = force_n_ - (input_n_ - lag_s_ * k), de = rate_n_s_ - k;
  force_n_ = f_n - lag_s_ * k + p11_ * e + p12_ * de;
  rate_n_s_ = k + p21_ * e + p22_ * de;
  input_n_ = f_n;
}

}  // namespace pamsim
