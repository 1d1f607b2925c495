// quarter_bridge_test.cc: the quarter Wheatstone bridge (quarter_bridge.h) against its
// formula worked by hand: four equal arms give G V_ex GF eps / (4 + 2 GF eps), unequal arms
// an offset at zero strain, drawn arms stay within their tolerance and repeat with the seed,
// and every bad value names its key.
#include "sensing/quarter_bridge.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "base/input_error.h"
#include "sensing/gauge_hardware.h"

namespace pamsim {
namespace {

TEST(QuarterBridgeTest, EqualArmsGiveTheTextbookQuarterBridge) {
  QuarterBridgeParams p;
  p.amplifier_gain = 100.0;
  const BridgeResistors arms = nominal_bridge(p);
  EXPECT_DOUBLE_EQ(quarter_bridge_output_v(p, arms, 0.0), 0.0);
  for (double strain : {-2e-3, -1e-4, 1e-6, 5e-4, 2e-3}) {
    const double gf_eps = 2.0 * strain;
    EXPECT_NEAR(quarter_bridge_output_v(p, arms, strain),
                100.0 * 5.0 * gf_eps / (4.0 + 2.0 * gf_eps), 1e-12)
        << strain;
  }
  // small strains: the familiar V_ex GF eps / 4, bending below it (by GF eps / 2) as it grows
  const double small = quarter_bridge_output_v(p, arms, 1e-6);
  EXPECT_NEAR(small, 100.0 * 5.0 * 2.0 * 1e-6 / 4.0, 1e-9);
  EXPECT_LT(quarter_bridge_output_v(p, arms, 2e-3), 100.0 * 5.0 * 2.0 * 2e-3 / 4.0);
}

TEST(QuarterBridgeTest, UnequalArmsReadAnOffsetAtZeroStrain) {
  QuarterBridgeParams p;
  const BridgeResistors arms{120.5, 119.5, 120.0, 120.25};
  // by hand: 120.25 / 240.25 - 119.5 / 240
  const double by_hand = 5.0 * (120.25 / 240.25 - 119.5 / 240.0);
  // ~13 mV: as large as ~5 mm/m of strain would read (V_ex GF / 4 = 2.5 V per unit strain)
  EXPECT_NEAR(quarter_bridge_output_v(p, arms, 0.0), by_hand, 1e-15);
}

TEST(QuarterBridgeTest, DrawnArmsStayInTheirToleranceAndRepeatWithTheSeed) {
  QuarterBridgeParams p;  // 120 +- 0.5 Ohm
  std::mt19937_64 a(7), b(7), c(8);
  double widest = 0.0;
  for (int i = 0; i < 1000; ++i) {
    const BridgeResistors r = draw_bridge(p, a);
    for (double ohm : {r.r1_ohm, r.r2_ohm, r.r3_ohm, r.gauge_ohm}) {
      EXPECT_LE(std::fabs(ohm - 120.0), 0.5 + 1e-12);
      widest = std::max(widest, std::fabs(ohm - 120.0));
    }
    const BridgeResistors again = draw_bridge(p, b);
    EXPECT_EQ(r.r1_ohm, again.r1_ohm);
    EXPECT_EQ(r.gauge_ohm, again.gauge_ohm);
  }
  EXPECT_GT(widest, 0.49);  // the draws fill the band
  EXPECT_NE(draw_bridge(p, c).r1_ohm, draw_bridge(p, a).r1_ohm);
  p.tolerance_pct = 0.0;
  const BridgeResistors exact = draw_bridge(p, a);
  EXPECT_EQ(exact.r3_ohm, 120.0);
}

TEST(QuarterBridgeTest, EveryBadValueNamesItsKey) {
  struct Case {
    const char* key;
    double QuarterBridgeParams::*field;
    double value;
  };
  const double nan = std::nan("");
  for (const Case& c : {Case{"excitation_V", &QuarterBridgeParams::excitation_v, 0.0},
                        Case{"gauge_factor", &QuarterBridgeParams::gauge_factor, -2.0},
                        Case{"nominal_Ohm", &QuarterBridgeParams::nominal_ohm, nan},
                        Case{"tolerance_pct", &QuarterBridgeParams::tolerance_pct, 100.0},
                        Case{"tolerance_pct", &QuarterBridgeParams::tolerance_pct, 150.0},
                        Case{"tolerance_pct", &QuarterBridgeParams::tolerance_pct, -0.1}}) {
    GaugeHardwareConfig gauge;  // the bridge's keys are the gauge's rows
    gauge.bridge.*c.field = c.value;
    try {
      validate(gauge);
      ADD_FAILURE() << "no throw for " << c.key << " = " << c.value;
    } catch (const InputError& e) {
      const std::string what = e.what();
      EXPECT_EQ(what.rfind(std::string("sensors.gauge.") + c.key + " must be ", 0), 0u) << what;
    }
  }
  EXPECT_NO_THROW(validate(GaugeHardwareConfig{}));
}

}  // namespace
}  // namespace pamsim
