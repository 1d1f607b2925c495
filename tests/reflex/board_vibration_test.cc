// board_vibration_test.cc: the gauge board's first bending mode (board_vibration.h) against
// closed forms: its frequency is Euler-Bernoulli's for a clamped-free strip, its step
// response the damped oscillator's, a held pull keeps it at rest, and a gauge on a ringing
// board reads the bend of that moment, not the pull.
#include "reflex/board_vibration.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "reflex/gauge_hardware.h"

namespace pamsim {
namespace {

constexpr double kPi = 3.14159265358979323846;

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

// A pull stepped from 0 to 1 N: F_b(t) = 1 - e^(-sigma t) (cos wd t + sigma / wd sin wd t),
// exactly at every step (the input is held over each), whatever the step's size.
TEST(BoardVibrationTest, StepResponseIsTheDampedOscillators) {
  const double f = 841.0, zeta = 0.015;
  for (double dt : {1e-3, 1e-4}) {
    BoardVibration board(f, zeta, dt);
    board.step(0.0);   // at rest, unloaded
    const double w = 2.0 * kPi * f, sigma = zeta * w, wd = w * std::sqrt(1.0 - zeta * zeta);
    double worst = 0.0, peak = 0.0;
    for (int k = 1; k <= 200; ++k) {
      board.step(1.0);
      const double t = k * dt;
      const double exact =
          1.0 - std::exp(-sigma * t) * (std::cos(wd * t) + sigma / wd * std::sin(wd * t));
      worst = std::max(worst, std::fabs(board.equivalent_force_n() - exact));
      peak = std::max(peak, board.equivalent_force_n());
    }
    EXPECT_LT(worst, 1e-12) << dt;
    if (dt < 1e-3) {
      EXPECT_GT(peak, 1.9) << "a lightly damped step overshoots nearly 100 %";
    }
  }
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
  for (int k = 0; k < 500; ++k) ringing.observe(30.0);   // 0.5 s: 40 decay times
  EXPECT_NEAR(ringing.voltage(30.0), still.voltage(30.0), 1e-9);
  // switched off, the gauge reads the pull as before
  c.vibration.enabled = false;
  GaugeHardware off(c, published, rng, 0.01);
  off.enable_vibration(1e-3);
  EXPECT_FALSE(off.vibrates());
}

}  // namespace
}  // namespace pamsim
