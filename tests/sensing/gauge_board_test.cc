// gauge_board_test.cc: the gauge's acrylic board (gauge_board.h) against beam theory worked
// by hand: the surface strain of a cantilever 6 F lever / (E w t^2), its change when the
// line's contact point shifts, no bending from a slack line, and every bad value by its key.
#include "sensing/gauge_board.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "base/input_error.h"
#include "sensing/gauge_hardware.h"

namespace pamsim {
namespace {

GaugeBoardParams strip_board() {
  GaugeBoardParams b;  // a 20 x 2 mm acrylic strip, gauge 10 mm from the clamp
  b.width_m = 0.020;
  b.thickness_m = 0.002;
  b.gauge_position_m = 0.010;
  b.contact_position_m = 0.040;
  return b;
}

TEST(GaugeBoardTest, StrainIsTheCantileverSurfaceStrain) {
  const GaugeBoardParams b = strip_board();
  // by hand: M = 10 N x 30 mm = 0.3 N m; I = w t^3 / 12 = 1.333e-11 m^4; c = 1 mm;
  // eps = M c / (E I) = 0.3 x 0.001 / (3.3e9 x 1.333e-11) = 6.818e-3
  const double i_m4 = 0.020 * std::pow(0.002, 3) / 12.0;
  EXPECT_NEAR(gauge_board_strain(b, 10.0, b.contact_position_m), 0.3 * 0.001 / (3.3e9 * i_m4),
              1e-15);
  EXPECT_NEAR(gauge_board_strain(b, 10.0, b.contact_position_m), 6.818e-3, 1e-6);
  // linear in the force
  EXPECT_NEAR(gauge_board_strain(b, 2.5, 0.040), gauge_board_strain(b, 10.0, 0.040) / 4.0, 1e-18);
}

TEST(GaugeBoardTest, AContactShiftReadsAsAForceChange) {
  const GaugeBoardParams b = strip_board();
  // a 1 mm shift along a 30 mm lever: 1/30 of the reading, as 1/30 more force would give
  const double at = gauge_board_strain(b, 10.0, 0.040);
  const double shifted = gauge_board_strain(b, 10.0, 0.041);
  EXPECT_NEAR(shifted / at, 31.0 / 30.0, 1e-12);
  EXPECT_NEAR(shifted, gauge_board_strain(b, 10.0 * 31.0 / 30.0, 0.040), 1e-15);
}

TEST(GaugeBoardTest, ASlackLineOrAContactAtTheGaugeBendsNothingThere) {
  const GaugeBoardParams b = strip_board();
  EXPECT_EQ(gauge_board_strain(b, 0.0, 0.040), 0.0);
  EXPECT_EQ(gauge_board_strain(b, -3.0, 0.040), 0.0);
  EXPECT_EQ(gauge_board_strain(b, 10.0, 0.010), 0.0);
  EXPECT_EQ(gauge_board_strain(b, 10.0, 0.005), 0.0);  // inside the gauge: no moment there
}

TEST(GaugeBoardTest, EveryBadValueNamesItsKey) {
  struct Case {
    const char* key;
    double GaugeBoardParams::*field;
    double value;
  };
  for (const Case& c : {Case{"youngs_modulus_MPa", &GaugeBoardParams::youngs_modulus_pa, 0.0},
                        Case{"width_mm", &GaugeBoardParams::width_m, -0.01},
                        Case{"thickness_mm", &GaugeBoardParams::thickness_m, 0.0},
                        Case{"thickness_mm", &GaugeBoardParams::thickness_m, std::nan("")},
                        Case{"gauge_position_mm", &GaugeBoardParams::gauge_position_m, -0.001},
                        Case{"contact_position_mm", &GaugeBoardParams::contact_position_m, 0.01}}) {
    GaugeHardwareConfig gauge;  // each key's row, then what joins them
    gauge.board.*c.field = c.value;
    try {
      validate(gauge);
      ADD_FAILURE() << "no throw for " << c.key;
    } catch (const InputError& e) {
      const std::string what = e.what();
      EXPECT_EQ(what.rfind(std::string("sensors.gauge.board.") + c.key + " must be ", 0), 0u)
          << what;
    }
  }
  EXPECT_NO_THROW(validate_gauge_board(strip_board(), "gauge.board."));
}

}  // namespace
}  // namespace pamsim
