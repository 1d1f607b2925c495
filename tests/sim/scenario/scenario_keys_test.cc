// scenario_keys_test.cc: the keys of the experiment-agnostic scenario (muscles, schedules,
// bodies, holds, events, controller, metrics, valve ranges, reflex pairs, the joint): every
// bad value is refused with one line naming the file and the key, whether it is caught when
// the file is read or when the model is bound; shorthands keep their meaning.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "base/input_error.h"
#include "sim/core/trial_model.h"
#include "sim/scenario/scenario_file.h"
#include "sim/scenario_errors.h"

namespace pamsim {
namespace {

using pamsim_test::BadValue;
using pamsim_test::error_of;
using pamsim_test::expect_each_named;
using pamsim_test::kScenarios;

TEST(ScenarioKeysTest, ShippedExperimentsLoad) {
  for (const char* name : {"pulley_sine_5kg.toml", "pulley_sine_10kg.toml", "reaching.toml"}) {
    EXPECT_EQ(error_of(name, {}), "") << name;
  }
  const Scenario pulley = load_scenario(kScenarios + "pulley_sine_5kg.toml");
  ASSERT_EQ(pulley.muscles.size(), 1u);
  EXPECT_EQ(pulley.muscles[0].command.kind, ScheduleKind::kSine);
  EXPECT_DOUBLE_EQ(pulley.muscles[0].command.at(1.25), 0.8e6);
  EXPECT_EQ(pulley.controller_kind, "none");
  EXPECT_TRUE(pulley.controller_channels().empty());
  EXPECT_FALSE(pulley.controller_records("stretch_trigger"));
  const Scenario reaching = load_scenario(kScenarios + "reaching.toml");
  EXPECT_EQ(reaching.muscle("agonist")->label, "ago");
  EXPECT_DOUBLE_EQ(reaching.muscle("antagonist")->command.at(14.0), 0.2e6);
}

TEST(ScenarioKeysTest, MuscleAndScheduleKeysNameTheirKey) {
  const std::string c = "muscles.agonist.command";
  expect_each_named(
      "reaching.toml",
      {
          {{c + ".kind=\"square\""}, c + ".kind"},
          {{c + ".kind=\"sine\""}, c + ".offset_MPa"},  // a sine needs its own fields
          {{c + ".to_MPa=\"high\""}, c + ".to_MPa"},
          {{c + ".to_MPa=nan"}, c},
          {{c + ".to_MPa=0.9"}, c},  // above the 0.7 MPa supply
          {{c + ".from_MPa=-0.1"}, c},
          {{c + ".duration_s=0"}, c + ".duration_s"},
          {{c + ".duration_s=-12"}, c + ".duration_s"},
          {{c + ".start_s=inf"}, c},
          {{c + ".shape=1"}, c + ".shape"},  // an unknown key
          {{c + "={ kind = \"steps\", times_s = [0, 1], MPa = [0.2] }"}, c + ".MPa"},
          {{c + "={ kind = \"steps\", times_s = [1, 0], MPa = [0.2, 0.3] }"}, c + ".times_s"},
          {{c + "={ kind = \"table\" }"}, c + ".file"},
          {{c + "={ kind = \"table\", file = \"missing.csv\" }"}, "missing.csv"},
          {{c + "={ kind = \"sine\", offset_MPa = 0.4, amplitude_MPa = 0.1, period_s = 0 }"},
           c + ".period_s"},
          {{c + "=0.6"}, c + " must be a table"},
          {{"muscles.agonist.label=\"a b\""}, "muscles.agonist.label"},
          {{"muscles.agonist.label=\"anta\""}, "muscles.antagonist.label"},  // repeated
          {{"muscles.agonist.line=\"loose\""}, "muscles.agonist.line"},
          {{"muscles.agonist.line_mm=0"}, "muscles.agonist.line_mm"},
          {{"muscles.agonist.line_diameter_mm=0", "muscles.agonist.line_modulus_MPa=2500"},
           "muscles.agonist.line_diameter_mm must be in (0, 10] mm, got 0"},
          {{"muscles.agonist.line_diameter_mm=nan", "muscles.agonist.line_modulus_MPa=2500"},
           "muscles.agonist.line_diameter_mm"},
          {{"muscles.agonist.line_diameter_mm=0.5", "muscles.agonist.line_modulus_MPa=-1"},
           "muscles.agonist.line_modulus_MPa"},
          {{"muscles.agonist.line_diameter_mm=0.5"},
           "muscles.agonist.line_modulus_MPa is required"},
          {{"muscles.agonist.line_modulus_MPa=2500"},
           "muscles.agonist.line_diameter_mm is required"},
          {{"muscles.agonist.line_mm=300", "muscles.agonist.line=\"equilibrium\""},
           "muscles.agonist.line"},
          {{"muscles.agonist.params=\"missing.toml\""}, "missing.toml"},
          {{"muscles.agonist.plant=\"missing.toml\""}, "muscles.agonist.plant: "},
          {{"muscles.agonist.plant=3"}, "muscles.agonist.plant"},
          {{"muscles.biceps.command.MPa=0.4"}, "muscles.biceps.params"},
          {{"model.joint=\"elbow\""}, "model.joint"},
          {{"model.joint=\"ball\""}, "model.joint"},  // a free joint
          {{"metrics=[\"speed\"]"}, "metrics"},
          {{"metrics=[\"drop\"]"}, "metrics"},  // no release or impact event
          {{"controller.kind=\"pid\""}, "controller.kind"},
          {{"valve.supply_MPa=0"}, "valve.supply_MPa"},
          {{"valve.supply_MPa=nan"}, "valve.supply_MPa"},
          {{"valve.command_max_MPa=0.9"}, "valve.command_max_MPa"},  // above the supply
          {{"valve.command_max_MPa=-1"}, "valve.command_max_MPa"},
      });
}

// clang-format off
TEST(ScenarioKeysTest, BodyHoldAndEventKeysNameTheirKey) {
  const std::string e = "events.load";
  const std::string add = e + ".action=\"add_mass\"";
  expect_each_named("reaching.toml", {
      {{"bodies.basket.mass_kg=0"}, "bodies.basket.mass_kg"},
      {{"bodies.basket.mass_kg=2000"}, "bodies.basket.mass_kg"},
      {{"bodies.ghost.mass_kg=1"}, "bodies.ghost"},
      {{"bodies.basket.inertia_kg_m2=[1e-4, 1e-4]"}, "bodies.basket.inertia_kg_m2"},
      {{"bodies.basket.inertia_kg_m2=[1e-4, 0, 1e-4]"}, "bodies.basket.inertia_kg_m2"},
      {{"bodies.basket.inertia_kg_m2=[1e-4, nan, 1e-4]"}, "bodies.basket.inertia_kg_m2"},
      {{"bodies.basket.inertia_kg_m2=[1e-4, 1e-4, 3e-4]"}, "bodies.basket.inertia_kg_m2 is no rigid body's"},
      {{"bodies.ghost.inertia_kg_m2=[1e-4, 1e-4, 1e-4]"}, "bodies.ghost"},
      {{"joints.shoulder.damping_N_m_s_per_rad=-0.1"}, "joints.shoulder.damping_N_m_s_per_rad"},
      {{"joints.shoulder.damping_N_m_s_per_rad=nan"}, "joints.shoulder.damping_N_m_s_per_rad"},
      {{"joints.shoulder.frictionloss_N_m=1e5"}, "joints.shoulder.frictionloss_N_m"},
      {{"joints.shoulder.frictionloss_N=1"}, "joints.shoulder gives a slide's keys"},
      {{"joints.shoulder.frictionloss_N=1", "joints.shoulder.frictionloss_N_m=1"},
       "joints.shoulder mixes"},
      {{"joints.shoulder.stiffness=1"}, "joints.shoulder gives none"},
      {{"joints.shoulder.start_deg=400"}, "joints.shoulder.start_deg must be in [-360, 360] deg, got 400"},
      {{"joints.shoulder.start_deg=nan"}, "joints.shoulder.start_deg"},
      {{"joints.shoulder.start_deg=-30"}, "joints.shoulder.start_deg would move the start"},
      {{"joints.shoulder.start_mm=10"}, "joints.shoulder gives a slide's keys"},
      {{"joints.elbow.damping_N_m_s_per_rad=1"}, "joints.elbow names a joint 'elbow'"},
      {{"joints.ball.damping_N_m_s_per_rad=1"}, "joints.ball names joint 'ball'"},   // free
      {{"holds.ball.position_m=[1, 2]"}, "holds.ball.position_m"},
      {{"holds.ball.above_site=\"basket_floor\""}, "holds.ball"},   // and position_m
      {{"holds.arm.height_m=0.1", "holds.arm.above_site=\"basket_floor\""}, "holds.arm"},   // not free
      {{"holds.ghost.position_m=[0, 0, 1]"}, "holds.ghost"},
      {{"holds.ball={ above_site = \"nowhere\", height_m = 0.1 }"}, "holds.ball"},
      {{"holds.ball={ above_site = \"basket_floor\", height_m = -0.1 }"}, "holds.ball.height_m"},
      {{e + ".action=\"explode\"", e + ".when.at_s=1"}, e + ".action"},
      {{add, e + ".body=\"basket\"", e + ".mass_kg=0", e + ".when.at_s=1"}, e + ".mass_kg"},
      {{add, e + ".mass_kg=1", e + ".when.at_s=1"}, e + ".body"},
      {{add, e + ".body=\"ghost\"", e + ".mass_kg=1", e + ".when.at_s=1"}, "ghost"},
      {{add, e + ".body=\"basket\"", e + ".mass_kg=1"}, e + ".when"},
      {{add, e + ".body=\"basket\"", e + ".mass_kg=1", e + ".when.at_s=-1"}, e + ".when.at_s"},
      {{add, e + ".body=\"basket\"", e + ".mass_kg=1", e + ".when.at_s=99"}, e + ".when.at_s"},
      {{add, e + ".body=\"basket\"", e + ".mass_kg=1", e + ".when.at_s=1",
        e + ".when.contact=[\"ball\", \"basket\"]"}, e + ".when"},   // two conditions
      {{"events.end.action=\"end\"", "events.end.when.contact=[\"ball\"]"},
       "events.end.when.contact"},
      {{"events.end.action=\"end\"", "events.end.when.contact=[\"ball\", \"ghost\"]"}, "ghost"},
      {{"events.end.action=\"end\"", "events.end.when.joint=\"shoulder\""}, "events.end.when"},
      {{"events.end.action=\"end\"", "events.end.when.joint=\"elbow\"",
        "events.end.when.below_deg=0"}, "elbow"},
      {{"events.end.action=\"end\"", "events.end.when.body=\"ball\""}, "events.end.when.below_z_m"},
      {{"events.end.action=\"end\"", "events.end.when.at_s=1", "events.end.after=\"nothing\""},
       "events.end.after"},
      {{"events.end.action=\"end\"", "events.end.when.at_s=1", "events.end.after=\"end\""},
       "events.end.after"},
      {{"events.go.action=\"release\"", "events.go.body=\"basket\"", "events.go.when.at_s=1"},
       "events.go.body"},   // no hold holds the basket
  });
}
// clang-format on

// A start key on the calibrated joint is refused when model.joint names it (above) and when
// it is the model's first hinge by default (drop_mass.toml names none)
TEST(ScenarioKeysTest, AStartKeyOnTheDefaultCalibratedJointIsRefused) {
  expect_each_named("drop_mass.toml", {
                                          {{"joints.shoulder.start_deg=-30"},
                                           "joints.shoulder.start_deg would move the start"},
                                      });
}

TEST(ScenarioKeysTest, ReflexPairsNameKnownDistinctMuscles) {
  expect_each_named(
      "drop_mass.toml",
      {
          {{"reflex.pairs=[[\"agonist\", \"biceps\"]]"}, "reflex.pairs"},
          // the controller would clamp a goal above its range: refused, naming the muscle
          {{"controller.p_max_MPa=0.3"}, "muscles.agonist.command goes up to 0.4 MPa"},
          // a [drop] sets the ball's mass already
          {{"bodies.ball.mass_kg=0.3"}, "bodies.ball.mass_kg sets body 'ball', already set by"},
          {{"sensors.gauge_adc_bits=4294967308"}, "sensors.gauge_adc_bits"},
          {{"sensors.pressure_adc_bits=-1"}, "sensors.pressure_adc_bits"},
          {{"reflex.pairs=[[\"agonist\", \"agonist\"]]"},
           "reflex.pairs pairs muscle 'agonist' with itself"},
          {{"reflex.pairs=[[\"agonist\", \"antagonist\"], [\"antagonist\", \"agonist\"]]"},
           "reflex.pairs puts muscle 'antagonist' in two pairs"},
          {{"reflex.pairs=[[\"agonist\"]]"}, "reflex.pairs"},
          {{"reflex.pairs=\"agonist\""}, "reflex.pairs"},
      });
}

// A schedule must stay within the valve's command range (the regulator would clamp it):
// the pulley rig's 0.8 MPa regulator admits its sine, a 0.7 MPa one does not.
TEST(ScenarioKeysTest, SchedulesStayWithinTheValvesRange) {
  EXPECT_EQ(error_of("pulley_sine_5kg.toml", {}), "");
  const std::string message = error_of("pulley_sine_5kg.toml", {"valve.command_max_MPa=0.7"});
  EXPECT_NE(message.find("muscles.pam.command must stay within [0, 0.7] MPa"), std::string::npos)
      << message;
}

TEST(ScenarioKeysTest, AShorthandSetOnTheCommandLineReplacesTheLongForm) {
  const Scenario sc = load_scenario(kScenarios + "reaching.toml", {"pressure.agonist_MPa=0.3"});
  EXPECT_EQ(sc.muscle("agonist")->command.kind, ScheduleKind::kConstant);
  EXPECT_DOUBLE_EQ(sc.muscle("agonist")->command.at(8.0), 0.3e6);
  // the other way round, both would be in play: refused, naming both
  const std::string message = error_of("drop_mass.toml", {"muscles.agonist.command.MPa=0.3"});
  EXPECT_NE(message.find("pressure.agonist_MPa is the shorthand of muscles.agonist.command"),
            std::string::npos)
      << message;
}

// The keys a sweep's best.toml must rebase when it moves a scenario elsewhere.
TEST(ScenarioKeysTest, PathKeysAreTheOnesThatNameFiles) {
  for (const char* key : {"model.file", "model.calibration", "model.pneumatics",
                          "model.agonist_params", "muscles.pam.params", "muscles.pam.plant",
                          "muscles.pam.plant.file", "muscles.pam.command.file"}) {
    EXPECT_TRUE(is_scenario_path_key(key)) << key;
  }
  for (const char* key : {"muscles.pam.label", "muscles.pam.line", "muscles.pam.command.kind",
                          "reflex.v_thr_mm_s", "model.joint", "muscles.plant.label"}) {
    EXPECT_FALSE(is_scenario_path_key(key)) << key;
  }
}

}  // namespace
}  // namespace pamsim
