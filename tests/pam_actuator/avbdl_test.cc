// avbdl_test.cc: the AVBDL plant law of Pipan et al. (avbdl.h): Chou-Hannaford as its special
// case, volume and force by virtual work, the bladder's Mooney-Rivlin work, the friction
// loop; its bad values are plant_keys_test.cc's.
#include "pam_actuator/avbdl.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <string>
#include <vector>

#include "base/input_error.h"
#include "base/no_value.h"
#include "base/units.h"

namespace pamsim {
namespace {

constexpr double kBar = units::kPaPerBar;

// neither bladder loss nor end regions: the model should be Chou-Hannaford's cylinder
AvbdlParams losses_and_ends_off(AvbdlParams p) {
  p.wall_thickness_m = 0.0;
  p.end_length_m = 0.0;
  return p;
}

// Table I agonist geometry (180 mm, 16 mm) with a silicone bladder
AvbdlParams arm_pam() {
  return avbdl_params_from_geometry(0.180, 0.016, units::deg_to_rad(25.0), 0.002,
                                    kSiliconeElastosilM4601);
}

AvbdlParams with_friction(AvbdlParams p) {
  p.friction.extension = {2.0, 4e-5, 1e-4};
  p.friction.contraction = {1.0, 2e-5, 5e-5};
  return p;
}

double central_difference(const std::function<double(double)>& f, double x, double h) {
  return (f(x + h) - f(x - h)) / (2.0 * h);
}

TEST(AvbdlTest, LossesAndEndsOffIsChouHannaford) {
  AvbdlParams steep;
  steep.braid_angle_rad = units::deg_to_rad(35.0);
  for (const AvbdlParams& base : {AvbdlParams{}, arm_pam(), steep}) {
    const AvbdlParams p = losses_and_ends_off(base);
    const BraidGeometry g = braid_from_initial_shape(p.length_m, p.diameter_m, p.braid_angle_rad);
    for (double p_bar : {0.5, 1.0, 3.0, 6.0}) {
      for (double ratio : {0.72, 0.8, 0.9, 1.0, 1.05}) {
        const double l = ratio * p.length_m;
        const double f_ch = chou_hannaford_force(g, p_bar * kBar, l);
        EXPECT_NEAR(avbdl_static_force(p, p_bar * kBar, l), f_ch, 1e-9 * std::abs(f_ch))
            << "p " << p_bar << " bar, L/L0 " << ratio;
        EXPECT_NEAR(avbdl_force(p, p_bar * kBar, l, 0.05), f_ch, 1e-9 * std::abs(f_ch));
        const double v_ch = chou_hannaford_volume(g, l);
        EXPECT_NEAR(avbdl_volume(p, l), v_ch, 1e-12 * v_ch);
      }
    }
  }
}

TEST(AvbdlTest, EndProfileJoinsTheFittingAndTheStraightPart) {
  for (double a : {0.0, 2.0, 3.0}) {
    AvbdlParams p;
    p.end_slope = a;
    const double l = 0.85 * p.length_m;
    const double r0 = 0.5 * p.diameter_m;
    const double r = avbdl_middle_radius(p, l);
    ASSERT_GT(r, r0);  // contracted: the middle is wider than the fitting
    EXPECT_NEAR(avbdl_end_radius(p, 0.0, l), r0, 1e-15);
    EXPECT_NEAR(avbdl_end_radius(p, p.end_length_m, l), r, 1e-15);
    // tangent to the straight part, and monotone in between
    const double h = 1e-7;
    const double slope_end =
        (avbdl_end_radius(p, p.end_length_m, l) - avbdl_end_radius(p, p.end_length_m - h, l)) / h;
    EXPECT_NEAR(slope_end, 0.0, 1e-5);
    for (int i = 1; i <= 100; ++i) {
      const double x0 = (i - 1) * p.end_length_m / 100, x1 = i * p.end_length_m / 100;
      EXPECT_GE(avbdl_end_radius(p, x1, l), avbdl_end_radius(p, x0, l));
    }
  }
}

TEST(AvbdlTest, VolumeIsTheRestCylinderAndGrowsAsTheMuscleShortens) {
  const AvbdlParams p;
  const double r0 = 0.5 * p.diameter_m;
  // at rest the profile is flat: the cylinder, with or without end regions
  EXPECT_NEAR(avbdl_volume(p, p.length_m), units::kPi * r0 * r0 * p.length_m,
              1e-12 * units::kPi * r0 * r0 * p.length_m);
  // shortening from L0 to 25 % contraction (the DMSP-20's rated stroke) inflates it
  double previous = avbdl_volume(p, p.length_m);
  for (int i = 1; i <= 50; ++i) {
    const double l = p.length_m * (1.0 - 0.25 * i / 50);
    const double v = avbdl_volume(p, l);
    EXPECT_GT(v, previous) << "L " << l;
    previous = v;
  }
  // narrow ends hold less gas than Chou's cylinder, the more so the longer they are
  AvbdlParams long_ends = p;
  long_ends.end_length_m = 0.050;
  for (double ratio : {0.8, 0.9, 0.95}) {
    const double l = ratio * p.length_m;
    const double v_cylinder = avbdl_volume(losses_and_ends_off(p), l);
    EXPECT_GT(avbdl_volume(p, l), 0.0);
    EXPECT_LT(avbdl_volume(p, l), v_cylinder);
    EXPECT_LT(avbdl_volume(long_ends, l), avbdl_volume(p, l));
  }
}

TEST(AvbdlTest, ForceIsMinusPressureTimesVolumeSlopeWithoutLosses) {
  for (double a : {0.0, 2.0, 3.0}) {
    AvbdlParams p;
    p.wall_thickness_m = 0.0;
    p.end_slope = a;
    const auto volume = [&](double l) { return avbdl_volume(p, l); };
    for (double ratio : {0.7, 0.8, 0.9, 1.0, 1.05}) {
      const double l = ratio * p.length_m;
      const double dv = central_difference(volume, l, 1e-6);
      EXPECT_NEAR(avbdl_dvolume_dlength(p, l), dv, 1e-7 * std::abs(dv));
      const double f = -4 * kBar * dv;
      EXPECT_NEAR(avbdl_static_force(p, 4 * kBar, l), f, 1e-7 * std::abs(f));
    }
  }
}

TEST(AvbdlTest, MooneyRivlinStressIsTheSlopeOfItsWork) {
  for (const MooneyRivlinConstants& c : {kNaturalRubberTreloar, kSiliconeElastosilM4601}) {
    EXPECT_EQ(mooney_rivlin_stress(c, 1.0), 0.0);
    EXPECT_EQ(mooney_rivlin_energy_density(c, 1.0), 0.0);
    const auto w = [&](double l) { return mooney_rivlin_energy_density(c, l); };
    for (double stretch : {0.7, 1.3, 2.0, 2.4}) {
      const double dw = central_difference(w, stretch, 1e-6);
      EXPECT_NEAR(mooney_rivlin_stress(c, stretch), dw, 1e-6 * std::abs(dw));
      EXPECT_GT(w(stretch), 0.0);  // stored work either way from the rest state
    }
  }
  // neo-Hookean limit by hand: sigma = 2 C10 (lambda - 1/lambda^2)
  const MooneyRivlinConstants neo{1e5, 0.0, 0.0};
  EXPECT_NEAR(mooney_rivlin_stress(neo, 2.0), 2e5 * (2.0 - 0.25), 1e-9);
}

TEST(AvbdlTest, BladderWorkSlopeAndForceMatchFiniteDifferences) {
  for (const AvbdlParams& p : {AvbdlParams{}, arm_pam()}) {
    EXPECT_NEAR(avbdl_bladder_energy(p, p.length_m), 0.0, 1e-15);
    const auto energy = [&](double l) { return avbdl_bladder_energy(p, l); };
    const auto volume = [&](double l) { return avbdl_volume(p, l); };
    for (double ratio : {0.75, 0.85, 0.95, 1.03}) {
      const double l = ratio * p.length_m;
      const double dw = central_difference(energy, l, 1e-6);
      EXPECT_NEAR(avbdl_dbladder_energy_dlength(p, l), dw, 1e-6 * std::abs(dw));
      const double f = -3 * kBar * central_difference(volume, l, 1e-6) + dw;
      EXPECT_NEAR(avbdl_static_force(p, 3 * kBar, l), f, 1e-6 * std::abs(f));
    }
  }
}

TEST(AvbdlTest, BladderWorkIsTheSliceSumOfEq24) {
  const AvbdlParams p;
  const double l = 0.82 * p.length_m;
  const double r0 = 0.5 * p.diameter_m;
  const double t = p.wall_thickness_m;
  const double area = units::kPi * t * (2 * r0 + t);  // annulus, per unit length
  // middle: reference volume of the straight part times W_def(R / R0)
  double w = area * (p.length_m - 2 * p.end_length_m) *
             mooney_rivlin_energy_density(p.bladder, avbdl_middle_radius(p, l) / r0);
  // ends: 20000 slices each, midpoint rule, as the paper sums over x
  const int n = 20000;
  const double dx = p.end_length_m / n;
  for (int i = 0; i < n; ++i) {
    const double r = avbdl_end_radius(p, (i + 0.5) * dx, l);
    w += 2 * area * dx * mooney_rivlin_energy_density(p.bladder, r / r0);
  }
  EXPECT_NEAR(avbdl_bladder_energy(p, l), w, 1e-8 * w);
}

TEST(AvbdlTest, BladderLossLowersThePullAndGrowsWithWallThickness) {
  AvbdlParams thin, thick, none;
  thin.wall_thickness_m = 0.001;
  thick.wall_thickness_m = 0.003;
  none.wall_thickness_m = 0.0;
  for (double p_bar : {1.0, 3.0, 6.0}) {
    for (double ratio : {0.8, 0.9, 0.95}) {
      const double l = ratio * none.length_m;
      const double f_none = avbdl_static_force(none, p_bar * kBar, l);
      const double loss_thin = f_none - avbdl_static_force(thin, p_bar * kBar, l);
      const double loss_thick = f_none - avbdl_static_force(thick, p_bar * kBar, l);
      EXPECT_GT(loss_thin, 0.0) << "p " << p_bar << " bar, L/L0 " << ratio;
      EXPECT_GT(loss_thick, loss_thin) << "p " << p_bar << " bar, L/L0 " << ratio;
    }
  }
  // at rest the bladder is unstrained and takes nothing
  EXPECT_NEAR(avbdl_static_force(thick, 3 * kBar, thick.length_m),
              avbdl_static_force(none, 3 * kBar, none.length_m), 1e-9);
}

TEST(AvbdlTest, Dmsp20PullsLessThanChouAsThePaperMeasured) {
  // Pipan et al., Fig. 11: Chou's model overestimates the DMSP-20 at every p and contraction
  const AvbdlParams p;
  const BraidGeometry g = avbdl_braid(p);
  for (double p_bar : {2.0, 4.0, 6.0}) {
    for (double dl_mm : {5.0, 10.0, 20.0, 30.0}) {
      const double l = p.length_m - units::mm_to_m(dl_mm);
      EXPECT_LT(avbdl_static_force(p, p_bar * kBar, l), chou_hannaford_force(g, p_bar * kBar, l));
    }
  }
}

TEST(AvbdlTest, FrictionOpposesMotionAndGrowsWithPressureAndStrain) {
  const AvbdlParams p = with_friction(AvbdlParams{});
  const double l = 0.9 * p.length_m;
  // continuous through rest, signed against the motion
  EXPECT_EQ(avbdl_smooth_friction_force(p, 4 * kBar, l, 0.0), 0.0);
  EXPECT_GT(avbdl_smooth_friction_force(p, 4 * kBar, l, 0.01), 0.0);
  EXPECT_LT(avbdl_smooth_friction_force(p, 4 * kBar, l, -0.01), 0.0);
  EXPECT_LT(std::abs(avbdl_smooth_friction_force(p, 4 * kBar, l, 1e-9)), 1e-4);
  // saturated, the smooth form is the direction form
  for (StretchDirection d : {StretchDirection::kExtension, StretchDirection::kContraction}) {
    const double v = d == StretchDirection::kExtension ? 0.1 : -0.1;
    EXPECT_NEAR(avbdl_smooth_friction_force(p, 4 * kBar, l, v),
                avbdl_friction_force(p, 4 * kBar, l, d), 1e-9);
  }
  // F0 + p (A0 + A1 eps) by hand for lengthening at eps = 0.1
  EXPECT_NEAR(avbdl_friction_magnitude(p, 4 * kBar, l, StretchDirection::kExtension),
              2.0 + 4e5 * (4e-5 + 1e-4 * 0.1), 1e-9);
  const auto mag = [&](double p_pa, double length_m) {
    return avbdl_friction_magnitude(p, p_pa, length_m, StretchDirection::kContraction);
  };
  EXPECT_GT(mag(5 * kBar, l), mag(2 * kBar, l));
  EXPECT_GT(mag(4 * kBar, 0.8 * p.length_m), mag(4 * kBar, 0.9 * p.length_m));
  EXPECT_EQ(mag(-0.2 * kBar, l), 1.0);  // below ambient only F0 remains
}

// the closed work integral of F dL over a lengthen-then-shorten cycle at fixed p
double loop_work(const AvbdlParams& p, double p_pa, double l_short, double l_long) {
  const int n = 2000;
  const double speed = 0.02;  // 20 mm/s, 20 v_s: friction saturated
  const double dl = (l_long - l_short) / n;
  double work = 0.0;
  for (int i = 0; i < n; ++i) {  // lengthening
    const double l0 = l_short + i * dl, l1 = l0 + dl;
    work += 0.5 * (avbdl_force(p, p_pa, l0, speed) + avbdl_force(p, p_pa, l1, speed)) * dl;
  }
  for (int i = 0; i < n; ++i) {  // shortening back along the same points
    const double l0 = l_long - i * dl, l1 = l0 - dl;
    work -= 0.5 * (avbdl_force(p, p_pa, l0, -speed) + avbdl_force(p, p_pa, l1, -speed)) * dl;
  }
  return work;
}

TEST(AvbdlTest, HysteresisLoopEnclosesWorkOnlyWithFriction) {
  const AvbdlParams plain;
  const AvbdlParams rough = with_friction(plain);
  const double l_short = 0.85 * plain.length_m, l_long = 0.95 * plain.length_m;
  const double p_pa = 3 * kBar;

  // friction off: the static force is conservative, the loop closes on itself
  const double stroke_work =
      std::abs(avbdl_bladder_energy(plain, l_long) - avbdl_bladder_energy(plain, l_short)) +
      p_pa * std::abs(avbdl_volume(plain, l_long) - avbdl_volume(plain, l_short));
  EXPECT_NEAR(loop_work(plain, p_pa, l_short, l_long), 0.0, 1e-12 * stroke_work);

  // friction on: pulls harder lengthening than shortening, and the loop's area is the
  // integral of F_f,ext + F_f,con: (F0e + F0c) dL + p (A0e + A0c) dL + p (A1e + A1c) int eps
  EXPECT_GT(avbdl_force(rough, p_pa, 0.9 * rough.length_m, 0.02),
            avbdl_force(rough, p_pa, 0.9 * rough.length_m, -0.02));
  const double span = l_long - l_short;
  const double eps_integral =
      (rough.length_m * span - 0.5 * (l_long * l_long - l_short * l_short)) / rough.length_m;
  const double expected = 3.0 * span + p_pa * 6e-5 * span + p_pa * 1.5e-4 * eps_integral;
  const double area = loop_work(rough, p_pa, l_short, l_long);
  EXPECT_GT(area, 0.0);
  EXPECT_NEAR(area, expected, 1e-6 * expected);
}

TEST(AvbdlTest, DefaultsPresetsAndScaledGeometryValidate) {
  EXPECT_NO_THROW(validate_avbdl_params(AvbdlParams{}, "plant."));
  AvbdlParams silicone;
  silicone.bladder = kSiliconeElastosilM4601;
  EXPECT_NO_THROW(validate_avbdl_params(silicone, ""));
  EXPECT_NO_THROW(validate_avbdl_params(with_friction(AvbdlParams{}), ""));
  EXPECT_NO_THROW(validate_avbdl_params(losses_and_ends_off(AvbdlParams{}), ""));
  // Eq. (27)-(29) scaling: the DMSP-20's 32 mm of 200 mm
  const AvbdlParams arm = arm_pam();
  EXPECT_NEAR(arm.end_length_m, 0.180 * 0.16, 1e-15);
  EXPECT_THROW(avbdl_params_from_geometry(0.18, -0.016, 0.4, 0.002, kNaturalRubberTreloar),
               InputError);
}

// A slack muscle's free length tracked over a trial's pressures: each agrees with
// the search over the whole stroke to the solvers' tolerance, whether the pressure crept (a
// step's change) or jumped, for the law's bladder and for a tube (whose low pressures put
// the root past L0); the same pressure again answers the same length; a taut muscle is its
// line's length and leaves the track alone; after no pressure (NaN) the track starts over
void expect_tracked_as_whole(const AvbdlParams& p, const std::vector<double>& pressures) {
  const AvbdlShape shape = avbdl_shape(p);
  const double slack = shape.min_length;  // the line's ends closer than any free length
  FreeLengthTrack track;
  for (double pa : pressures) {
    const double whole = avbdl_line_muscle_length(p, shape, pa, slack);
    const double tracked = avbdl_line_muscle_length(p, shape, pa, slack, &track);
    ASSERT_GT(whole, slack);
    ASSERT_NEAR(tracked, whole, 1e-12 * whole) << pa / kBar << " bar";
    ASSERT_EQ(avbdl_line_muscle_length(p, shape, pa, slack, &track), tracked) << "again";
    ASSERT_EQ(track.pressure_pa, pa);
  }
  const FreeLengthTrack before = track;
  const double taut = avbdl_max_length(p);  // pulled to the law's end: the line is taut
  EXPECT_EQ(avbdl_line_muscle_length(p, shape, 0.25 * kBar, taut, &track), taut);
  EXPECT_EQ(track.length_m, before.length_m);
  avbdl_line_muscle_length(p, shape, kNaN, slack, &track);
  EXPECT_TRUE(std::isnan(track.pressure_pa));
  EXPECT_NEAR(avbdl_line_muscle_length(p, shape, 3.0 * kBar, slack, &track),
              avbdl_line_muscle_length(p, shape, 3.0 * kBar, slack), 1e-15);
}

TEST(AvbdlTest, ATrackedFreeLengthAgreesWithTheWholeSearch) {
  std::vector<double> pressures;
  for (int k = 0; k <= 500; ++k) pressures.push_back((1.0 + 0.01 * k) * kBar);  // 1 -> 6 bar
  pressures.insert(pressures.end(), {1.5 * kBar, 6.5 * kBar, 0.2 * kBar});      // jumps
  expect_tracked_as_whole(with_friction(arm_pam()), pressures);
  AvbdlParams tube = with_friction(arm_pam());
  tube.bladder_diameter_m = 0.6 * tube.diameter_m;
  std::vector<double> low;
  for (int k = 1; k <= 300; ++k) low.push_back(0.01 * k * kBar);  // 0.01 -> 3 bar
  low.insert(low.end(), {0.02 * kBar, 2.0 * kBar});
  ASSERT_GT(avbdl_free_length(tube, 0.05 * kBar), tube.length_m) << "a root past L0";
  expect_tracked_as_whole(tube, low);
}

// The shape derived once gives what each call derives for itself, to the bit; its memo
// answers the same (p, L) with the same force and recomputes for another
TEST(AvbdlTest, AShapeDerivedOnceGivesTheSameBitsAndItsMemoOnlyRepeats) {
  const AvbdlParams p = with_friction(arm_pam());
  const AvbdlShape shape = avbdl_shape(p);
  EXPECT_EQ(shape.min_length, avbdl_min_length(p));
  FrictionInput rest;
  for (double l : {0.150, 0.165, 0.172, 0.185}) {
    for (double bar : {0.0, 2.0, 6.0}) {
      const double pa = bar * kBar;
      EXPECT_EQ(avbdl_volume(p, shape, l), avbdl_volume(p, l));
      EXPECT_EQ(avbdl_dvolume_dlength(p, shape, l), avbdl_dvolume_dlength(p, l));
      const double pull = avbdl_line_pull(p, shape, pa, l, rest);
      EXPECT_EQ(pull, avbdl_line_pull(p, pa, l, rest));
      EXPECT_EQ(avbdl_line_muscle_length(p, shape, pa, l), avbdl_line_muscle_length(p, pa, l));
      EXPECT_EQ(avbdl_line_pull(p, shape, pa, l, rest), pull) << "the memo's answer";
    }
  }
  const double l = 0.172;
  avbdl_line_pull(p, shape, 4.0 * kBar, l, rest);
  EXPECT_EQ(shape.memo_pressure_pa, 4.0 * kBar);
  EXPECT_EQ(avbdl_line_pull(p, shape, 5.0 * kBar, l, rest), avbdl_line_pull(p, 5.0 * kBar, l, rest))
      << "another pressure is computed, not remembered";
}

}  // namespace
}  // namespace pamsim
