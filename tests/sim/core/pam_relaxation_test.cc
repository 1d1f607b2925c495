// pam_relaxation_test.cc: the bladder's relaxation (bladder_relaxation.h) in the MuJoCo
// binding: a length step is answered with the law's static pull plus the Prony overstress
// of the bladder's force change, relaxing step by step as the closed form says; the binding
// round-trips; a model without room for the history is refused by name.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "sim/inline_mjcf.h"
#include "sim/slider_mjcf.h"
#include "base/input_error.h"
#include "base/units.h"
#include "sim/core/mujoco_util.h"
#include "sim/core/pam_callback.h"

namespace pamsim {
namespace {

using pamsim_test::load_inline;

constexpr double kLine = 0.3, kPressure = 0.4e6;

AvbdlParams relaxing_plant() {
  AvbdlParams plant = avbdl_params_from_geometry(0.18, 0.010, units::deg_to_rad(25.0), 0.002,
                                                 kNaturalRubberTreloar);
  plant.relaxation.count = 2;
  plant.relaxation.weight = {0.2, 0.1};
  plant.relaxation.time_s = {0.005, 0.05};
  return plant;
}

// The slider (slider_mjcf.h) with room for a relaxing bladder (`size`: 2 pressures' worth of
// userdata, then the history block) and a 1 ms step
MjModelPtr model_with(const AvbdlParams& plant, const char* size = "nuserdata=\"8\"") {
  std::string xml = pamsim_test::kSliderXml;
  xml.replace(xml.find("nuserdata=\"2\""), 13, size);
  xml.replace(xml.find("gravity=\"0 0 0\""), 15, "gravity=\"0 0 0\" timestep=\"0.001\"");
  MjModelPtr m = load_inline(xml.c_str(), "relaxing.xml");
  const SpringModel spring = spring_model_from_paper_units(SpringLaw::kEq3, -60.1, 170.1,
                                                           {0.911, 0.256, 7.00, -0.201, 0, 0});
  store_pam_in_model(m.get(), 0, spring, kLine, 1, "relaxing.xml");
  store_plant_in_model(m.get(), 0, plant, 2, "relaxing.xml");
  return m;
}

// The pull at muscle length `length` after forward dynamics, committing the step after.
double pull_and_commit(const mjModel* m, mjData* d, double length) {
  d->qpos[0] = length + kLine;
  d->userdata[1] = kPressure;
  mj_forward(m, d);
  const double pull = -d->actuator_force[0];
  pam_commit_history(m, d, 0, pam_muscle_length(m, d, 0));
  return pull;
}

// Held at L1, then stepped to L2 and held: the pull is the static law at L2 plus
// sum g_i ((1 - e_i) tau_i / dt) dF_e e_i^n after n further steps, dF_e the bladder's
// relaxed force change dW/dL(L2) - dW/dL(L1) (Pipan et al., Eq. (23)-(25)).
TEST(PamRelaxationTest, ALengthStepRelaxesAsThePronySeriesSays) {
  install_pam_actuator_callback();
  const AvbdlParams plant = relaxing_plant();
  MjModelPtr m = model_with(plant);
  MjDataPtr d = make_data(m.get());
  const double l1 = avbdl_length_at_force(plant, kPressure, 20.0), l2 = l1 + 2e-3;
  for (int k = 0; k < 500; ++k) pull_and_commit(m.get(), d.get(), l1);  // relaxed at L1
  const double change =
      avbdl_dbladder_energy_dlength(plant, l2) - avbdl_dbladder_energy_dlength(plant, l1);
  ASSERT_GT(std::fabs(change), 0.1) << "the bladder's force moves with the step";
  const double static_pull = avbdl_static_force(plant, kPressure, l2);
  for (int n = 0; n < 200; ++n) {
    double expected = static_pull;
    for (int i = 0; i < 2; ++i) {
      const double x = 0.001 / plant.relaxation.time_s[i];
      expected += plant.relaxation.weight[i] * (1.0 - std::exp(-x)) / x * change * std::exp(-x * n);
    }
    ASSERT_NEAR(pull_and_commit(m.get(), d.get(), l2), expected, 1e-9 * expected) << n;
  }
  for (int n = 200; n < 2000; ++n) pull_and_commit(m.get(), d.get(), l2);
  EXPECT_NEAR(pull_and_commit(m.get(), d.get(), l2), static_pull, 1e-12 * static_pull)
      << "relaxed after 40 times the longest time";
}

// The same plant without the rate term pulls exactly the static law at every step.
TEST(PamRelaxationTest, AnElasticBladderHasNoOverstress) {
  install_pam_actuator_callback();
  AvbdlParams plant = relaxing_plant();
  plant.relaxation = BladderRelaxation{};
  MjModelPtr m = model_with(plant);
  MjDataPtr d = make_data(m.get());
  const double l = avbdl_length_at_force(plant, kPressure, 20.0);
  pull_and_commit(m.get(), d.get(), l);
  EXPECT_EQ(pull_and_commit(m.get(), d.get(), l + 2e-3),
            avbdl_static_force(plant, kPressure, l + 2e-3));
}

TEST(PamRelaxationTest, TheTermsRoundTripAndAModelWithoutRoomIsRefused) {
  const AvbdlParams plant = relaxing_plant();
  MjModelPtr m = model_with(plant);
  AvbdlParams back;
  ASSERT_TRUE(pam_plant_from_model(m.get(), 0, &back));
  EXPECT_EQ(back.relaxation.count, 2);
  EXPECT_EQ(back.relaxation.weight[1], 0.1);
  EXPECT_EQ(back.relaxation.time_s[0], 0.005);
  EXPECT_EQ(pam_history_size(plant), 4);
  try {
    model_with(plant, "nuserdata=\"5\"");
    ADD_FAILURE() << "a 4-value history at index 2 bound in 5 values of userdata";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()),
              "relaxing.xml: <size nuserdata> must be >= 6 to hold the "
              "PAMs' pressures and histories");
  }
}

}  // namespace
}  // namespace pamsim
