// contact_onset_test.cc: sim.contact_soft_onset_mm. MuJoCo starts a contact with the force
// of its impedance at zero penetration, so a ball's landing that moves by one physics step
// makes the trajectory jump however small the parameter change that moved it; with the
// onset softened the trajectory is a continuous function of the parameters again, and the
// ball at rest sinks by no more than the onset's width.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <toml++/toml.h>

#include "base/format.h"
#include "sim/core/trial.h"
#include "sim/core/trial_model.h"
#include "sim/identify_test_arm.h"
#include "sim/scenario/scenario_file.h"

namespace pamsim {
namespace {

// the ball released at 1 s into the basket of the example arm (kArm), a 3 s trial, with
// `extra` overrides; its trial, which must run to its end
TrialResult ball_drop(const std::vector<std::string>& extra) {
  std::vector<std::string> sets = {"sim.duration_s=3", "events.fall.action=\"release\"",
                                   "events.fall.body=\"ball\"", "events.fall.when.at_s=1.0"};
  sets.insert(sets.end(), extra.begin(), extra.end());
  const Scenario sc = load_scenario(kArm, sets);
  TrialResult r = run_trial(load_trial_model(sc), sc, sc.seed);
  EXPECT_EQ(r.summary.status, "ok") << r.summary.message;
  return r;
}

// The line of examples/identify/landing_line.toml: parameters between which, at the model's
// own contact, the ball's landing on the basket's wall moves by a physics step.
struct LandingLine {
  std::vector<std::string> keys;
  std::vector<double> from, to;
  int steps = 0;
};

LandingLine landing_line() {
  const toml::table file =
      toml::parse_file(std::string(PAMSIM_SOURCE_DIR) + "/examples/identify/landing_line.toml");
  LandingLine line;
  line.steps = static_cast<int>(file["steps"].value_or(0));
  for (const toml::node& p : *file["parameter"].as_array()) {
    const toml::table& t = *p.as_table();
    line.keys.push_back(t["key"].value_or(std::string()));
    line.from.push_back(t["from"].value_or(NAN));
    line.to.push_back(t["to"].value_or(NAN));
  }
  return line;
}

// The passive drop's angle [deg] at each log row, at fraction `t` of the way along the
// line, with `extra` overrides.
std::vector<double> drop_angle(const LandingLine& line, double t,
                               const std::vector<std::string>& extra) {
  std::vector<std::string> sets = {"sensors.noise_scale=0"};
  for (std::size_t i = 0; i < line.keys.size(); ++i) {
    sets.push_back(line.keys[i] + "=" +
                   format_shortest(line.from[i] + t * (line.to[i] - line.from[i])));
  }
  sets.insert(sets.end(), extra.begin(), extra.end());
  const TrialResult r = ball_drop(sets);
  const std::size_t angle = r.trajectory.column("angle_deg");
  std::vector<double> out;
  for (std::size_t row = 0; row < r.trajectory.rows(); ++row) {
    out.push_back(r.trajectory.at(row, angle));
  }
  return out;
}

// Over the line's equal steps (16), the largest step's RMS change of the angle over the
// median step's: near 1 for a trajectory continuous in the parameters, the jump over the
// parameters' own effect where a landing moves by a step.
double largest_over_median_step(const std::vector<std::string>& extra) {
  const LandingLine line = landing_line();
  const int steps = line.steps;
  EXPECT_EQ(line.keys.size(), 4u);
  std::vector<std::vector<double>> runs;
  for (int k = 0; k <= steps; ++k) runs.push_back(drop_angle(line, k / double(steps), extra));
  std::vector<double> step;
  for (int k = 0; k < steps; ++k) {
    double sum = 0.0;
    for (std::size_t i = 0; i < runs[k].size(); ++i) {
      sum += (runs[k + 1][i] - runs[k][i]) * (runs[k + 1][i] - runs[k][i]);
    }
    step.push_back(std::sqrt(sum / runs[k].size()));
  }
  const double largest = *std::max_element(step.begin(), step.end());
  std::nth_element(step.begin(), step.begin() + steps / 2, step.end());
  return largest / step[steps / 2];
}

TEST(ContactOnsetTest, TheModelsOwnContactMakesALandingJump) {
  // the reason for the key: without it one sixteenth of this line moves the angle 11 times as
  // far as the median sixteenth does (1.05 times with it, below)
  EXPECT_GT(largest_over_median_step({"sim.contact_soft_onset_mm=0"}), 5.0);
}

TEST(ContactOnsetTest, ASoftOnsetMakesTheTrajectoryContinuousInTheParameters) {
  EXPECT_LT(largest_over_median_step({"sim.contact_soft_onset_mm=1"}), 1.5);
}

// The ball's height [m] at the end of a passive drop, settled in the basket.
double ball_rest_height(const std::vector<std::string>& extra) {
  std::vector<std::string> sets = {"joints.shoulder.damping_N_m_s_per_rad=2"};
  sets.insert(sets.end(), extra.begin(), extra.end());
  const TrialResult r = ball_drop(sets);
  return r.trajectory.at(r.trajectory.rows() - 1, r.trajectory.column("ball_z_m"));
}

TEST(ContactOnsetTest, TheBallAtRestSinksByNoMoreThanTheOnsetsWidth) {
  const double hard = ball_rest_height({"sim.contact_soft_onset_mm=0"});
  for (const double width_mm : {0.5, 1.0, 2.0}) {
    const double soft =
        ball_rest_height({"sim.contact_soft_onset_mm=" + format_shortest(width_mm)});
    EXPECT_LT(soft, hard) << "a softer start sinks the ball (" << width_mm << " mm)";
    EXPECT_GT(soft, hard - width_mm * 1e-3) << width_mm << " mm";
  }
}

}  // namespace
}  // namespace pamsim
