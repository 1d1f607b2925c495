// pose_calibration_test.cc: `calibrate --pose` on the PAM leg. The balanced lines hold the
// pose as MuJoCo itself computes it (the PAM force callback's pulls through MuJoCo's moment
// arms against gravity: qfrc_actuator + qfrc_passive - qfrc_bias = 0 on every crossed joint);
// the uniform rule's residual is what MuJoCo sees; the leg's scenarios carry the uniform
// lines; bad requests are refused in one line.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "base/input_error.h"
#include "base/units.h"
#include "sim/cli_util.h"
#include "sim/core/pose_calibration.h"
#include "sim/core/trial_lines.h"
#include "sim/scenario/scenario_file.h"
#include "sim/test_paths.h"

namespace {

using pamsim::PoseCalibration;
using pamsim::PoseCalibrationRequest;
using pamsim::Scenario;
using pamsim::TrialModel;

const std::string kLanding = pamsim_test::kScenarios + "landing.toml";

PoseCalibration calibrate_leg(bool balance, const std::string& scenario = kLanding,
                              double pressure_pa = -1) {
  const Scenario sc = pamsim::load_scenario(scenario);
  const TrialModel tm = pamsim::load_trial_model(sc);
  PoseCalibrationRequest req;
  req.balance = balance;
  req.pressure_pa = pressure_pa;
  return pamsim::solve_pose_calibration(tm, sc, req);
}

// MuJoCo's net generalised force on each crossed joint at the start, the leg's lines set to
// `c`'s (full precision).
std::vector<double> net_torques(const PoseCalibration& c) {
  std::vector<std::string> lines;
  for (const auto& l : c.lines) {
    char buf[96];
    std::snprintf(buf, sizeof(buf), "%s.line_mm=%.17g", l.muscle.c_str(),
                  pamsim::units::m_to_mm(l.line_m()));
    lines.push_back(buf);
  }
  const Scenario sc = pamsim::load_scenario(kLanding, lines);
  const TrialModel tm = pamsim::load_trial_model(sc);
  const pamsim::MjDataPtr d = pamsim::detail::start_state(sc, tm);
  const mjModel* m = tm.model.get();
  std::vector<double> net;
  for (const std::string& joint : c.joints) {
    const int dof = m->jnt_dofadr[mj_name2id(m, mjOBJ_JOINT, joint.c_str())];
    net.push_back(d->qfrc_actuator[dof] + d->qfrc_passive[dof] - d->qfrc_bias[dof]);
  }
  return net;
}

TEST(PoseCalibrationTest, BalancedLinesHoldTheLegsPoseAsMujocoComputesIt) {
  const PoseCalibration c = calibrate_leg(true);
  ASSERT_EQ(c.joints, (std::vector<std::string>{"hip", "knee", "ankle"}));
  const std::vector<double> net = net_torques(c);
  for (std::size_t j = 0; j < net.size(); ++j) EXPECT_NEAR(net[j], 0.0, 1e-6) << c.joints[j];
  for (const auto& l : c.lines) {
    EXPECT_GT(l.deformation_m, 0.0) << l.muscle;  // every line taut
    EXPECT_GT(l.force_n, 0.0) << l.muscle;
  }
}

TEST(PoseCalibrationTest, TheUniformRulesResidualIsWhatMujocoSees) {
  const PoseCalibration c = calibrate_leg(false);
  const std::vector<double> net = net_torques(c);
  double largest = 0;
  for (std::size_t j = 0; j < net.size(); ++j) {
    EXPECT_NEAR(net[j], -c.residual_nm[j], 1e-6) << c.joints[j];
    largest = std::max(largest, std::fabs(net[j]));
  }
  EXPECT_GT(largest, 0.1);  // 2 mm everywhere does not hold the pose
  for (const auto& l : c.lines) EXPECT_DOUBLE_EQ(l.deformation_m, 2e-3) << l.muscle;
}

// The leg's scenarios in the crouch carry calibrate --pose --pressure-MPa 0.4's uniform lines
// (written to 0.01 mm; hopping's commands start elsewhere, its lines are the crouch's at 0.4).
TEST(PoseCalibrationTest, TheLegsScenariosCarryTheUniformLines) {
  for (const char* file : {"landing.toml", "landing_reflex.toml", "hopping.toml"}) {
    const std::string path = pamsim_test::kScenarios + file;
    const PoseCalibration c = calibrate_leg(false, path, 0.4e6);
    const Scenario sc = pamsim::load_scenario(path);
    ASSERT_EQ(sc.muscles.size(), c.lines.size()) << file;
    for (const auto& line : c.lines) {
      for (const auto& spec : sc.muscles) {
        if (spec.key != line.muscle) continue;
        EXPECT_NEAR(spec.line_length_m, line.line_m(), 0.005e-3) << file << " " << line.muscle;
      }
    }
  }
}

TEST(PoseCalibrationTest, BadRequestsAreOneLineAndExit2) {
  for (const std::string& args :
       {std::string("--pose --deformation-mm 0"), std::string("--pose --deformation-mm -1"),
        std::string("--pose --pressure-MPa -0.1"), std::string("--balance")}) {
    const auto r = pamsim_test::run_pamsim("calibrate " + kLanding + " " + args);
    EXPECT_EQ(r.exit_code, 2) << args << ": " << r.err;
    EXPECT_EQ(pamsim_test::line_count(r.err), 1) << args << ": " << r.err;
  }
  // 200 mm past the free length: longer than any of the leg's tendons
  const Scenario sc = pamsim::load_scenario(kLanding);
  const TrialModel tm = pamsim::load_trial_model(sc);
  PoseCalibrationRequest req;
  req.deformation_m = 0.2;
  EXPECT_THROW(pamsim::solve_pose_calibration(tm, sc, req), pamsim::InputError);
}

}  // namespace
