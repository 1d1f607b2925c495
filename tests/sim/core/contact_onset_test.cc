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

// Two points of the harder identification family's parameters (the antagonist's wall [mm],
// the agonist's extension friction A0 [mm^2], the valve's time constant [ms], the regulator's
// band [kPa]) between which, at the model's own contact, the ball's landing on the basket's
// wall moves by a physics step (a fit once ended at the first, the truth was the second).
constexpr double kFrom[] = {2.586692288, 3.543786011, 15.66680396, 340.0871688};
constexpr double kTo[] = {2.58701, 3.5455, 15.7005, 340.536};
const char* const kOnsetKeys[] = {"muscles.antagonist.plant.geometry.wall_thickness_mm",
                                  "muscles.agonist.plant.friction.extension.A0_mm2",
                                  "valve.valve_time_constant_ms", "valve.proportional_band_kPa"};

// The passive drop's angle [deg] at each log row, at fraction `t` of the way from kFrom to
// kTo, with `extra` overrides.
std::vector<double> drop_angle(double t, const std::vector<std::string>& extra) {
  std::vector<std::string> sets = {"sensors.noise_scale=0"};
  for (int i = 0; i < 4; ++i) {
    sets.push_back(std::string(kOnsetKeys[i]) + "=" +
                   format_shortest(kFrom[i] + t * (kTo[i] - kFrom[i])));
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

// Over 16 equal steps along the line, the largest step's RMS change of the angle over the
// median step's: near 1 for a trajectory continuous in the parameters, the jump over the
// parameters' own effect where a landing moves by a step.
double largest_over_median_step(const std::vector<std::string>& extra) {
  constexpr int kSteps = 16;
  std::vector<std::vector<double>> runs;
  for (int k = 0; k <= kSteps; ++k) runs.push_back(drop_angle(k / double(kSteps), extra));
  std::vector<double> step;
  for (int k = 0; k < kSteps; ++k) {
    double sum = 0.0;
    for (std::size_t i = 0; i < runs[k].size(); ++i) {
      sum += (runs[k + 1][i] - runs[k][i]) * (runs[k + 1][i] - runs[k][i]);
    }
    step.push_back(std::sqrt(sum / runs[k].size()));
  }
  const double largest = *std::max_element(step.begin(), step.end());
  std::nth_element(step.begin(), step.begin() + kSteps / 2, step.end());
  return largest / step[kSteps / 2];
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
