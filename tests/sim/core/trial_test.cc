// trial_test.cc: the co-simulated arm: static equilibrium at the calibrated start angle,
// the passive drop's events, convergence in the timestep, and determinism across threads;
// a trial stepped by its caller (SteppedTrial) is run_trial's, and takes outside commands.
#include "sim/scenario/scenario_file.h"
#include "sim/core/trial.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <string>
#include <thread>
#include <vector>

#include "base/input_error.h"
#include "sim/core/runner.h"

namespace pamsim {
namespace {

const std::string kPassive = std::string(PAMSIM_SOURCE_DIR) + "/scenarios/drop_mass_passive.toml";

TrialResult run_passive(const std::vector<std::string>& overrides, std::uint64_t seed = 1) {
  const Scenario sc = load_scenario(kPassive, overrides);
  const TrialModel arm = load_trial_model(sc);
  return run_trial(arm, sc, seed);
}

// angle [deg] at time t, interpolated between control ticks
double angle_at(const Trajectory& tr, double t) {
  const std::size_t time = tr.column("time_s"), angle = tr.column("angle_deg");
  for (std::size_t r = 1; r < tr.rows(); ++r) {
    if (tr.at(r, time) >= t) {
      const double w = (t - tr.at(r - 1, time)) / (tr.at(r, time) - tr.at(r - 1, time));
      return (1 - w) * tr.at(r - 1, angle) + w * tr.at(r, angle);
    }
  }
  return NAN;
}

TEST(TrialTest, RestsAtTheCalibratedStartAngle) {
  const TrialResult r = run_passive({"drop.enabled=false", "sim.duration_s=2.0"});
  ASSERT_EQ(r.summary.status, "ok") << r.summary.message;
  const Trajectory& tr = r.trajectory;
  const std::size_t angle = tr.column("angle_deg");
  for (std::size_t row = 0; row < tr.rows(); ++row) {
    EXPECT_NEAR(tr.at(row, angle), -36.0, 0.5) << "row " << row;
  }
  EXPECT_NEAR(r.summary.metric("final_angle_deg"), -36.0, 0.5);
}

TEST(TrialTest, PassiveDropLandsDropsAndSettlesHoldingTheMass) {
  const TrialResult r = run_passive({});
  const TrialSummary& s = r.summary;
  ASSERT_EQ(s.status, "ok") << s.message;

  // the mass lands after falling 14 cm: sqrt(2 h / g) = 0.169 s after the release
  EXPECT_NEAR(s.metric("start_angle_deg"), -36.0, 0.5);
  EXPECT_NEAR(s.metric("impact_time_s") - 1.0, std::sqrt(2 * 0.14 / 9.81), 0.01);

  // the arm drops after the impact, then comes back up and settles below its start
  EXPECT_GT(s.metric("min_angle_time_s"), s.metric("impact_time_s"));
  EXPECT_LT(s.metric("min_angle_deg"), s.metric("start_angle_deg") - 3.0);
  EXPECT_GT(s.metric("final_angle_deg"), s.metric("min_angle_deg") + 3.0);
  EXPECT_LT(s.metric("final_angle_deg"), s.metric("start_angle_deg"));
  EXPECT_NEAR(s.metric("peak_drop_deg"), s.metric("start_angle_deg") - s.metric("min_angle_deg"),
              1e-9);

  // settled: the last 0.5 s hardly move, and the mass is still in the basket (it rides
  // about 0.3 m below the shoulder at 1.0 m)
  const Trajectory& tr = r.trajectory;
  const std::size_t omega = tr.column("omega_deg_s"), ball_z = tr.column("ball_z_m");
  for (std::size_t row = tr.rows() - 50; row < tr.rows(); ++row) {
    EXPECT_LT(std::fabs(tr.at(row, omega)), 20.0) << "row " << row;
  }
  EXPECT_GT(tr.at(tr.rows() - 1, ball_z), 0.75);
  EXPECT_LT(tr.at(tr.rows() - 1, ball_z), 0.90);
}

// Halving the step: the passive drop's angle at fixed times moves by less than 0.25 deg.
// Why that tolerance: Euler in MuJoCo and the zero-order hold of the PAM length in the
// pressure ODE are first order in dt, so the 1 ms error is about the 1 ms - 0.5 ms
// difference; 0.25 deg is 3 % of the ~9 deg drop and a tenth of the reflex effects the
// scenario is used to compare (1-4 deg in a prototype of the arm).
TEST(TrialTest, ConvergesAsTheTimestepHalves) {
  const TrialResult coarse = run_passive({"sim.duration_s=2.0"});
  const TrialResult fine = run_passive({"sim.duration_s=2.0", "sim.timestep_s=0.0005"});
  ASSERT_EQ(coarse.summary.status, "ok");
  ASSERT_EQ(fine.summary.status, "ok");
  for (double t : {1.15, 1.2, 1.25, 1.3, 1.4, 1.6, 1.9}) {
    EXPECT_NEAR(angle_at(coarse.trajectory, t), angle_at(fine.trajectory, t), 0.25) << "t " << t;
  }
  EXPECT_NEAR(coarse.summary.metric("min_angle_deg"), fine.summary.metric("min_angle_deg"), 0.25);
}

TEST(TrialTest, SameSeedGivesBitIdenticalTrajectories) {
  const Scenario sc = load_scenario(kPassive, {"sim.duration_s=1.5", "reflex.enabled=true"});
  const TrialModel arm = load_trial_model(sc);
  const TrialResult a = run_trial(arm, sc, 7);
  const TrialResult b = run_trial(arm, sc, 7);
  ASSERT_EQ(a.trajectory.values.size(), b.trajectory.values.size());
  EXPECT_EQ(0, std::memcmp(a.trajectory.values.data(), b.trajectory.values.data(),
                           a.trajectory.values.size() * sizeof(double)));
}

TEST(TrialTest, EightTrialsOnTwoThreadsEqualOneThread) {
  const Scenario sc = load_scenario(kPassive, {"sim.duration_s=1.4", "reflex.enabled=true"});
  const TrialModel arm = load_trial_model(sc);
  const auto one = run_trials(arm, sc, 8, 1);
  const auto two = run_trials(arm, sc, 8, 2);
  ASSERT_EQ(one.size(), 8u);
  ASSERT_EQ(two.size(), 8u);
  for (int k = 0; k < 8; ++k) {
    EXPECT_EQ(one[k].summary.seed, sc.seed + k);
    EXPECT_EQ(two[k].summary.seed, sc.seed + k);
    const auto& va = one[k].trajectory.values;
    const auto& vb = two[k].trajectory.values;
    ASSERT_EQ(va.size(), vb.size());
    EXPECT_EQ(0, std::memcmp(va.data(), vb.data(), va.size() * sizeof(double))) << "trial " << k;
  }
  // different seeds see different sensor noise
  EXPECT_NE(0, std::memcmp(one[0].trajectory.values.data(), one[1].trajectory.values.data(),
                           one[0].trajectory.values.size() * sizeof(double)));
}

// Records what it is shown, every `period_s` of simulated time, and nothing else.
class RecordingObserver : public TrialObserver {
 public:
  explicit RecordingObserver(double period_s) : period_s_(period_s) {}
  double next_observation_time_s() const override { return period_s_ * times_s.size(); }
  void observe(const TrialSnapshot& snapshot) override {
    times_s.push_back(snapshot.time_s);
    angles_deg.push_back(snapshot.joint_position_deg_or_mm);
    any_reflex = any_reflex || (*snapshot.channel_values)[0][0] != 0.0;  // reflex_ (Ia)
    first_trigger_s = snapshot.first_trigger_s;
  }
  std::vector<double> times_s;
  std::vector<double> angles_deg;
  bool any_reflex = false;
  double first_trigger_s = std::nan("");

 private:
  double period_s_;
};

TEST(TrialTest, ObserverSeesItsTimesAndChangesNothing) {
  const Scenario sc = load_scenario(kPassive, {"sim.duration_s=1.5", "reflex.enabled=true"});
  const TrialModel arm = load_trial_model(sc);
  RecordingObserver observer(0.1);
  TrialOptions options;
  options.observer = &observer;
  const TrialResult watched = run_trial(arm, sc, 3, options);
  const TrialResult alone = run_trial(arm, sc, 3);

  // the initial state, then the first step at or after each multiple of 0.1 s, up to 1.5 s
  ASSERT_EQ(observer.times_s.size(), 16u);
  for (std::size_t k = 0; k < observer.times_s.size(); ++k) {
    EXPECT_NEAR(observer.times_s[k], 0.1 * k, 1e-9) << k;  // 0.1 s is a whole 100 steps
  }
  EXPECT_NEAR(observer.angles_deg.front(), -36.0, 0.5);
  EXPECT_TRUE(observer.any_reflex) << "the reflex fires after the impact at 1.17 s";
  // the first trigger, as the summary has it (the video marks it)
  double first = std::nan("");
  for (const Metric& m : watched.summary.metrics) {
    if (m.name == "first_trigger_time_s") first = m.value;
  }
  ASSERT_TRUE(std::isfinite(first));
  EXPECT_EQ(observer.first_trigger_s, first);

  // bit-identical physics with and without the observer
  const auto& va = watched.trajectory.values;
  const auto& vb = alone.trajectory.values;
  ASSERT_EQ(va.size(), vb.size());
  EXPECT_EQ(0, std::memcmp(va.data(), vb.data(), va.size() * sizeof(double)));
}

}  // namespace
}  // namespace pamsim

namespace pamsim {
namespace {

const std::string kReflex = std::string(PAMSIM_SOURCE_DIR) + "/scenarios/drop_mass.toml";

// Stepped with no commands until done, a trial is run_trial's, bit for bit (summary metrics
// and every logged value), with the stretch-reflex controller deciding.
TEST(SteppedTrialTest, SteppingWithTheScenariosControllerReproducesRunTrial) {
  const Scenario sc = load_scenario(kReflex, {"sim.duration_s=1.5", "drop.time_s=0.3"});
  const TrialModel arm = load_trial_model(sc);
  const TrialResult ran = run_trial(arm, sc, 7);
  SteppedTrial stepped(arm, sc, 7);
  long periods = 0;
  double last_time = -1;
  while (stepped.step()) {
    const TrialObservation o = stepped.observe();
    EXPECT_GT(o.time_s, last_time);
    last_time = o.time_s;
    ++periods;
  }
  const TrialResult mine = stepped.finish();
  EXPECT_EQ(periods + 1, static_cast<long>(ran.trajectory.rows()));  // one row per period
  ASSERT_EQ(mine.trajectory.columns, ran.trajectory.columns);
  ASSERT_EQ(mine.trajectory.values.size(), ran.trajectory.values.size());
  EXPECT_EQ(std::memcmp(mine.trajectory.values.data(), ran.trajectory.values.data(),
                        ran.trajectory.values.size() * sizeof(double)),
            0);
  ASSERT_EQ(mine.summary.metrics.size(), ran.summary.metrics.size());
  for (std::size_t k = 0; k < ran.summary.metrics.size(); ++k) {
    if (is_timing_metric(ran.summary.metrics[k].name)) continue;
    const double a = mine.summary.metrics[k].value, b = ran.summary.metrics[k].value;
    EXPECT_TRUE(a == b || (std::isnan(a) && std::isnan(b))) << ran.summary.metrics[k].name;
  }
  // reset runs it again from the start
  stepped.reset(7);
  while (stepped.step()) {
  }
  const TrialResult again = stepped.finish();
  EXPECT_EQ(std::memcmp(again.trajectory.values.data(), ran.trajectory.values.data(),
                        ran.trajectory.values.size() * sizeof(double)),
            0);
}

// A stepped trial may move between threads (a thread pool steps it, as ThreadedVectorEnv
// does): reset on a thread that then exits, and stepped on this one, beside a run_trial
// here, it is still run_trial's trial bit for bit (it owns its data; under ASan a borrow
// from the exited thread would be a use after free).
TEST(SteppedTrialTest, ATrialResetOnAnotherThreadRunsOnThisOne) {
  const Scenario sc = load_scenario(kReflex, {"sim.duration_s=1.2", "drop.time_s=0.3"});
  const TrialModel arm = load_trial_model(sc);
  const TrialResult ran = run_trial(arm, sc, 3);
  SteppedTrial stepped(arm, sc, 1);
  std::thread([&] { stepped.reset(3); }).join();
  stepped.step();
  const TrialResult beside = run_trial(arm, sc, 3);  // this thread's data, while it runs
  while (stepped.step()) {
  }
  const TrialResult mine = stepped.finish();
  ASSERT_EQ(mine.trajectory.values.size(), ran.trajectory.values.size());
  EXPECT_EQ(std::memcmp(mine.trajectory.values.data(), ran.trajectory.values.data(),
                        ran.trajectory.values.size() * sizeof(double)),
            0);
  EXPECT_EQ(std::memcmp(beside.trajectory.values.data(), ran.trajectory.values.data(),
                        ran.trajectory.values.size() * sizeof(double)),
            0);
}

// Commands given to step() are the valve commands in force, and logged as such.
TEST(SteppedTrialTest, CommandsReplaceTheControllersAndAreChecked) {
  const Scenario sc =
      load_scenario(kReflex, {"sim.duration_s=0.2", "drop.time_s=0.1", "drop.enabled=false"});
  const TrialModel arm = load_trial_model(sc);
  SteppedTrial stepped(arm, sc, 1);
  const std::vector<double> commands = {0.45e6, 0.3e6};  // each muscle its own
  ASSERT_EQ(arm.muscles.size(), commands.size());
  for (int k = 0; k < 20 && stepped.step(&commands); ++k) {
    EXPECT_EQ(stepped.observe().command_pa, commands) << "tick " << k;
  }
  const std::vector<double> too_few(arm.muscles.size() - 1, 0.4e6);
  EXPECT_THROW(stepped.step(&too_few), InputError);
  const TrialResult r = stepped.finish();
  const std::size_t p_cmd = r.trajectory.column("p_cmd_" + arm.muscles[0].label + "_MPa");
  EXPECT_EQ(r.trajectory.at(5, p_cmd), 0.45);
  const std::size_t other = r.trajectory.column("p_cmd_" + arm.muscles[1].label + "_MPa");
  EXPECT_EQ(r.trajectory.at(5, other), 0.3);
}

}  // namespace
}  // namespace pamsim
