// maxwell_slip_test.cc: the Maxwell-slip hysteresis model (maxwell_slip.h) against its
// closed forms: the virgin curve F_up sum w_i min(x / delta_i, 1), a loop's width
// F_up + F_down and area 2 (F_up + F_down) sum w_i (A - delta_i), no loss inside the stick
// band, memory of where it rests, slip forces that follow the load at once, and every bad
// value named by its key.
#include "pam_actuator/maxwell_slip.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <string>

#include "base/input_error.h"

namespace pamsim {
namespace {

constexpr double kStep = 1e-7;  // [m] input increment of the sweeps below

MaxwellSlipParams two_elements() {
  MaxwellSlipParams p;
  p.count = 2;
  p.weight = {0.75, 0.25};
  p.breakaway_m = {1.5e-4, 2.0e-4};
  return p;
}

struct Slip {
  MaxwellSlipParams params = two_elements();
  std::array<double, kMaxSlipElements> state{};
  double x = 0.0;
  double up = 4.0, down = 4.0;  // [N]

  double force() const { return maxwell_slip_force(params, state.data(), up, down); }
  // Drives the input to `to` in kStep increments; returns the work done on it (trapezoids).
  double sweep(double to) {
    const int n = static_cast<int>(std::lround(std::fabs(to - x) / kStep));
    const double from = x;
    double work = 0.0, f_prev = force();
    for (int i = 1; i <= n; ++i) {
      const double next = from + (to - from) * i / n;
      maxwell_slip_advance(params, next - x, state.data());
      work += 0.5 * (force() + f_prev) * (next - x);
      x = next;
      f_prev = force();
    }
    return work;
  }
};

TEST(MaxwellSlipTest, VirginCurveIsTheSumOfSaturatingSprings) {
  Slip s;
  for (double x : {1e-5, 1e-4, 1.5e-4, 1.8e-4, 5e-4, 1e-3}) {
    s.sweep(x);
    const double expected =
        4.0 * (0.75 * std::min(x / 1.5e-4, 1.0) + 0.25 * std::min(x / 2.0e-4, 1.0));
    EXPECT_NEAR(s.force(), expected, 1e-9) << "x " << x;
  }
  EXPECT_NEAR(s.force(), 4.0, 1e-12) << "fully slipping: the whole slip force";
}

TEST(MaxwellSlipTest, ALoopHasItsAnalyticWidthAndArea) {
  // asymmetric slip forces, as braid friction has while lengthening and while shortening
  const double amplitude = 1e-3;
  Slip s;
  s.up = 5.0;
  s.down = 3.0;
  s.sweep(amplitude);  // the virgin branch, then one full cycle
  const double falling_half = s.sweep(0.0);
  const double falling_at_zero = s.force();
  const double middle = s.sweep(-amplitude) + s.sweep(0.0);
  const double rising_at_zero = s.force();
  const double area = falling_half + middle + s.sweep(amplitude);
  EXPECT_NEAR(rising_at_zero - falling_at_zero, 5.0 + 3.0, 1e-9) << "width F_up + F_down";
  const double expected = 2.0 * 8.0 * (0.75 * (amplitude - 1.5e-4) + 0.25 * (amplitude - 2.0e-4));
  EXPECT_NEAR(area, expected, 1e-6 * expected);
}

TEST(MaxwellSlipTest, AReversalInsideTheStickBandIsElastic) {
  Slip s;
  s.params.count = 1;
  s.params.weight = {1.0};
  s.params.breakaway_m = {1.5e-4};
  s.sweep(1e-3);  // slipping, at +F
  const double before = s.force();
  // back by less than 2 delta = 0.3 mm and forth again: the spring alone moves
  const double work = s.sweep(0.8e-3) + s.sweep(1e-3);
  EXPECT_NEAR(work, 0.0, 1e-12);
  EXPECT_DOUBLE_EQ(s.force(), before);
  s.sweep(0.9e-3);
  EXPECT_NEAR(s.force(), 4.0 * (1.0 - 1e-4 / 1.5e-4), 1e-9);
}

TEST(MaxwellSlipTest, ItRemembersWhereInTheLoopItRests) {
  Slip rising, falling;
  rising.sweep(1e-3);
  falling.sweep(-1e-3);
  // both brought to x = 0 from opposite sides: the full band apart
  rising.sweep(0.0);
  falling.sweep(0.0);
  EXPECT_NEAR(rising.force(), -4.0, 1e-9);
  EXPECT_NEAR(falling.force(), 4.0, 1e-9);
}

TEST(MaxwellSlipTest, TheHeldForceFollowsTheSlipForceAtOnce) {
  Slip s;
  s.sweep(1e-3);
  EXPECT_NEAR(s.force(), 4.0, 1e-12);
  s.up = 1.4;  // the pressure falls: the contact load, and the force held, with it
  EXPECT_NEAR(s.force(), 1.4, 1e-12);
  s.up = 6.0;  // and rises: a stuck element holds its share of the new limit
  EXPECT_NEAR(s.force(), 6.0, 1e-12);
}

TEST(MaxwellSlipTest, EveryBadValueNamesItsKey) {
  const double nan = std::nan("");
  struct Case {
    int count;
    double weight1, breakaway1;
    const char* key;
  };
  for (const Case& c :
       {Case{0, 0.25, 2e-4, "breakaway_mm"}, Case{5, 0.25, 2e-4, "breakaway_mm"},
        Case{2, 0.25, 0.0, "breakaway_mm[1]"}, Case{2, 0.25, -1e-4, "breakaway_mm[1]"},
        Case{2, 0.25, nan, "breakaway_mm[1]"}, Case{2, 0.0, 2e-4, "weights[1]"},
        Case{2, nan, 2e-4, "weights[1]"}, Case{2, 0.2, 2e-4, "weights"}}) {
    MaxwellSlipParams p = two_elements();
    p.count = c.count;
    p.weight[1] = c.weight1;
    p.breakaway_m[1] = c.breakaway1;
    try {
      validate_maxwell_slip(p, "friction.");
      ADD_FAILURE() << "no throw for " << c.key;
    } catch (const InputError& e) {
      const std::string what = e.what();
      EXPECT_EQ(what.rfind(std::string("friction.") + c.key + " must be ", 0), 0u) << what;
    }
  }
  EXPECT_NO_THROW(validate_maxwell_slip(two_elements(), "friction."));
}

}  // namespace
}  // namespace pamsim
