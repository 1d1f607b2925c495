// pam_callback_test.cc: the MuJoCo binding applies exactly the pam_actuator force law.
#include "sim/core/pam_callback.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "sim/inline_mjcf.h"
#include "sim/slider_mjcf.h"
#include "base/input_error.h"
#include "base/units.h"
#include "sim/core/mujoco_util.h"

namespace pamsim {
namespace {

using pamsim_test::load_inline;

using pamsim_test::kSliderXml;

// The slider with `userdata` values of d->userdata, loaded as "slider.xml".
MjModelPtr slider_with_userdata(int userdata) {
  std::string xml = kSliderXml;
  xml.replace(xml.find("nuserdata=\"2\""), 13, "nuserdata=\"" + std::to_string(userdata) + "\"");
  return load_inline(xml.c_str(), "slider.xml");
}

class PamCallbackTest : public ::testing::Test {
 protected:
  void SetUp() override {
    model_ = load_inline(kSliderXml, "slider.xml");
    ASSERT_TRUE(model_);
    spring_ = spring_model_from_paper_units(SpringLaw::kEq3, -60.1, 170.1,
                                            {0.911, 0.256, 7.00, -0.201, 0, 0});
    store_pam_in_model(model_.get(), 0, spring_, kLineLength, 1, "slider.xml");
    data_ = make_data(model_.get());
  }

  // actuator force for a PAM length (through the tendon) and a pressure
  double actuator_force(double pam_length_m, double p_pa) {
    data_->qpos[0] = pam_length_m + kLineLength;
    data_->userdata[1] = p_pa;
    mj_forward(model_.get(), data_.get());
    return data_->actuator_force[0];
  }

  static constexpr double kLineLength = 0.3;
  MjModelPtr model_;
  MjDataPtr data_;
  SpringModel spring_;
};

TEST_F(PamCallbackTest, AppliedForceEqualsTheLaw) {
  for (double p_mpa : {0.1, 0.25, 0.4, 0.6, 0.8}) {
    const double p = units::mpa_to_pa(p_mpa);
    for (double d_mm : {0.5, 2.0, 5.0, 10.0, 20.0}) {
      const double l = natural_length(spring_, p) + units::mm_to_m(d_mm);
      const double expected = spring_force(spring_, p, units::mm_to_m(d_mm));
      ASSERT_GT(expected, 0.0);
      EXPECT_NEAR(-actuator_force(l, p), expected, 1e-9 * expected) << p_mpa << " MPa " << d_mm;
    }
  }
}

TEST_F(PamCallbackTest, Table4AgonistAt10mmPulls54_67N) {
  const double p = units::mpa_to_pa(0.4);
  const double l = natural_length(spring_, p) + 0.010;
  EXPECT_NEAR(-actuator_force(l, p), 54.67, 1e-9 * 54.67);
}

TEST_F(PamCallbackTest, ShorterThanNaturalLengthIsSlack) {
  const double p = units::mpa_to_pa(0.4);
  for (double short_by_mm : {0.1, 5.0, 40.0}) {
    const double l = natural_length(spring_, p) - units::mm_to_m(short_by_mm);
    EXPECT_EQ(actuator_force(l, p), 0.0) << short_by_mm;
  }
  // at the natural length itself only rounding of the tendon length remains
  EXPECT_NEAR(actuator_force(natural_length(spring_, p), p), 0.0, 1e-9);
}

TEST_F(PamCallbackTest, PullsOnlyAndMovesTheSliderTowardShorter) {
  const double p = units::mpa_to_pa(0.4);
  data_->qpos[0] = natural_length(spring_, p) + 0.01 + kLineLength;
  data_->userdata[1] = p;
  mj_forward(model_.get(), data_.get());
  EXPECT_LT(data_->actuator_force[0], 0.0);
  EXPECT_LT(data_->qacc[0], 0.0);
}

// Only a user-bias tendon actuator with room for its pressure in userdata is a PAM; a plant
// or a line's stiffness needs a bound spring law first.
TEST_F(PamCallbackTest, RejectsActuatorsThatCannotBePams) {
  constexpr char kNoRoom[] = R"(<mujoco><worldbody><body>
    <joint name="j" type="slide"/><geom size="0.1" mass="1"/></body></worldbody>
    <tendon><fixed name="t"><joint joint="j" coef="1"/></fixed></tendon>
    <actuator><general tendon="t" biastype="user"/></actuator></mujoco>)";
  MjModelPtr no_room = load_inline(kNoRoom, "small.xml");
  ASSERT_TRUE(no_room);
  EXPECT_THROW(store_pam_in_model(no_room.get(), 0, spring_, 0.1, 0, "small.xml"), InputError);
  std::string affine = kSliderXml;
  affine.replace(affine.find("biastype=\"user\""), 15, "biastype=\"affine\"");
  MjModelPtr not_user = load_inline(affine.c_str(), "affine.xml");
  ASSERT_TRUE(not_user);
  EXPECT_THROW(store_pam_in_model(not_user.get(), 0, spring_, 0.1, 0, "affine.xml"), InputError);
  MjModelPtr unbound = load_inline(kSliderXml, "slider.xml");
  try {
    store_plant_in_model(unbound.get(), 0, AvbdlParams{}, -1, "slider.xml");
    ADD_FAILURE() << "a plant was bound to an actuator with no spring law";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("slider.xml: actuator 0 is not a bound PAM"),
              std::string::npos)
        << e.what();
  }
  EXPECT_THROW(store_line_in_model(unbound.get(), 0, LineBinding{300.0}, "slider.xml"), InputError);
}

// The binding belongs to the model: a copy (copy_model) pulls with the same law, a rebinding
// is seen at once by a thread that has evaluated the old one, an unbound actuator pulls
// nothing, and a deleted model's bindings are gone.
TEST_F(PamCallbackTest, TheBindingFollowsTheModelItsCopiesAndItsRebindings) {
  const double p = units::mpa_to_pa(0.4), l = natural_length(spring_, p) + 0.010;
  const double pull = -actuator_force(l, p);
  MjModelPtr copy = copy_model(model_.get());
  MjDataPtr d = make_data(copy.get());
  mj_copyData(d.get(), model_.get(), data_.get());
  mj_forward(copy.get(), d.get());
  EXPECT_EQ(-d->actuator_force[0], pull) << "the copy pulls with the original's law";

  store_pam_in_model(model_.get(), 0, spring_, kLineLength + 0.005, 1, "slider.xml");
  EXPECT_NEAR(-actuator_force(l + 0.005, p), pull, 1e-9 * pull) << "the longer line, seen";
  mj_forward(copy.get(), d.get());
  EXPECT_EQ(-d->actuator_force[0], pull) << "the copy keeps the law it was given";

  const mjModel* deleted = copy.get();
  copy.reset();
  EXPECT_EQ(find_muscle(deleted, 0), nullptr);
  MjModelPtr unbound = load_inline(kSliderXml, "slider.xml");
  MjDataPtr du = make_data(unbound.get());
  du->qpos[0] = l + kLineLength;
  du->userdata[1] = p;
  mj_forward(unbound.get(), du.get());
  EXPECT_EQ(du->actuator_force[0], 0.0);
}

// The same slider with a plant: the actuator force is the AVBDL law's (Eq. (25)),
// pull only, and the plant's parameters read back exactly.
TEST_F(PamCallbackTest, APlantActuatorPullsWithTheAvbdlLaw) {
  MjModelPtr m = load_inline(kSliderXml, "slider.xml");
  ASSERT_TRUE(m);
  AvbdlParams plant = avbdl_params_from_geometry(0.18, 0.010, units::deg_to_rad(25.0), 0.002,
                                                 kNaturalRubberTreloar);
  plant.friction.extension.force_n = 0.5;
  store_pam_in_model(m.get(), 0, spring_, kLineLength, 1, "slider.xml");
  AvbdlParams none;
  EXPECT_FALSE(pam_plant_from_model(m.get(), 0, &none)) << "the spring law until a plant is stored";
  store_plant_in_model(m.get(), 0, plant, -1, "slider.xml");
  AvbdlParams back;
  ASSERT_TRUE(pam_plant_from_model(m.get(), 0, &back));
  EXPECT_EQ(back.wall_thickness_m, plant.wall_thickness_m);
  EXPECT_EQ(back.friction.extension.force_n, 0.5);

  MjDataPtr d = make_data(m.get());
  for (double l : {0.150, 0.160, 0.170}) {
    d->qpos[0] = l + kLineLength;
    d->qvel[0] = 0.0;
    d->userdata[1] = 0.4e6;
    mj_forward(m.get(), d.get());
    const double expected = std::max(avbdl_static_force(plant, 0.4e6, l), 0.0);
    EXPECT_NEAR(-d->actuator_force[0], expected, 1e-9 * (1.0 + expected)) << l;
  }
  // shorter than its free length: slack, and the muscle rests at that free length
  d->qpos[0] = 0.130 + kLineLength;
  mj_forward(m.get(), d.get());
  EXPECT_EQ(d->actuator_force[0], 0.0);
  EXPECT_NEAR(pam_muscle_length(m.get(), d.get(), 0), avbdl_free_length(plant, 0.4e6), 1e-12);
  // with the line's length at hand (pam_muscle_length_at): a taut line's is the muscle's, a
  // slack one's gives the free length, whatever it is
  const double free = avbdl_free_length(plant, 0.4e6);
  EXPECT_EQ(pam_muscle_length_at(m.get(), d.get(), 0, free + 0.004), free + 0.004);
  EXPECT_NEAR(pam_muscle_length_at(m.get(), d.get(), 0, free - 0.010), free, 1e-12);
  EXPECT_NEAR(pam_muscle_length_at(m.get(), d.get(), 0, free - 0.020), free, 1e-12);
}

// Stores Table IV's agonist spring law (line 0.3 m, pressure at userdata[1]) and `plant`
// (its slip state from userdata[2]) in actuator 0 of `m`.
void store_slider_plant(mjModel* m, const AvbdlParams& plant) {
  const SpringModel spring = spring_model_from_paper_units(SpringLaw::kEq3, -60.1, 170.1,
                                                           {0.911, 0.256, 7.00, -0.201, 0, 0});
  store_pam_in_model(m, 0, spring, 0.3, 1, "slider.xml");
  store_plant_in_model(m, 0, plant, 2, "slider.xml");
}

// The slider with room for a Maxwell-slip plant's state, overdamped (so it approaches
// monotonically), under a constant load that stretches the muscle, with braid friction of
// the given form.
struct LoadedSlider {
  MjModelPtr m;
  MjDataPtr d;
  AvbdlParams plant;
  static constexpr double kPressure = 0.4e6, kLoad = 20.0;  // [Pa], [N]

  explicit LoadedSlider(FrictionModel form) {
    std::string xml = kSliderXml;
    xml.replace(xml.find("nuserdata=\"2\""), 13, "nuserdata=\"5\"");
    xml.replace(xml.find("type=\"slide\""), 12, "type=\"slide\" damping=\"400\"");
    // the smooth friction's slope near rest, F_f / v_s = 1 800 N s/m, is explicit in the
    // Euler step: stable only for c dt / m < 2
    xml.replace(xml.find("<option "), 8, "<option timestep=\"0.0005\" ");
    m = load_inline(xml.c_str(), "slider.xml");
    plant = avbdl_params_from_geometry(0.18, 0.010, units::deg_to_rad(25.0), 0.002,
                                       kNaturalRubberTreloar);
    plant.friction.extension = {1.0, 2.0e-6, 0.0};    // 1.8 N at 0.4 MPa
    plant.friction.contraction = {1.0, 1.5e-6, 0.0};  // 1.6 N
    plant.friction.model = form;
    plant.friction.slip.count = 2;
    plant.friction.slip.weight = {0.5, 0.5};
    plant.friction.slip.breakaway_m = {0.05e-3, 0.2e-3};
    store_slider_plant(m.get(), plant);
    d = make_data(m.get());
  }

  // Starts `offset_m` from where the law holds the load, at rest, and lets it settle;
  // returns the muscle length it rests at.
  double settle_from(double offset_m) {
    d->qpos[0] = avbdl_length_at_force(plant, kPressure, kLoad) + offset_m + 0.3;
    d->userdata[1] = kPressure;
    for (int k = 0; k < 12000; ++k) {  // 6 s
      d->xfrc_applied[6 * 1 + 0] = kLoad;
      mj_step(m.get(), d.get());
      pam_commit_history(m.get(), d.get(), 0, pam_muscle_length(m.get(), d.get(), 0));
    }
    EXPECT_LT(std::fabs(d->qvel[0]), 1e-5) << "at rest";
    return pam_muscle_length(m.get(), d.get(), 0);
  }
};

// The arm's braid friction as Maxwell-slip sticks: approached from a longer and from a
// shorter length, the muscle stops on either side of the friction-free equilibrium, the
// friction band over the law's stiffness apart; the smooth tanh(v / v_s) form creeps to the
// same length from both sides.
TEST(PamCallbackSlipTest, MaxwellSlipStopsWithinTheFrictionBandAndSmoothFrictionCreeps) {
  install_pam_actuator_callback();
  LoadedSlider slip(FrictionModel::kMaxwellSlip), smooth(FrictionModel::kSmooth);
  const double p = LoadedSlider::kPressure;
  const double l_eq = avbdl_length_at_force(slip.plant, p, LoadedSlider::kLoad);
  const double stiffness = (avbdl_static_force(slip.plant, p, l_eq + 1e-5) -
                            avbdl_static_force(slip.plant, p, l_eq - 1e-5)) /
                           2e-5;
  const double band = (1.0 + 2.0e-6 * p) + (1.0 + 1.5e-6 * p);
  const double from_above = slip.settle_from(3e-3), from_below = slip.settle_from(-3e-3);
  EXPECT_GT(from_above, l_eq) << "shortening, the friction holds back the pull";
  EXPECT_LT(from_below, l_eq);
  EXPECT_NEAR(from_above - from_below, band / stiffness, 0.1 * band / stiffness);
  const double smooth_gap = smooth.settle_from(3e-3) - smooth.settle_from(-3e-3);
  EXPECT_LT(std::fabs(smooth_gap), 0.05 * band / stiffness);
}

TEST(PamCallbackSlipTest, AMaxwellSlipPlantNeedsRoomForItsState) {
  AvbdlParams plant = avbdl_params_from_geometry(0.18, 0.010, units::deg_to_rad(25.0), 0.002,
                                                 kNaturalRubberTreloar);
  plant.friction.model = FrictionModel::kMaxwellSlip;
  plant.friction.slip.count = 2;
  plant.friction.slip.weight = {0.5, 0.5};
  plant.friction.slip.breakaway_m = {0.05e-3, 0.2e-3};
  for (int history_index : {2, -1}) {  // 2 + 1 + 2 values need nuserdata 5
    MjModelPtr m = slider_with_userdata(4);
    ASSERT_TRUE(m);
    store_pam_in_model(m.get(), 0, SpringModel{}, 0.3, 1, "slider.xml");
    try {
      store_plant_in_model(m.get(), 0, plant, history_index, "slider.xml");
      ADD_FAILURE() << "bound with its history at " << history_index;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("slider.xml: <size nuserdata> must be >= "),
                std::string::npos)
          << e.what();
    }
  }
  // read back whole from a model with room
  LoadedSlider loaded(FrictionModel::kMaxwellSlip);
  AvbdlParams back;
  ASSERT_TRUE(pam_plant_from_model(loaded.m.get(), 0, &back));
  EXPECT_EQ(back.friction.model, FrictionModel::kMaxwellSlip);
  EXPECT_EQ(back.friction.slip.count, 2);
  EXPECT_EQ(back.friction.slip.breakaway_m[1], 0.2e-3);
  EXPECT_EQ(back.friction.slip.weight[0], 0.5);
}

// An extensible line in series with a linear spring law (Eq. (3) with a0 only): two springs in
// series, F = k (x0 - l_n) / (1 + k c) with c = L0 / (E A), and the PAM's end where the
// stretched line leaves it, x0 - c F.
TEST(PamCallbackLineTest, AnExtensibleLineIsASpringInSeriesWithTheMuscle) {
  MjModelPtr m = load_inline(kSliderXml, "slider.xml");
  ASSERT_TRUE(m);
  install_pam_actuator_callback();
  SpringModel linear;
  linear.m_m_per_pa = -60e-9;  // l_n = 0.17 m - 60 mm/MPa p
  linear.h_m = 0.170;
  linear.coef = {5000.0, 0, 0, 0, 0, 0};  // k [N/m]
  const double line = 0.3, ea = 300.0, c = line / ea, k = 5000.0, p = 0.4e6;
  store_pam_in_model(m.get(), 0, linear, line, 1, "slider.xml");
  store_line_in_model(m.get(), 0, LineBinding{ea}, "slider.xml");
  EXPECT_EQ(pam_line_axial_stiffness(m.get(), 0), ea);
  MjDataPtr d = make_data(m.get());
  const double l_n = natural_length(linear, p);
  for (double stretch : {0.002, 0.010, 0.030}) {
    d->qpos[0] = line + l_n + stretch;
    d->userdata[1] = p;
    mj_forward(m.get(), d.get());
    const double f = k * stretch / (1.0 + k * c);
    EXPECT_NEAR(-d->actuator_force[0], f, 1e-9 * f) << stretch;
    EXPECT_NEAR(pam_taut_length(m.get(), d.get(), 0), l_n + stretch - c * f, 1e-12) << stretch;
  }
  d->qpos[0] = line + l_n - 0.001;  // slack: no tension, no stretch
  mj_forward(m.get(), d.get());
  EXPECT_EQ(d->actuator_force[0], 0.0);
  EXPECT_NEAR(pam_taut_length(m.get(), d.get(), 0), l_n - 0.001, 1e-15);

  // made inextensible again: the muscle's end is the line's, tendon - L0
  store_line_in_model(m.get(), 0, LineBinding{}, "slider.xml");
  EXPECT_EQ(pam_line_axial_stiffness(m.get(), 0), 0.0);
  d->qpos[0] = line + l_n + 0.010;
  mj_forward(m.get(), d.get());
  EXPECT_NEAR(-d->actuator_force[0], k * 0.010, 1e-9 * k * 0.010);
}

// A tube bladder with the Gent-Gent law is bound whole, and the callback pulls with its law.
TEST(PamCallbackBladderTest, ATubeBladderPlantIsStoredWholeAndPullsWithItsLaw) {
  MjModelPtr m = load_inline(kSliderXml, "slider.xml");
  ASSERT_TRUE(m);
  install_pam_actuator_callback();
  AvbdlParams tube;
  tube.length_m = 0.180;
  tube.diameter_m = 0.016;
  tube.wall_thickness_m = 0.5e-3;
  tube.bladder_law = BladderLaw::kGentGent;
  tube.bladder_diameter_m = 0.004;
  tube.end_length_m = 0.0256;
  const double line = 0.3;
  store_pam_in_model(
      m.get(), 0,
      spring_model_from_paper_units(SpringLaw::kEq3, -60.1, 170.1, {0.911, 0.256, 7.0, -0.2, 0, 0}),
      line, 1, "slider.xml");
  store_plant_in_model(m.get(), 0, tube, -1, "slider.xml");
  AvbdlParams back;
  ASSERT_TRUE(pam_plant_from_model(m.get(), 0, &back));
  EXPECT_EQ(back.bladder_law, BladderLaw::kGentGent);
  EXPECT_EQ(back.bladder_diameter_m, 0.004);
  EXPECT_EQ(back.bladder_gent.mu_pa, tube.bladder_gent.mu_pa);
  EXPECT_EQ(back.bladder_gent.c2_pa, tube.bladder_gent.c2_pa);
  EXPECT_EQ(back.bladder_gent.jm, tube.bladder_gent.jm);
  MjDataPtr d = make_data(m.get());
  const double p = 0.4e6, length = avbdl_free_length(tube, p) + 0.005;
  d->qpos[0] = line + length;
  d->userdata[1] = p;
  mj_forward(m.get(), d.get());
  EXPECT_NEAR(-d->actuator_force[0], avbdl_static_force(tube, p, length), 1e-9);
}

}  // namespace
}  // namespace pamsim
