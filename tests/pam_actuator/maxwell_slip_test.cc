// maxwell_slip_test.cc: the Maxwell-slip hysteresis model (maxwell_slip.h) against its
// closed forms: the virgin curve sum min(k_i x, F_i), a loop's area 4 F (A - F / k) per
// element, no loss inside the stick band, memory of where it rests, slip forces that grow
// with pressure, and every bad value named by its key.
#include "pam_actuator/maxwell_slip.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "base/input_error.h"

namespace pamsim {
namespace {

constexpr double kStep = 1e-7;   // [m] input increment of the sweeps below

// Drives the model from `from` to `to` in kStep increments at pressure p_pa and returns the
// work done on it, the integral of F dx (trapezoids).
double sweep(MaxwellSlip* model, double from, double to, double p_pa) {
  const int n = static_cast<int>(std::lround(std::fabs(to - from) / kStep));
  double work = 0.0, x_prev = from, f_prev = model->force_n();
  for (int i = 1; i <= n; ++i) {
    const double x = from + (to - from) * i / n;
    const double f = model->update(x, p_pa);
    work += 0.5 * (f + f_prev) * (x - x_prev);
    x_prev = x;
    f_prev = f;
  }
  return work;
}

const std::vector<MaxwellSlipElement> kTwo = {{2.0e4, 3.0, 0.0}, {5.0e3, 1.0, 0.0}};

TEST(MaxwellSlipTest, VirginCurveIsTheSumOfSaturatingSprings) {
  MaxwellSlip model(kTwo);
  model.update(0.0, 0.0);
  for (double x : {1e-5, 1e-4, 1.5e-4, 2e-4, 5e-4, 1e-3}) {
    // x rises monotonically: no element has slipped back, each holds min(k x, F)
    const double expected = std::min(2.0e4 * x, 3.0) + std::min(5.0e3 * x, 1.0);
    EXPECT_NEAR(model.update(x, 0.0), expected, 1e-12) << "x " << x;
  }
  EXPECT_DOUBLE_EQ(model.max_force_n(0.0), 4.0);
}

TEST(MaxwellSlipTest, ALoopEnclosesFourFTimesTheSlipTravelPerElement) {
  const double amplitude = 1e-3;
  MaxwellSlip model(kTwo);
  model.update(0.0, 0.0);
  sweep(&model, 0.0, amplitude, 0.0);   // the virgin branch, then full cycles
  const double loop = sweep(&model, amplitude, -amplitude, 0.0) +
                      sweep(&model, -amplitude, amplitude, 0.0);
  double expected = 0.0;
  for (const MaxwellSlipElement& e : kTwo) {
    expected += 4.0 * e.slip_force_n * (amplitude - e.slip_force_n / e.stiffness_n_per_m);
  }
  EXPECT_NEAR(loop, expected, 1e-6 * expected);
}

TEST(MaxwellSlipTest, AReversalInsideTheStickBandIsElastic) {
  MaxwellSlip model({{2.0e4, 3.0, 0.0}});
  model.update(0.0, 0.0);
  sweep(&model, 0.0, 1e-3, 0.0);   // slipping, at +F
  const double before = model.force_n();
  // back by less than 2 F / k = 0.3 mm and forth again: the spring alone moves
  const double work = sweep(&model, 1e-3, 0.8e-3, 0.0) + sweep(&model, 0.8e-3, 1e-3, 0.0);
  EXPECT_NEAR(work, 0.0, 1e-12);
  EXPECT_DOUBLE_EQ(model.force_n(), before);
  EXPECT_NEAR(model.update(0.9e-3, 0.0), 3.0 - 2.0e4 * 1e-4, 1e-9);
}

TEST(MaxwellSlipTest, ItRemembersWhereInTheLoopItRests) {
  MaxwellSlip rising(kTwo), falling(kTwo);
  for (MaxwellSlip* m : {&rising, &falling}) m->update(0.0, 0.0);
  sweep(&rising, 0.0, 1e-3, 0.0);
  sweep(&falling, 0.0, -1e-3, 0.0);
  // both brought to x = 0 from opposite sides: the full band apart, +-sum F
  sweep(&rising, 1e-3, 0.0, 0.0);
  sweep(&falling, -1e-3, 0.0, 0.0);
  EXPECT_NEAR(rising.force_n(), -4.0, 1e-9);
  EXPECT_NEAR(falling.force_n(), 4.0, 1e-9);
}

TEST(MaxwellSlipTest, SlipForcesGrowWithPressureAndAFallClipsThem) {
  MaxwellSlip model({{2.0e4, 1.0, 4.0e-6}});   // F = 1 N + 4 N/MPa
  model.update(0.0, 0.5e6);
  EXPECT_DOUBLE_EQ(model.max_force_n(0.5e6), 3.0);
  EXPECT_NEAR(model.update(1e-3, 0.5e6), 3.0, 1e-12);
  EXPECT_NEAR(model.update(1e-3, 0.1e6), 1.4, 1e-12);   // the lower limit, at once
  EXPECT_DOUBLE_EQ(model.max_force_n(-1.0e5), 1.0);      // vacuum adds no contact load
}

TEST(MaxwellSlipTest, EveryBadValueNamesItsKey) {
  struct Case { MaxwellSlipElement element; const char* key; };
  const double nan = std::nan("");
  for (const Case& c : {Case{{0.0, 1.0, 0.0}, "stiffness_N_per_mm"},
                        Case{{-1.0, 1.0, 0.0}, "stiffness_N_per_mm"},
                        Case{{nan, 1.0, 0.0}, "stiffness_N_per_mm"},
                        Case{{1.0, -0.1, 0.0}, "slip_force_N"},
                        Case{{1.0, nan, 0.0}, "slip_force_N"},
                        Case{{1.0, 1.0, -1e-9}, "slip_force_N_per_MPa"}}) {
    try {
      validate_maxwell_slip({{1.0, 1.0, 0.0}, c.element}, "friction.");
      ADD_FAILURE() << "no throw for " << c.key;
    } catch (const InputError& e) {
      const std::string what = e.what();
      EXPECT_EQ(what.rfind(std::string("friction.elements[1].") + c.key + " must be ", 0), 0u)
          << what;
    }
  }
  EXPECT_NO_THROW(validate_maxwell_slip(kTwo, "friction."));
}

}  // namespace
}  // namespace pamsim
