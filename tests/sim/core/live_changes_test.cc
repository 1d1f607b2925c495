// live_changes_test.cc: a trial changed while it runs (SteppedTrial's live changes, what
// `pamsim view` does) is, bit for bit, the trial of the scenario that holds the same change
// as an event at that time: a drop now is drop.time_s, a reflex switched off is a
// controller_off event, a slider is a `set` event; and a `set` event is the scenario with
// those keys from t = 0. Bad `set` events are refused naming the event's key.
#include <gtest/gtest.h>

#include <cstring>
#include <string>
#include <vector>

#include "base/input_error.h"
#include "base/toml_file.h"
#include "sim/core/trial.h"
#include "sim/scenario/scenario_file.h"

namespace pamsim {
namespace {

const std::string kReflex = std::string(PAMSIM_SOURCE_DIR) + "/scenarios/drop_mass.toml";
const std::vector<std::string> kShort = {"sim.duration_s=1.6", "drop.time_s=0.4"};

std::vector<std::string> with(std::vector<std::string> a, const std::vector<std::string>& b) {
  a.insert(a.end(), b.begin(), b.end());
  return a;
}

void expect_same_trial(const TrialResult& a, const TrialResult& b) {
  ASSERT_EQ(a.trajectory.columns, b.trajectory.columns);
  ASSERT_EQ(a.trajectory.values.size(), b.trajectory.values.size());
  EXPECT_EQ(std::memcmp(a.trajectory.values.data(), b.trajectory.values.data(),
                        a.trajectory.values.size() * sizeof(double)),
            0);
}

// Steps `sc` until its time reaches `at_s`, applies `change`, and steps to the end.
template <typename Change>
TrialResult stepped_with(const Scenario& sc, double at_s, Change change) {
  const TrialModel arm = load_trial_model(sc);
  SteppedTrial trial(arm, sc, 5);
  while (trial.time_s() < at_s - 1e-9) trial.step();
  change(trial);
  while (trial.step()) {
  }
  return trial.finish();
}

TrialResult run(const std::vector<std::string>& overrides) {
  const Scenario sc = load_scenario(kReflex, overrides);
  return run_trial(load_trial_model(sc), sc, 5);
}

double first_trigger(const TrialResult& r) {
  for (const Metric& m : r.summary.metrics) {
    if (m.name == "first_trigger_time_s") return m.value;
  }
  return -1.0;
}

TEST(LiveChangesTest, DropNowIsTheDropAtThatTime) {
  const Scenario sc = load_scenario(kReflex, with(kShort, {"drop.time_s=1.5"}));
  const TrialResult live =
      stepped_with(sc, 0.37, [](SteppedTrial& t) { EXPECT_TRUE(t.fire_event("release")); });
  expect_same_trial(live, run(with(kShort, {"drop.time_s=0.37"})));
}

TEST(LiveChangesTest, ReflexOffIsAControllerOffEvent) {
  const Scenario sc = load_scenario(kReflex, kShort);
  const TrialResult live =
      stepped_with(sc, 0.45, [](SteppedTrial& t) { t.set_controller_enabled(false); });
  const TrialResult held =
      run(with(kShort, {"events.off.action=controller_off", "events.off.when.at_s=0.45"}));
  expect_same_trial(live, held);
  // and it is not the trial with the reflex on (the drop at 0.4 triggers it by then)
  EXPECT_NE(std::memcmp(live.trajectory.values.data(), run(kShort).trajectory.values.data(),
                        live.trajectory.values.size() * sizeof(double)),
            0);
}

TEST(LiveChangesTest, ASliderIsASetEventAndASetAtZeroIsTheKey) {
  const std::vector<std::string> set = {"reflex.v_thr_mm_s=150", "reflex.k_MPa_s_per_mm=0.002"};
  const Scenario sc = load_scenario(kReflex, kShort);
  const auto config =
      load_controller_settings(read_text_file(kReflex), kReflex, kShort, set, "the slider");
  const TrialResult live =
      stepped_with(sc, 0.2, [&](SteppedTrial& t) { t.retune_controller(*config); });
  const TrialResult held = run(with(kShort, {"events.tune.action=set", "events.tune.when.at_s=0.2",
                                             "events.tune.set=[\"reflex.v_thr_mm_s=150\", "
                                             "\"reflex.k_MPa_s_per_mm=0.002\"]"}));
  expect_same_trial(live, held);
  const TrialResult at_zero = run(with(kShort, {"events.tune.action=set", "events.tune.when.at_s=0",
                                                "events.tune.set=[\"reflex.v_thr_mm_s=150\", "
                                                "\"reflex.k_MPa_s_per_mm=0.002\"]"}));
  expect_same_trial(at_zero, run(with(kShort, set)));
}

// The threshold a set event gives is the one the next trigger uses: raised past the drop's
// stretch velocity, the reflex no longer triggers; lowered, it triggers no later.
TEST(LiveChangesTest, TheNextTriggerUsesTheNewThreshold) {
  const double base = first_trigger(run(kShort));
  ASSERT_GT(base, 0.4);
  const auto set_at = [](double at_s, const std::string& v_thr) {
    return std::vector<std::string>{"events.t.action=set",
                                    "events.t.when.at_s=" + std::to_string(at_s),
                                    "events.t.set=[\"reflex.v_thr_mm_s=" + v_thr + "\"]"};
  };
  EXPECT_TRUE(std::isnan(first_trigger(run(with(kShort, set_at(0.3, "5000"))))) ||
              first_trigger(run(with(kShort, set_at(0.3, "5000")))) > base);
  EXPECT_LE(first_trigger(run(with(kShort, set_at(0.3, "20")))), base);
}

TEST(LiveChangesTest, BadSetEventsAreRefusedNamingTheEvent) {
  const auto refusal = [](const std::vector<std::string>& overrides,
                          const std::string& path = kReflex) {
    try {
      load_scenario(path, path == kReflex ? with(kShort, overrides) : overrides);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  const std::vector<std::string> at = {"events.s.action=set", "events.s.when.at_s=0.5"};
  EXPECT_NE(refusal(at).find("events.s.set is required"), std::string::npos) << refusal(at);
  const std::string sensor = refusal(with(at, {"events.s.set=[\"reflex.sensor=fiber\"]"}));
  EXPECT_NE(sensor.find("events.s.set sets reflex.sensor, which cannot change during a trial"),
            std::string::npos)
      << sensor;
  EXPECT_NE(sensor.find("reflex.v_thr_mm_s"), std::string::npos) << sensor;  // what can
  const std::string negative = refusal(with(at, {"events.s.set=[\"reflex.v_thr_mm_s=-3\"]"}));
  EXPECT_NE(negative.find("events.s.set is refused"), std::string::npos) << negative;
  EXPECT_NE(negative.find("reflex.v_thr_mm_s"), std::string::npos) << negative;
  const std::string none = refusal(with(at, {"events.s.set=[\"reflex.v_thr_mm_s=3\"]"}),
                                   std::string(PAMSIM_SOURCE_DIR) + "/scenarios/reaching.toml");
  EXPECT_NE(none.find("lets none"), std::string::npos) << none;
}

TEST(LiveChangesTest, AnEventFiresOnceAndAnUnknownOneIsRefused) {
  const Scenario sc = load_scenario(kReflex, kShort);
  const TrialModel arm = load_trial_model(sc);
  SteppedTrial trial(arm, sc, 1);
  EXPECT_TRUE(trial.fire_event("release"));
  EXPECT_FALSE(trial.fire_event("release"));
  EXPECT_THROW(trial.fire_event("no_such_event"), InputError);
}

}  // namespace
}  // namespace pamsim
