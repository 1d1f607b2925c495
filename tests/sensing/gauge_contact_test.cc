// gauge_contact_test.cc: where the line bears on the gauge's board (gauge_contact.h) against
// closed forms: the resting point is the line's shortest path over the edge, the contact
// sticks within the friction's play and then follows at its edge, a frictionless line leaves
// the board at the shortening geometry predicts, a slack line and a fixed contact stay put,
// a misalignment solved for an observed loss loses the line there, a gauge reads the pull
// times the lever of the moment and nothing once the line is off, and every bad key is named.
#include "sensing/gauge_contact.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "base/input_error.h"
#include "sensing/gauge_hardware.h"

namespace pamsim {
namespace {

constexpr double kL0 = 0.150;  // the muscle's start length [m]

GaugeBoardParams default_board() {
  return GaugeHardwareConfig{}.board;
}  // contact 40, free end 45 mm

// the path fitting -> edge point y -> shaft, unfolded: its length as a function of y
double path_length(const GaugeContactParams& c, double y_p, double l1, double y) {
  return std::hypot(l1, y - y_p) + std::hypot(c.shaft_distance_m, y_p + c.misalignment_m - y);
}

TEST(GaugeContactTest, TheRestingPointIsTheShortestPath) {
  GaugeContactParams c;
  c.misalignment_m = 0.050;
  const double y0 = 0.040, s = 0.012, l1 = c.fitting_distance_m + s;
  const double y_p =
      y0 - c.misalignment_m * c.fitting_distance_m / (c.fitting_distance_m + c.shaft_distance_m);
  // golden-section search for the shortest path's crossing
  double a = y_p - 0.1, b = y_p + 0.2;
  const double g = (std::sqrt(5.0) - 1.0) / 2.0;
  for (int k = 0; k < 200; ++k) {
    const double x1 = b - g * (b - a), x2 = a + g * (b - a);
    if (path_length(c, y_p, l1, x1) < path_length(c, y_p, l1, x2)) {
      b = x2;
    } else {
      a = x1;
    }
  }
  const double y = contact_rest_position_m(c, y0, s);
  EXPECT_NEAR(y, 0.5 * (a + b), 1e-7);  // a minimum's flatness limits the search
  // exactly: the path's slope in y is zero there (equal angles on both sides of the edge)
  const double h = 1e-7;
  EXPECT_NEAR(path_length(c, y_p, l1, y + h) - path_length(c, y_p, l1, y - h), 0.0, 1e-15);
  EXPECT_DOUBLE_EQ(contact_rest_position_m(c, y0, 0.0), y0);  // at the start, the contact
}

// w = 2 mu sin(theta / 2) / (1/L1 + 1/L2); the contact stays until y* has moved w, then
// follows it at w behind.
TEST(GaugeContactTest, TheContactSticksWithinThePlayThenFollowsAtItsEdge) {
  GaugeContactParams c;
  c.misalignment_m = 0.300;
  const double w0 = 2.0 * 0.3 * std::sin(15.0 * M_PI / 180.0) / (1.0 / 0.020 + 1.0 / 0.250);
  EXPECT_NEAR(contact_stick_band_m(c, 0.0), w0, 1e-15);
  GaugeContact contact(c, default_board());
  contact.follow(kL0, 10.0);
  for (double s = 0.0; s <= 0.006; s += 1e-4) {
    contact.follow(kL0 - s, 10.0);
    const double rest = contact_rest_position_m(c, 0.040, s), w = contact_stick_band_m(c, s);
    if (rest - 0.040 <= w) {
      EXPECT_DOUBLE_EQ(contact.position_m(), 0.040) << s;
    } else {
      EXPECT_NEAR(contact.position_m(), rest - w, 1e-15) << s;
    }
  }
  EXPECT_GT(contact.position_m(), 0.040);  // it did slide
}

// Without friction the contact is y*; it leaves the 45 mm board where y*(s) = 45 mm:
// (d1 + s) / (d1 + s + d2) = r, r = (L_b - y0) / D + d1 / (d1 + d2), s = r d2 / (1 - r) - d1.
TEST(GaugeContactTest, AFrictionlessLineLeavesTheBoardWhereGeometryPredicts) {
  GaugeContactParams c;
  c.misalignment_m = 0.200;
  c.friction_coefficient = 0.0;
  const double r = (0.045 - 0.040) / 0.200 + 0.020 / 0.270;
  const double s_loss = r * 0.250 / (1.0 - r) - 0.020;
  EXPECT_GT(s_loss, 0.005);
  GaugeContact before(c, default_board()), after(c, default_board());
  before.follow(kL0, 10.0);
  after.follow(kL0, 10.0);
  before.follow(kL0 - (s_loss - 1e-6), 10.0);
  after.follow(kL0 - (s_loss + 1e-6), 10.0);
  EXPECT_FALSE(before.lost());
  EXPECT_TRUE(after.lost());
  after.follow(kL0, 10.0);  // gone for good
  EXPECT_TRUE(after.lost());
}

// The calibration to an observed loss: the least misalignment that loses a steadily
// shortening line by s, found by bisection on the contact itself, is the closed form; and a
// contact given lost_at_shortening_mm loses its line there, re-seated or not.
TEST(GaugeContactTest, ASolvedMisalignmentLosesTheLineAtTheGivenShortening) {
  const GaugeContactParams shipped;  // margin 5 mm to the free end, w about 2.9 mm
  const double s_loss = 0.012;
  auto lost_by = [&](GaugeContactParams c, double shift_m, double s_end) {
    GaugeContact g(c, default_board());
    g.reseat(shift_m);
    for (int i = 0; i <= 2000; ++i) g.follow(kL0 - s_end * i / 2000.0, 10.0);
    return g.lost();
  };
  double lo = 0.0, hi = 10.0;
  for (int k = 0; k < 60; ++k) {
    GaugeContactParams c = shipped;
    c.misalignment_m = 0.5 * (lo + hi);
    (lost_by(c, 0.0, s_loss) ? hi : lo) = c.misalignment_m;
  }
  EXPECT_NEAR(lo, misalignment_for_loss_m(shipped, 0.005, s_loss), 1e-9);
  for (double shift : {0.0, 0.002, -0.002}) {
    GaugeContactParams c = shipped;
    c.lost_at_shortening_m = s_loss;
    EXPECT_FALSE(lost_by(c, shift, 0.999 * s_loss)) << shift;
    EXPECT_TRUE(lost_by(c, shift, 1.001 * s_loss)) << shift;
  }
}

TEST(GaugeContactTest, ASlackLineAndAFixedContactStayPut) {
  GaugeContactParams c;
  c.misalignment_m = 0.300;
  c.friction_coefficient = 0.0;
  GaugeContact slack(c, default_board());
  slack.follow(kL0, 0.0);
  slack.follow(kL0 - 0.010, 0.0);
  EXPECT_DOUBLE_EQ(slack.position_m(), 0.040);
  c.sliding = false;
  GaugeContact fixed(c, default_board());
  fixed.follow(kL0, 10.0);
  fixed.follow(kL0 - 0.010, 10.0);
  EXPECT_DOUBLE_EQ(fixed.position_m(), 0.040);
}

// The reading follows the pull times the lever y - y_g: a shift of the contact reads as a
// change of force; a line off the board reads the bridge's zero.
TEST(GaugeContactTest, TheGaugeReadsThePullTimesTheLeverOfTheMoment) {
  GaugeHardwareConfig h;
  h.enabled = true;
  h.bridge.tolerance_pct = 0.0;
  h.contact.misalignment_m = 0.200;
  h.contact.friction_coefficient = 0.0;
  std::mt19937_64 rng(1);
  GaugeHardware still(h, StrainGaugeParams{2.25e-3, 0.1}, rng, 0.01), moved = still;
  moved.follow(kL0, 20.0);
  moved.follow(kL0 - 0.004, 20.0);
  const double y = contact_rest_position_m(h.contact, 0.040, 0.004);
  ASSERT_GT(y, 0.040);
  const double lever_ratio = (y - 0.010) / (0.040 - 0.010);
  // small strains: the bridge is linear to 1e-4 here
  EXPECT_NEAR((moved.voltage(20.0) - 0.1) / (still.voltage(20.0) - 0.1), lever_ratio, 1e-3);
  moved.follow(kL0 - 0.030, 20.0);
  ASSERT_TRUE(moved.contact_lost());
  EXPECT_NEAR(moved.voltage(20.0), still.voltage(0.0), 1e-12);
}

TEST(GaugeContactTest, EveryBadKeyIsNamed) {
  struct Case {
    const char* key;
    void (*spoil)(GaugeContactParams&);
  };
  const Case cases[] = {
      {"sensors.gauge.contact.misalignment_mm",
       [](GaugeContactParams& c) { c.misalignment_m = NAN; }},
      {"sensors.gauge.contact.fitting_distance_mm",
       [](GaugeContactParams& c) { c.fitting_distance_m = 0; }},
      {"sensors.gauge.contact.fitting_distance_mm",
       [](GaugeContactParams& c) { c.fitting_distance_m = 0.5e-3; }},
      {"sensors.gauge.contact.shaft_distance_mm",
       [](GaugeContactParams& c) { c.shaft_distance_m = -1; }},
      {"sensors.gauge.contact.wrap_deg", [](GaugeContactParams& c) { c.wrap_deg = 180; }},
      {"sensors.gauge.contact.wrap_deg", [](GaugeContactParams& c) { c.wrap_deg = 0; }},
      {"sensors.gauge.contact.friction_coefficient",
       [](GaugeContactParams& c) { c.friction_coefficient = -0.1; }},
      {"sensors.gauge.contact.lost_at_shortening_mm",
       [](GaugeContactParams& c) { c.lost_at_shortening_m = -0.001; }},
      {"sensors.gauge.contact.lost_at_shortening_mm",
       [](GaugeContactParams& c) {
         c.sliding = false;
         c.lost_at_shortening_m = 0.010;
       }},
  };
  for (const Case& k : cases) {
    GaugeHardwareConfig gauge;  // the contact's keys are the gauge's rows
    k.spoil(gauge.contact);
    try {
      validate(gauge);
      ADD_FAILURE() << "no throw for " << k.key;
    } catch (const InputError& e) {
      EXPECT_EQ(std::string(e.what()).rfind(std::string(k.key) + " must be ", 0), 0u) << e.what();
    }
  }
  // a board that ends before its contact
  GaugeHardwareConfig h;
  h.enabled = true;
  h.board.length_m = 0.030;
  try {
    validate(h);
    ADD_FAILURE() << "no throw for length_mm";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()).rfind("sensors.gauge.board.length_mm must be ", 0), 0u);
  }
}

}  // namespace
}  // namespace pamsim
