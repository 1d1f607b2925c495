// board_vibration_test.cc: the gauge board's first bending mode (board_vibration.h) against
// closed forms: its frequency is Euler-Bernoulli's for a clamped-free strip, its step
// response the damped oscillator's, a held pull keeps it at rest, and a gauge on a ringing
// board reads the bend of that moment, not the pull.
#include "sensing/board_vibration.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "sensing/gauge_hardware.h"
#include "base/units.h"

namespace pamsim {
namespace {

using units::kPi;

// f1 = 1.8751^2 / (2 pi L^2) sqrt(E t^2 / (12 rho)) for a strip (I / A = t^2 / 12), by hand:
// the default board, 3.3 GPa, 1190 kg/m^3, 5 mm thick, free end 45 mm: 664.2 Hz
TEST(BoardVibrationTest, FirstModeIsEulerBernoullisClampedFreeBeam) {
  const GaugeHardwareConfig c;
  const double by_hand = 1.8751040687 * 1.8751040687 / (2.0 * kPi * 0.045 * 0.045) *
                         std::sqrt(3.3e9 * 0.005 * 0.005 / (12.0 * 1190.0));
  EXPECT_NEAR(board_first_mode_hz(c.board, c.vibration), by_hand, 1e-6 * by_hand);
  EXPECT_NEAR(by_hand, 664.2, 0.1);
  // twice as long, a quarter of the frequency; twice as thick, twice
  GaugeBoardParams longer = c.board, thicker = c.board;
  longer.length_m *= 2.0;
  thicker.thickness_m *= 2.0;
  EXPECT_NEAR(board_first_mode_hz(longer, c.vibration), by_hand / 4.0, 1e-6 * by_hand);
  EXPECT_NEAR(board_first_mode_hz(thicker, c.vibration), by_hand * 2.0, 1e-6 * by_hand);
}

// A pull ramped from 0 to 1 N over the first step, then held (the input the first-order hold
// sees): F_b(t) = (R(t) - R(t - dt)) / dt with R the unit ramp's response,
//   R(t) = t - 2 zeta / w + e^(-sigma t) (2 zeta / w cos wd t + (2 zeta^2 - 1) / wd sin wd t),
// exactly at every step, whatever the step's size.
TEST(BoardVibrationTest, RampResponseIsTheDampedOscillators) {
  const double f = 664.0, zeta = 0.015;
  const double w = 2.0 * kPi * f, sigma = zeta * w, wd = w * std::sqrt(1.0 - zeta * zeta);
  const auto ramp = [&](double t) {
    if (t <= 0.0) return 0.0;
    return t - 2.0 * zeta / w +
           std::exp(-sigma * t) * (2.0 * zeta / w * std::cos(wd * t) +
                                   (2.0 * zeta * zeta - 1.0) / wd * std::sin(wd * t));
  };
  for (double dt : {1e-3, 1e-4}) {
    BoardVibration board(f, zeta, dt);
    board.step(0.0);  // at rest, unloaded
    double worst = 0.0, peak = 0.0;
    for (int k = 1; k <= 200; ++k) {
      board.step(1.0);
      const double t = k * dt;
      const double exact = (ramp(t) - ramp(t - dt)) / dt;
      worst = std::max(worst, std::fabs(board.equivalent_force_n() - exact));
      peak = std::max(peak, board.equivalent_force_n());
    }
    EXPECT_LT(worst, 1e-12) << dt;
    if (dt < 1e-3) {
      EXPECT_GT(peak, 1.9) << "a lightly damped, nearly sharp step overshoots nearly 100 %";
    }
  }
}

// A continuous pull sampled at 1 ms or at 0.1 ms rings the board alike: the first-order
// hold's error is second order in the step (a held staircase would ring the 664 Hz mode by
// itself, at 1 ms by tens of percent).
TEST(BoardVibrationTest, TheRingingHardlyDependsOnTheStep) {
  const double f = 664.0, zeta = 0.015;
  // a pull rising by 20 N over 4 ms (the impact's contact time) from 18 N
  const auto pull = [](double t) {
    return t < 0.0 ? 18.0 : 18.0 + 20.0 * std::min(t / 0.004, 1.0);
  };
  BoardVibration coarse(f, zeta, 1e-3), fine(f, zeta, 1e-4);
  coarse.step(pull(-1e-3));
  fine.step(pull(-1e-4));
  double worst = 0.0, ringing = 0.0;
  for (int k = 0; k <= 30; ++k) {
    coarse.step(pull(k * 1e-3));
    for (int j = 1; j <= 10; ++j) fine.step(pull((k - 1) * 1e-3 + j * 1e-4));
    worst = std::max(worst, std::fabs(coarse.equivalent_force_n() - fine.equivalent_force_n()));
    ringing = std::max(ringing, std::fabs(fine.equivalent_force_n() - pull(k * 1e-3)));
  }
  EXPECT_GT(ringing, 1.0);          // the sharp rise does ring the board
  EXPECT_LT(worst, 0.1 * ringing);  // and both steps see the same ringing
}

TEST(BoardVibrationTest, AHeldPullKeepsTheBoardAtRest) {
  BoardVibration board(841.0, 0.015, 1e-3);
  for (int k = 0; k < 50; ++k) board.step(37.5);
  EXPECT_DOUBLE_EQ(board.equivalent_force_n(), 37.5);
}

// The gauge reads the ringing board: right after a sharp pull it reads the bend the
// oscillator gives, not the pull, and once the ringing has died, the static reading.
TEST(BoardVibrationTest, AGaugeOnARingingBoardReadsItsBend) {
  GaugeHardwareConfig c;
  c.enabled = true;
  c.bridge.tolerance_pct = 0.0;
  const StrainGaugeParams published{2.25e-3, 0.1};
  std::mt19937_64 rng(1);
  GaugeHardware still(c, published, rng, 0.01), ringing = still;
  ringing.enable_vibration(1e-3);
  ASSERT_TRUE(ringing.vibrates());
  BoardVibration twin(board_first_mode_hz(c.board, c.vibration), c.vibration.loss_factor / 2.0,
                      1e-3);
  ringing.observe(0.0);
  twin.step(0.0);
  ringing.observe(30.0);
  twin.step(30.0);
  const double bent = twin.equivalent_force_n();
  EXPECT_GT(std::fabs(bent - 30.0), 1.0);
  EXPECT_NEAR(ringing.voltage(30.0), still.voltage(bent), 1e-12);
  for (int k = 0; k < 500; ++k) ringing.observe(30.0);  // 0.5 s: 40 decay times
  EXPECT_NEAR(ringing.voltage(30.0), still.voltage(30.0), 1e-9);
  // switched off, the gauge reads the pull as before
  c.vibration.enabled = false;
  GaugeHardware off(c, published, rng, 0.01);
  off.enable_vibration(1e-3);
  EXPECT_FALSE(off.vibrates());
}

}  // namespace
}  // namespace pamsim
