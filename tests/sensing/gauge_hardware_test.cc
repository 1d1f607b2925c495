// gauge_hardware_test.cc: the gauge as hardware (gauge_hardware.h) and its static
// calibration: a nominal gauge reads the published Eq. (8) slope and offset, a built one
// reads its own (the arms' offset, calibrated away), a creeping board calibrates to the
// compliance its hold lets it reach (1 + g for a term much faster than the hold), the
// instrument seed fixes the arms, a line re-laid after calibration reads by the lever's
// ratio, and every bad key is named.
#include "sensing/gauge_hardware.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "base/input_error.h"
#include "base/control_step.h"

namespace pamsim {
namespace {

using pamsim_test::kControlDt;

const StrainGaugeParams kPublished{2.25e-3, 0.1};  // Table IV's agonist q, an offset

GaugeHardwareConfig config(double tolerance_pct, double max_n = 50.0) {
  GaugeHardwareConfig c;
  c.enabled = true;
  c.bridge.tolerance_pct = tolerance_pct;
  c.calibration_max_n = max_n;
  return c;
}

TEST(GaugeHardwareTest, ANominalGaugeReadsThePublishedSlopeAndOffset) {
  const GaugeHardwareConfig c = config(0.0, 5.0);
  std::mt19937_64 rng(1);
  GaugeHardware gauge(c, kPublished, rng, kControlDt);
  EXPECT_DOUBLE_EQ(gauge.voltage(0.0), 0.1);
  // 1 N: q plus the bridge's own bend, GF eps / 2 of it (eps ~ 1.1e-4 per N here)
  EXPECT_NEAR(gauge.voltage(1.0) - 0.1, 2.25e-3, 2.25e-3 * 2e-4);
  const StrainGaugeParams fit = calibrate_gauge(gauge, c, kControlDt, "muscles.agonist");
  EXPECT_NEAR(fit.q_v_per_n, 2.25e-3, 2.25e-3 * 1e-3);
  EXPECT_NEAR(fit.v_base_v, 0.1, 1e-5);
}

TEST(GaugeHardwareTest, ABuiltGaugeCalibratesItsOwnOffsetAway) {
  const GaugeHardwareConfig c = config(100.0 * 0.5 / 120.0);
  std::mt19937_64 rng(3);
  GaugeHardware gauge(c, kPublished, rng, kControlDt);
  const StrainGaugeParams fit = calibrate_gauge(gauge, c, kControlDt, "muscles.agonist");
  // the arms' offset, by hand from the drawn arms, amplified
  const BridgeResistors& r = gauge.arms();
  const double zero = gauge.gain() * 5.0 *
                      (r.gauge_ohm / (r.gauge_ohm + r.r3_ohm) - r.r2_ohm / (r.r1_ohm + r.r2_ohm));
  EXPECT_GT(std::fabs(zero), 1e-3);
  EXPECT_NEAR(fit.v_base_v, 0.1 + zero, 5e-3 * std::fabs(zero) + 1e-4);
  // Eq. (8) with the calibrated constants reads this gauge back within its nonlinearity
  for (double f : {5.0, 20.0, 45.0}) {
    EXPECT_NEAR((gauge.voltage(f) - fit.v_base_v) / fit.q_v_per_n, f, 0.1) << f;
  }
}

TEST(GaugeHardwareTest, ACreepingBoardCalibratesToItsCompliance) {
  GaugeHardwareConfig c = config(0.0, 5.0);
  c.creep = {{0.05, 0.1}};  // 5 % more strain, 0.1 s: complete within a 2 s hold
  std::mt19937_64 rng(1);
  const StrainGaugeParams fit = calibrate_gauge(GaugeHardware(c, kPublished, rng, kControlDt), c,
                                                kControlDt, "muscles.agonist");
  EXPECT_NEAR(fit.q_v_per_n / 2.25e-3, 1.05, 2e-3);
  c.calibration_hold_s = 0.0;  // read at once: one tick of creep, 1 - exp(-0.1)
  std::mt19937_64 rng2(1);
  const StrainGaugeParams quick = calibrate_gauge(GaugeHardware(c, kPublished, rng2, kControlDt), c,
                                                  kControlDt, "muscles.agonist");
  EXPECT_LT(quick.q_v_per_n, fit.q_v_per_n);
}

TEST(GaugeHardwareTest, ALineReseatedAfterCalibrationReadsByTheLeversRatio) {
  // calibrated with the line 30 mm beyond the gauge, then laid 3 mm further out: a pull
  // reads 33 / 30 of what the calibration says (the bridge's own curvature aside)
  GaugeHardwareConfig c = config(0.0);
  c.contact.sliding = false;
  c.contact.reseat_m = 0.003;
  std::mt19937_64 rng(1);
  GaugeHardware gauge(c, kPublished, rng, kControlDt);
  const StrainGaugeParams calibrated = calibrate_gauge(gauge, c, kControlDt, "k");
  gauge.reseat();
  const double lever = c.board.contact_position_m - c.board.gauge_position_m;
  const double read = (gauge.voltage(20.0) - calibrated.v_base_v) / calibrated.q_v_per_n;
  EXPECT_NEAR(read / 20.0, (lever + 0.003) / lever, 2e-3);
}

TEST(GaugeHardwareTest, TheInstrumentSeedFixesTheArms) {
  const GaugeHardwareConfig c = config(0.4);
  std::mt19937_64 a(5), b(5), other(6);
  const GaugeHardware ga(c, kPublished, a, kControlDt), gb(c, kPublished, b, kControlDt),
      go(c, kPublished, other, kControlDt);
  EXPECT_EQ(ga.arms().r1_ohm, gb.arms().r1_ohm);
  EXPECT_EQ(ga.arms().gauge_ohm, gb.arms().gauge_ohm);
  EXPECT_NE(ga.arms().r1_ohm, go.arms().r1_ohm);
}

// clang-format off
TEST(GaugeHardwareTest, EveryBadKeyIsNamed) {
  struct Case { const char* key; void (*spoil)(GaugeHardwareConfig&); };
  const Case cases[] = {
      {"sensors.gauge.tolerance_pct", [](GaugeHardwareConfig& c) { c.bridge.tolerance_pct = 120; }},
      {"sensors.gauge.excitation_V", [](GaugeHardwareConfig& c) { c.bridge.excitation_v = 0; }},
      {"sensors.gauge.gauge_factor", [](GaugeHardwareConfig& c) { c.bridge.gauge_factor = -1; }},
      {"sensors.gauge.board.thickness_mm", [](GaugeHardwareConfig& c) { c.board.thickness_m = 0; }},
      {"sensors.gauge.board.creep_weights[0]", [](GaugeHardwareConfig& c) { c.creep = {{-0.1, 1}}; }},
      {"sensors.gauge.board.creep_times_s[0]", [](GaugeHardwareConfig& c) { c.creep = {{0.1, 0}}; }},
      {"sensors.gauge.calibration.max_N", [](GaugeHardwareConfig& c) { c.calibration_max_n = 0; }},
      {"sensors.gauge.calibration.steps", [](GaugeHardwareConfig& c) { c.calibration_steps = 0; }},
      {"sensors.gauge.calibration.hold_s", [](GaugeHardwareConfig& c) { c.calibration_hold_s = -1; }},
      {"sensors.gauge.board.loss_factor", [](GaugeHardwareConfig& c) { c.vibration.loss_factor = 1.0; }},
      {"sensors.gauge.board.loss_factor", [](GaugeHardwareConfig& c) { c.vibration.loss_factor = 0.0; }},
      {"sensors.gauge.board.loss_factor", [](GaugeHardwareConfig& c) { c.vibration.loss_factor = NAN; }},
      {"sensors.gauge.board.density_kg_m3", [](GaugeHardwareConfig& c) { c.vibration.density_kg_m3 = -1; }},
      {"sensors.gauge.board.length_mm", [](GaugeHardwareConfig& c) { c.board.length_m = 0.030; }},
      {"sensors.gauge.board.length_mm", [](GaugeHardwareConfig& c) { c.board.length_m = 1e200; }},
      {"sensors.gauge.board.creep_exponent", [](GaugeHardwareConfig& c) { c.findley.exponent = 0; }},
      {"sensors.gauge.board.creep_exponent", [](GaugeHardwareConfig& c) { c.findley.exponent = 0.8; }},
      {"sensors.gauge.board.creep_1000h", [](GaugeHardwareConfig& c) { c.findley.creep_1000h = -1; }},
      {"sensors.gauge.board.creep_1000h", [](GaugeHardwareConfig& c) {
         c.findley.creep_1000h = 0.6;   // and a Prony series: one law or the other
         c.creep = {{0.1, 1}};
       }},
      // the board ends 5 mm beyond the contact, the gauge 30 mm before it
      {"sensors.gauge.contact.reseat_mm", [](GaugeHardwareConfig& c) { c.contact.reseat_m = 0.006; }},
      {"sensors.gauge.contact.reseat_mm", [](GaugeHardwareConfig& c) { c.contact.reseat_m = -0.031; }},
  };
  for (const Case& k : cases) {
    GaugeHardwareConfig c = config(0.4);
    k.spoil(c);
    try {
      validate(c);
      ADD_FAILURE() << "no throw for " << k.key;
    } catch (const InputError& e) {
      const std::string what = e.what();
      EXPECT_EQ(what.rfind(std::string(k.key) + " must be ", 0), 0u) << what;
    }
  }
  EXPECT_NO_THROW(validate(config(0.4)));
  // a calibration of 2001 loads held an hour each at 100 Hz: refused, naming the hold
  GaugeHardwareConfig endless = config(0.4);
  endless.calibration_steps = 1000;
  endless.calibration_hold_s = 3600.0;
  EXPECT_THROW(validate_calibration_length(endless, 100.0), InputError);
  try {
    validate_calibration_length(endless, 100.0);
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()).rfind("sensors.gauge.calibration.hold_s must be", 0), 0u);
  }
  EXPECT_NO_THROW(validate_calibration_length(config(0.4), 100.0));
}
// clang-format on

}  // namespace
}  // namespace pamsim
