// scenario_key_tables_test.cc: [sim], the drop's numbers, [valve], joints.<joint>, bodies.<body>,
// holds.<body>, muscles.<actuator>'s line keys and events.<event>
// (scenario_key_tables.h) through the scenario reader: every key the reader asks for under sim. and
// drop. (the drop's names aside) has exactly one row and every row is read; a bad value of every
// row, generated from the row, is refused in one line naming the scenario file and the key; a value
// reaches its field; and what joins keys (the steps a trial takes, a drop before the end) is still
// refused.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "base/config_reader.h"
#include "base/input_error.h"
#include "base/key_table_test_util.h"
#include "base/units.h"
#include "sim/scenario/scenario_file.h"
#include "sim/scenario/scenario_key_tables.h"
#include "sim/test_paths.h"

namespace pamsim {
namespace {

using pamsim_test::kDropMass;

std::vector<KeyTable> tables(Scenario* sc, double* max_steps, DropShorthand* drop) {
  return {sim_key_table(sc, max_steps), drop_key_table(drop)};
}

TEST(TimeAndDropKeysTest, EveryKeyTheReaderAsksForHasExactlyOneRow) {
  Scenario sc;
  double max_steps = kDefaultMaxSteps;
  DropShorthand drop;
  std::set<std::string> asked;
  for (const ScenarioKeyValue& kv : scenario_key_values(kDropMass, {})) {
    const std::string table = split_key(kv.key).front();
    if (table == "sim" || table == "drop") asked.insert(kv.key);
  }
  expect_rows_are_the_asked_keys(row_keys(tables(&sc, &max_steps, &drop)), asked);
  EXPECT_EQ(asked.size(), 12u) << "the drop's names (body, basket, site) are rows too";
}

TEST(TimeAndDropKeysTest, EveryRowRefusesABadValueNamingTheFileAndTheKey) {
  Scenario sc;
  double max_steps = kDefaultMaxSteps;
  DropShorthand drop;
  int refused = 0;
  const auto expect_refused = [&](const std::string& key, const std::string& value) {
    const InputErrorParts parts =
        refusal_parts([&] { load_scenario(kDropMass, {key + "=" + value}); }, key + " = " + value);
    EXPECT_EQ(parts.key, key) << value;
    EXPECT_EQ(parts.file, kDropMass) << key;
    ++refused;
  };
  for (const KeyTable& t : tables(&sc, &max_steps, &drop)) {
    for (const NumberRow& row : t.numbers) {
      for (const std::string& value : bad_number_texts(row)) {
        expect_refused(t.name + "." + row.name, value);
      }
    }
    for (const BoolRow& row : t.bools) {
      for (const char* value : {"1", "\"x\""}) expect_refused(t.name + "." + row.name, value);
    }
    for (const TextRow& row : t.texts) {
      for (const char* value : {"1", "true"}) expect_refused(t.name + "." + row.name, value);
    }
  }
  EXPECT_GE(refused, 41);
}

TEST(TopLevelScenarioKeysTest, TheSeedIsARowThatRefusesItsBadValuesAndReachesTheScenario) {
  Scenario sc;
  const KeyTable table = top_level_key_table(&sc);
  ASSERT_EQ(table.ints.size(), 1u);
  for (const std::string& value : bad_int_texts(table.ints[0])) {
    const InputErrorParts parts =
        refusal_parts([&] { load_scenario(kDropMass, {"seed=" + value}); }, "seed = " + value);
    EXPECT_EQ(parts.key, "seed") << value;
    EXPECT_EQ(parts.file, kDropMass) << value;
  }
  EXPECT_EQ(load_scenario(kDropMass, {"seed=7"}).seed, 7u);
}

TEST(TimeAndDropKeysTest, AValueReachesItsFieldAndWhatJoinsKeysIsStillChecked) {
  const Scenario sc =
      load_scenario(kDropMass, {"sim.timestep_s=0.0005", "sim.control_hz=200", "drop.mass_kg=0.3",
                                "drop.height_m=0.1", "drop.time_s=1.5"});
  EXPECT_EQ(sc.timestep_s, 0.0005);
  EXPECT_EQ(sc.control_hz, 200.0);
  ASSERT_FALSE(sc.body_masses.empty());
  EXPECT_EQ(sc.body_masses.back().mass_kg, 0.3);
  const EventSpec* release = sc.event("release");
  ASSERT_NE(release, nullptr);
  EXPECT_EQ(release->when.at_s, 1.5);
  // 3 s at 0.1 ms is 30000 steps: more than a max_steps of 1000
  const auto refused_key = [](const std::vector<std::string>& overrides) {
    return refusal_parts([&] { load_scenario(kDropMass, overrides); }, overrides.back()).key;
  };
  EXPECT_EQ(refused_key({"sim.timestep_s=0.0001", "sim.max_steps=1000"}), "sim.timestep_s");
  EXPECT_EQ(refused_key({"sim.control_hz=300"}), "sim.control_hz");  // 1 kHz / 300
  EXPECT_EQ(refused_key({"drop.time_s=3.0"}), "drop.time_s");        // at the trial's end
}

// valve.model = "regulator" and each of the tables' keys at its default: the reader then
// asks for every valve key
std::vector<std::string> every_valve_key(const std::vector<KeyTable>& valve) {
  std::vector<std::string> overrides = {"valve.model=\"regulator\""};
  for (const KeyTable& t : valve) {
    for (const NumberRow& row : t.numbers) {
      overrides.push_back("valve." + row.name + "=" + format_number(file_value(t, row.name)));
    }
    for (const ChoiceRow& row : t.choices) {
      overrides.push_back("valve." + row.name + "=\"" + row.get() + "\"");
    }
  }
  return overrides;
}

TEST(ValveKeysTest, EveryValveKeyTheReaderAsksForIsOneRowOfThePneumaticsFile) {
  PneumaticParams p = load_scenario(kDropMass).pneumatics;  // the file's values
  const std::vector<KeyTable> valve = valve_key_tables(&p);
  std::set<std::string> asked;
  for (const ScenarioKeyValue& kv : scenario_key_values(kDropMass, every_valve_key(valve))) {
    if (split_key(kv.key).front() == "valve" && kv.key != "valve.model") asked.insert(kv.key);
  }
  expect_rows_are_the_asked_keys(row_keys(valve), asked);
  EXPECT_EQ(asked.size(), key_names(valve.at(1)).size() + 2);  // the supply, the command's max
  // given at the file's own values, the keys change nothing
  const PneumaticParams read = load_scenario(kDropMass, every_valve_key(valve)).pneumatics;
  EXPECT_EQ(read.regulator_dead_time_s, p.regulator_dead_time_s);
  EXPECT_EQ(read.tube_conductance_m3_per_s_pa, p.tube_conductance_m3_per_s_pa);
  EXPECT_EQ(read.supply_gauge_pa, p.supply_gauge_pa);
}

TEST(ValveKeysTest, EveryRowRefusesABadValueAndARegulatorKeyWantsTheRegulator) {
  PneumaticParams p;
  const std::vector<KeyTable> tables = valve_key_tables(&p);
  KeyTable valve = tables.at(1);  // the regulator's rows, then the rig's
  valve.numbers.insert(valve.numbers.end(), tables.at(0).numbers.begin(),
                       tables.at(0).numbers.end());
  int refused = 0;
  for (const NumberRow& row : valve.numbers) {
    const std::string key = "valve." + row.name;
    for (const std::string& value : bad_number_texts(row)) {
      const InputErrorParts parts = refusal_parts(
          [&] {
            load_scenario(kDropMass, {"valve.model=\"regulator\"", key + "=" + value});
          },
          key + " = " + value);
      EXPECT_EQ(parts.key, key) << value;
      EXPECT_EQ(parts.file, kDropMass) << key;
      ++refused;
    }
  }
  for (const ChoiceRow& row : valve.choices) {
    const std::string key = "valve." + row.name;
    EXPECT_EQ(refusal_parts(
                  [&] {
                    load_scenario(kDropMass, {"valve.model=\"regulator\"", key + "=\"neither\""});
                  },
                  key)
                  .key,
              key);
  }
  EXPECT_GE(refused, 5 * static_cast<int>(valve.numbers.size()));
  // a regulator key with another valve model, which would ignore it
  for (const std::string& key : key_names(tables.at(1))) {
    const InputErrorParts parts = refusal_parts(
        [&] {
          load_scenario(kDropMass, {"valve.model=\"iso6358\"", key + "=1"});
        },
        key);
    EXPECT_EQ(parts.key, key);
    EXPECT_NE(parts.problem.find("valve.model = \"regulator\""), std::string::npos) << key;
  }
}

// joints.<joint>.*: every row of a hinge (the arm's shoulder) and of a slide (the leg's trunk)
// refuses its bad values naming the key; a given value reaches its field, in SI; the other
// kind's key is refused.
TEST(JointKeysTest, EveryRowRefusesABadValueAndAValueReachesItsField) {
  JointSpec defaults;
  const std::string landing = pamsim_test::kScenarios + "landing.toml";
  int refused = 0;
  const std::pair<KeyTable, std::pair<std::string, std::string>> cases[] = {
      {hinge_key_table(&defaults), {kDropMass, "joints.shoulder"}},
      {slide_key_table(&defaults), {landing, "joints.trunk_z"}}};
  for (const auto& [table, where] : cases) {
    const std::string scenario = where.first, prefix = where.second;  // (lambdas capture them)
    for (const NumberRow& row : table.numbers) {
      const std::string key = prefix + "." + row.name;
      for (const std::string& value : bad_number_texts(row)) {
        const InputErrorParts parts =
            refusal_parts([&] { load_scenario(scenario, {key + "=" + value}); }, key + value);
        EXPECT_EQ(parts.key, key) << value;
        ++refused;
      }
    }
  }
  EXPECT_EQ(refused, 6 * 5);
  const Scenario arm = load_scenario(
      kDropMass, {"joints.shoulder.start_deg=-5", "joints.shoulder.frictionloss_N_m=0.02"});
  ASSERT_EQ(arm.joints.size(), 1u);
  EXPECT_TRUE(arm.joints[0].rotational);
  EXPECT_DOUBLE_EQ(arm.joints[0].start, -5.0 * units::kPi / 180.0);
  EXPECT_EQ(arm.joints[0].frictionloss, 0.02);
  EXPECT_TRUE(std::isnan(arm.joints[0].damping)) << "not given: the model's";
  const Scenario leg = load_scenario(landing, {"joints.trunk_z.start_mm=100"});
  bool found = false;
  for (const JointSpec& j : leg.joints) {
    if (j.joint != "trunk_z") continue;
    found = true;
    EXPECT_FALSE(j.rotational);
    EXPECT_DOUBLE_EQ(j.start, 0.1);
  }
  EXPECT_TRUE(found);
  EXPECT_EQ(refusal_parts([&] { load_scenario(landing, {"joints.trunk_z.start_deg=10"}); },
                          "a hinge's key on a slide")
                .key,
            "joints.trunk_z");
}

// bodies.<body> and holds.<body>: every number row refuses its bad values naming the key, a
// list of the wrong length or with a value outside its range is refused, and given values
// reach the scenario's bodies and holds in SI.
TEST(BodyAndHoldKeysTest, EveryRowRefusesABadValueAndAValueReachesItsField) {
  BodyKeys body;
  HoldSpec hold;
  std::vector<double> position;
  int refused = 0;
  for (const auto& [table, prefix] : std::vector<std::pair<KeyTable, std::string>>{
           {body_key_table(&body), "bodies.basket"},
           {hold_key_table(&hold, &position), "holds.ball"}}) {
    for (const NumberRow& row : table.numbers) {
      const std::string key = prefix + "." + row.name;
      for (const std::string& value : bad_number_texts(row)) {
        const InputErrorParts parts =
            refusal_parts([&] { load_scenario(kDropMass, {key + "=" + value}); }, key + value);
        EXPECT_EQ(parts.key, key) << value;
        ++refused;
      }
    }
  }
  EXPECT_EQ(refused, 5 + 5) << "a string, NaN, true and each side of the range, for both";
  for (const auto& [set, key] : std::vector<std::pair<std::string, std::string>>{
           {"bodies.basket.inertia_kg_m2=[1e-4, 2e-4]", "bodies.basket.inertia_kg_m2"},
           {"bodies.basket.inertia_kg_m2=[1e-4, 2e-4, 3e-4, 4e-4]", "bodies.basket.inertia_kg_m2"},
           {"bodies.basket.inertia_kg_m2=[1e-4, -2e-4, 2e-4]", "bodies.basket.inertia_kg_m2"},
           {"holds.ball.position_m=[0, 0.1]", "holds.ball.position_m"},
           {"holds.ball.above_site=3", "holds.ball.above_site"}}) {
    const std::string given = set;  // (a lambda captures no structured binding)
    EXPECT_EQ(refusal_parts([&] { load_scenario(kDropMass, {given}); }, given).key, key) << set;
  }
  const Scenario sc = load_scenario(
      kDropMass, {"bodies.basket.mass_kg=0.3", "bodies.basket.inertia_kg_m2=[1e-4, 2e-4, 2e-4]",
                  "holds.box={ position_m = [0, 0.1, 0.5] }"});
  bool basket = false, box = false;
  for (const BodyMassSpec& b : sc.body_masses) {
    if (b.body != "basket") continue;
    basket = true;
    EXPECT_EQ(b.mass_kg, 0.3);
    EXPECT_EQ(b.inertia_kg_m2[1], 2e-4);
  }
  for (const HoldSpec& h : sc.holds) {
    if (h.body != "box") continue;
    box = true;
    EXPECT_TRUE(h.at_position);
    EXPECT_EQ(h.position_m[2], 0.5);
  }
  EXPECT_TRUE(basket);
  EXPECT_TRUE(box) << "a hold on a body the model may lack is the binding's to refuse";
}

// muscles.<actuator>'s line keys: every number row refuses its bad values naming the key, and
// given values reach the muscle in SI (the line's E A from its diameter and modulus).
TEST(MuscleLineKeysTest, EveryRowRefusesABadValueAndAValueReachesItsField) {
  MuscleLineKeys keys;
  MuscleSpec muscle;
  int refused = 0;
  for (const NumberRow& row : muscle_line_key_table(&keys, &muscle).numbers) {
    const std::string key = "muscles.agonist." + row.name;
    for (const std::string& value : bad_number_texts(row)) {
      const InputErrorParts parts =
          refusal_parts([&] { load_scenario(kDropMass, {key + "=" + value}); }, key + value);
      EXPECT_EQ(parts.key, key) << value;
      ++refused;
    }
  }
  EXPECT_GE(refused, 6 * 4) << "a string, NaN, true and a side of the range, each row";
  const Scenario sc = load_scenario(
      kDropMass, {"muscles.agonist.line_mm=300", "muscles.agonist.line_diameter_mm=0.5",
                  "muscles.agonist.line_modulus_MPa=2500", "muscles.agonist.line_creep=0.1",
                  "muscles.agonist.line_creep_time_s=20", "muscles.agonist.line_limit_N=100",
                  "metrics=[\"drop\", \"reflex\", \"tension\"]"});  // the limit's readers
  const MuscleSpec& m = sc.muscles.front();
  ASSERT_EQ(m.key, "muscles.agonist");
  EXPECT_DOUBLE_EQ(m.line_length_m, 0.3);
  EXPECT_DOUBLE_EQ(m.line_axial_stiffness_n, 2500e6 * units::kPi * 0.25e-3 * 0.25e-3);
  EXPECT_EQ(m.line_creep, 0.1);
  EXPECT_EQ(m.line_creep_time_s, 20.0);
  EXPECT_EQ(m.line_limit_n, 100.0);
}

// events.<event> and its when.*: every number row refuses its bad values naming the key (with
// the keys its action or condition needs beside it), and a key beside the wrong action is
// refused as unknown.
TEST(EventKeysTest, EveryNumberRowRefusesABadValueNamingTheKey) {
  EventSpec event;
  EventThresholds thresholds;
  const std::vector<std::pair<KeyTable, std::vector<std::string>>> tables = {
      {event_key_table(&event),
       {"events.e.action=\"add_mass\"", "events.e.body=\"basket\"", "events.e.when.at_s=0.5"}},
      {event_when_key_table(&event, &thresholds), {}}};
  const std::map<std::string, std::string> beside = {
      // what each condition row goes with
      {"below_deg", "events.e.when.joint=\"shoulder\""},
      {"above_deg", "events.e.when.joint=\"shoulder\""},
      {"below_mm", "events.e.when.joint=\"shoulder\""},
      {"above_mm", "events.e.when.joint=\"shoulder\""},
      {"below_z_m", "events.e.when.body=\"ball\""}};
  int refused = 0;
  for (const auto& [table, context] : tables) {
    const std::string prefix = table.name == "events.<event>" ? "events.e." : "events.e.when.";
    for (const NumberRow& row : table.numbers) {
      const std::string key = prefix + row.name;
      for (const std::string& value : bad_number_texts(row)) {
        std::vector<std::string> set = context;
        if (beside.count(row.name)) set.push_back(beside.at(row.name));
        set.push_back(key + "=" + value);
        const InputErrorParts parts =
            refusal_parts([&] { load_scenario(kDropMass, set); }, key + value);
        EXPECT_EQ(parts.key, key) << value;
        ++refused;
      }
    }
  }
  EXPECT_GE(refused, 7 * 3) << "a string, NaN and true for each of the seven numbers";
  const std::vector<std::string> mark = {"events.e.when.at_s=0.5", "events.e.mass_kg=0.1"};
  EXPECT_EQ(refusal_parts([&] { load_scenario(kDropMass, mark); }, "mass_kg beside mark").key,
            "events.e.mass_kg");
}

}  // namespace
}  // namespace pamsim
