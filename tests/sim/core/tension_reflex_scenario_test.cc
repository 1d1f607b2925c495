// tension_reflex_scenario_test.cc: the tension (Ib) reflex through scenarios: on the paper's
// drop an Ib reflex sized above its tension never fires and the
// trial is bit for bit the Ia trial; on the heavier drop Ia + Ib keeps the agonist's peak
// pull below Ia alone's and keeps the mass, Ib alone unloads it further and drops further;
// the peak-tension metric bounds every logged pull; the kinds' keys are their own (an Ia
// key with "tension_reflex", a missing or negative Ib threshold: one line naming the key).
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "base/input_error.h"
#include "sim/core/trial.h"
#include "sim/core/trial_model.h"
#include "sim/scenario/scenario_file.h"
#include "sim/sweep/sweep.h"
#include "sim/scenario_errors.h"

namespace pamsim {
namespace {

using pamsim_test::kScenarios;

TrialResult run(const std::string& file, const std::vector<std::string>& overrides = {},
                std::uint64_t seed = 3) {
  const Scenario sc = load_scenario(kScenarios + file, overrides);
  const TrialModel model = load_trial_model(sc);
  return run_trial(model, sc, seed);
}

const std::vector<std::string> kSilentIb = {"controller.kind=\"stretch_tension_reflex\"",
                                            "reflex.ib.f_thr_N=60", "reflex.ib.df_thr_N_s=600",
                                            "reflex.ib.k_MPa_per_N=0.004",
                                            "metrics=[\"drop\", \"reflex\", \"tension\"]"};

TEST(TensionReflexScenarioTest, OnThePapersDropASilentIbReflexChangesNothing) {
  const TrialResult ia = run("drop_mass.toml", {"metrics=[\"drop\", \"reflex\", \"tension\"]"});
  const TrialResult both = run("drop_mass.toml", kSilentIb);
  ASSERT_EQ(ia.summary.status, "ok");
  EXPECT_EQ(both.summary.metric("tension_triggers_ago"), 0.0);
  // the Ia trial's columns bit for bit; the Ib windows' columns (the Ia kind has none) zero
  ASSERT_EQ(ia.trajectory.rows(), both.trajectory.rows());
  for (std::size_t c = 0; c < both.trajectory.columns.size(); ++c) {
    const std::string& name = both.trajectory.columns[c];
    const bool ib_column = name.rfind("tension_reflex_", 0) == 0;
    ASSERT_EQ(ia.trajectory.has_column(name), !ib_column) << name;
    for (std::size_t row = 0; row < both.trajectory.rows(); ++row) {
      const double expected = ib_column ? 0.0 : ia.trajectory.at(row, ia.trajectory.column(name));
      ASSERT_EQ(both.trajectory.at(row, c), expected) << name << " row " << row;
    }
  }
  EXPECT_EQ(ia.summary.metric("peak_tension_ago_N"), both.summary.metric("peak_tension_ago_N"));
}

TEST(TensionReflexScenarioTest, OnTheHeavierDropIbUnloadsTheLineAndTheArmStillKeepsTheMass) {
  const TrialResult ia = run("drop_mass_heavy.toml");
  const TrialResult both = run("drop_mass_heavy_ia_ib.toml");
  const TrialResult ib = run("drop_mass_heavy_ib.toml");
  for (const TrialResult* r : {&ia, &both, &ib}) {
    ASSERT_EQ(r->summary.status, "ok");
    EXPECT_EQ(r->summary.metric("mass_retained"), 1.0);
  }
  const auto peak = [](const TrialResult& r) { return r.summary.metric("peak_tension_ago_N"); };
  const auto drop = [](const TrialResult& r) { return r.summary.metric("peak_drop_deg"); };
  EXPECT_GT(both.summary.metric("tension_triggers_ago"), 0.0);
  EXPECT_LT(peak(both), peak(ia) - 10.0) << "Ib takes the Ia reflex's extra pull off the line";
  EXPECT_LT(peak(ib), peak(both));
  EXPECT_GT(drop(both), drop(ia)) << "and pays for it in drop";
  EXPECT_GT(drop(ib), drop(both));
  // the agonist's line's 100 N working limit: Ia alone over it, Ia + Ib under
  EXPECT_DOUBLE_EQ(ia.summary.metric("line_load_ago_pct"), peak(ia));
  EXPECT_GT(ia.summary.metric("line_load_ago_pct"), 100.0);
  EXPECT_LT(both.summary.metric("line_load_ago_pct"), 100.0);
  // (at 100 N the per cent reads as newtons; another limit shows the division)
  const TrialResult at_80 = run("drop_mass_heavy.toml", {"muscles.agonist.line_limit_N=80"});
  EXPECT_DOUBLE_EQ(at_80.summary.metric("line_load_ago_pct"), 100.0 * peak(ia) / 80.0);
  // the metric is the largest pull of any physics step: at least every logged sample
  const Trajectory& log = both.trajectory;
  const std::size_t column = log.column("force_ago_N");
  for (std::size_t row = 0; row < log.rows(); ++row) {
    ASSERT_LE(log.at(row, column), peak(both)) << row;
  }
}

// The log's tension_reflex_<m> column marks the Ib windows: it opens at the first Ib
// trigger and stays open for the window (0.2 s at 100 Hz: 20 rows); a kind without the Ib
// reflex logs no such column
TEST(TensionReflexScenarioTest, TheLogMarksTheIbWindowFromItsFirstTrigger) {
  const TrialResult ia = run("drop_mass_heavy.toml");
  const TrialResult both = run("drop_mass_heavy_ia_ib.toml");
  EXPECT_FALSE(ia.trajectory.has_column("tension_reflex_ago"));
  const Trajectory& log = both.trajectory;
  const std::size_t time = log.column("time_s"), window = log.column("tension_reflex_ago");
  std::size_t first = log.rows();
  for (std::size_t row = 0; row < log.rows() && first == log.rows(); ++row) {
    if (log.at(row, window) == 1.0) first = row;
  }
  ASSERT_LE(first + 20, log.rows()) << "no Ib window logged, or too late";
  EXPECT_EQ(log.at(first, time), both.summary.metric("first_tension_trigger_time_s"));
  for (std::size_t row = first; row < first + 20; ++row) {
    ASSERT_EQ(log.at(row, window), 1.0) << row;
  }
  EXPECT_EQ(log.at(log.rows() - 1, window), 0.0) << "the window closes";
}

// What an observer (the video) is shown: the Ib windows beside the Ia ones, as the log has
// them; and watching a trial changes none of its bits
class IbWatcher : public TrialObserver {
 public:
  double next_observation_time_s() const override { return 0.01 * shown; }
  void observe(const TrialSnapshot& snapshot) override {
    ++shown;
    // the controller's channels: reflex_ (Ia windows), then tension_reflex_ (Ib windows)
    if (snapshot.channel_values && snapshot.channel_values->size() == 2 &&
        (*snapshot.channel_values)[1][0] != 0.0) {
      ++ib_open;
    }
  }
  int shown = 0, ib_open = 0;
};

TEST(TensionReflexScenarioTest, AnObserverSeesTheIbWindowsAndChangesNothing) {
  const Scenario sc = load_scenario(kScenarios + "drop_mass_heavy_ia_ib.toml");
  const TrialModel model = load_trial_model(sc);
  IbWatcher watcher;
  TrialOptions options;
  options.observer = &watcher;
  const TrialResult watched = run_trial(model, sc, 3, options);
  EXPECT_GE(watcher.ib_open, 15) << "the 0.2 s window, seen every 10 ms";
  EXPECT_EQ(watched.trajectory.values, run("drop_mass_heavy_ia_ib.toml").trajectory.values);
}

// The shipped sweep of both gains reads: 12 x 12 points of the two gains, 3 seeds each
TEST(TensionReflexScenarioTest, TheGainSweepIsAGridOfValidScenarios) {
  const SweepDefinition sweep = load_sweep(kScenarios + "sweep_ia_ib.toml");
  EXPECT_EQ(sweep.trials(), 12 * 12 * 3);
  ASSERT_EQ(sweep.axes.size(), 2u);
  EXPECT_EQ(sweep.axes[1].key, "reflex.ib.k_MPa_per_N");
}

TEST(TensionReflexScenarioTest, EachKindReadsItsOwnKeysAndNamesABadOne) {
  pamsim_test::expect_each_named(
      "drop_mass_heavy_ia_ib.toml",
      {{{"reflex.ib.f_thr_N=-5"}, "reflex.ib.f_thr_N must be in (0, inf) N, got -5"},
       {{"reflex.ib.mode=\"hold\""}, "reflex.ib.mode"},
       {{"reflex.pairs=[[\"agonist\", \"agonist\"]]"}, "reflex.pairs"},
       {{"muscles.agonist.line_limit_N=0"},
        "muscles.agonist.line_limit_N must be in (0, 100000] N"},
       {{"muscles.agonist.line_limit_N=nan"}, "muscles.agonist.line_limit_N"}});
  pamsim_test::expect_each_named(
      "drop_mass.toml",
      {{{"controller.kind=\"stretch_tension_reflex\"", "reflex.ib.k_MPa_per_N=0.004"},
        "reflex.ib.f_thr_N is required"},
       {{"reflex.ib.f_thr_N=60"}, "reflex.ib.f_thr_N"},  // the Ia kind: an unknown key
       {{"muscles.agonist.line_limit_N=100"},            // no tension set to read it
        "muscles.agonist.line_limit_N needs the metric set \"tension\""}});
  pamsim_test::expect_each_named(
      "drop_mass_heavy_ib.toml",
      {{{"reflex.v_thr_mm_s=70"}, "reflex.v_thr_mm_s"}});  // an Ia key with the Ib kind
}

}  // namespace
}  // namespace pamsim
