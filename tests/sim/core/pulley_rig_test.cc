// pulley_rig_test.cc: the pulley rig (models/pulley_rig.xml) loads, its PAM holds the hanging
// weight, and the force it settles at is the weight's: a static check of the binding on the
// second model the project ships.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "pam_actuator/pam_params.h"
#include "base/units.h"
#include "sim/core/mujoco_util.h"
#include "sim/core/pam_callback.h"

namespace pamsim {
namespace {

TEST(PulleyRigTest, PamHoldsTheWeightAtTheLawsDeformation) {
  const std::string dir = std::string(PAMSIM_SOURCE_DIR) + "/models/";
  MjModelPtr model = load_mjcf(dir + "pulley_rig.xml");
  mjModel* m = model.get();
  const PamParams pam = load_pam_params(dir + "pams/table4_agonist.toml");
  const int act = require_id(m, mjOBJ_ACTUATOR, "pam", "pulley_rig.xml");
  const int weight = require_id(m, mjOBJ_BODY, "weight", "pulley_rig.xml");
  const double p = units::mpa_to_pa(0.4);
  const double weight_n = m->body_mass[weight] * 9.81;
  ASSERT_NEAR(m->body_mass[weight], 5.0, 1e-12);

  // line length so that the weight hangs at the slide's zero when the law carries it
  const DeformationEstimate d_eq = invert_spring_model(pam.spring, p, weight_n);
  ASSERT_EQ(d_eq.status, InversionStatus::kOk);
  MjDataPtr data = make_data(m);
  mj_forward(m, data.get());
  const double line = data->actuator_length[act] - (natural_length(pam.spring, p) + d_eq.d_m);
  store_pam_in_model(m, act, pam.spring, line, 0, "pulley_rig.xml");

  // released 5 mm high, it settles where the PAM force equals the weight
  data->qpos[0] = 0.005;
  data->userdata[0] = p;
  for (int step = 0; step < 4000; ++step) mj_step(m, data.get());
  EXPECT_NEAR(-data->actuator_force[act], weight_n, 1e-3 * weight_n);
  EXPECT_NEAR(data->qpos[0], 0.0, 1e-4);
  EXPECT_LT(std::fabs(data->qvel[0]), 1e-3);
}

}  // namespace
}  // namespace pamsim
