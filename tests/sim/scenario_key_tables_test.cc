// scenario_key_tables_test.cc: [sim], the drop's numbers and [valve] (scenario_key_tables.h)
// through the scenario reader: every key the reader asks for under sim. and drop. (the drop's names
// aside) has exactly one row and every row is read; a bad value of every row, generated from
// the row, is refused in one line naming the scenario file and the key; a value reaches its
// field; and what joins keys (the steps a trial takes, a drop before the end) is still refused.
#include <gtest/gtest.h>

#include <set>
#include <string>

#include "base/config_reader.h"
#include "base/input_error.h"
#include "base/key_table_test_util.h"
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
    const bool name = kv.key == "drop.body" || kv.key == "drop.basket" || kv.key == "drop.site";
    if ((table == "sim" || table == "drop") && !name) asked.insert(kv.key);
  }
  expect_rows_are_the_asked_keys(row_keys(tables(&sc, &max_steps, &drop)), asked);
  EXPECT_EQ(asked.size(), 8u);
}

TEST(TimeAndDropKeysTest, EveryRowRefusesABadValueNamingTheFileAndTheKey) {
  Scenario sc;
  double max_steps = kDefaultMaxSteps;
  DropShorthand drop;
  int refused = 0;
  const auto expect_refused = [&](const std::string& key, const std::string& value) {
    const InputErrorParts parts = refusal_parts(
        [&] { load_scenario(kDropMass, {key + "=" + value}); }, key + " = " + value);
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
  }
  EXPECT_GE(refused, 35);
}

TEST(TimeAndDropKeysTest, AValueReachesItsFieldAndWhatJoinsKeysIsStillChecked) {
  const Scenario sc = load_scenario(
      kDropMass, {"sim.timestep_s=0.0005", "sim.control_hz=200", "drop.mass_kg=0.3",
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
  EXPECT_EQ(refused_key({"sim.control_hz=300"}), "sim.control_hz");   // 1 kHz / 300
  EXPECT_EQ(refused_key({"drop.time_s=3.0"}), "drop.time_s");        // at the trial's end
}

// valve.model = "regulator" and each of the table's keys at its default: the reader then
// asks for every valve key
std::vector<std::string> every_valve_key(const KeyTable& valve) {
  std::vector<std::string> overrides = {"valve.model=\"regulator\""};
  for (const NumberRow& row : valve.numbers) {
    overrides.push_back("valve." + row.name + "=" + format_number(file_value(valve, row.name)));
  }
  for (const ChoiceRow& row : valve.choices) {
    overrides.push_back("valve." + row.name + "=\"" + row.get() + "\"");
  }
  return overrides;
}

TEST(ValveKeysTest, EveryValveKeyTheReaderAsksForIsOneRowOfThePneumaticsFile) {
  PneumaticParams p = load_scenario(kDropMass).pneumatics;   // the file's values
  std::vector<std::string> regulator;
  const KeyTable valve = valve_key_table(&p, &regulator);
  std::set<std::string> asked;
  for (const ScenarioKeyValue& kv : scenario_key_values(kDropMass, every_valve_key(valve))) {
    if (split_key(kv.key).front() == "valve" && kv.key != "valve.model") asked.insert(kv.key);
  }
  expect_rows_are_the_asked_keys(row_keys({valve}), asked);
  EXPECT_EQ(asked.size(), regulator.size() + 2);   // the supply and the command's maximum
  // given at the file's own values, the keys change nothing
  const PneumaticParams read = load_scenario(kDropMass, every_valve_key(valve)).pneumatics;
  EXPECT_EQ(read.regulator_dead_time_s, p.regulator_dead_time_s);
  EXPECT_EQ(read.tube_conductance_m3_per_s_pa, p.tube_conductance_m3_per_s_pa);
  EXPECT_EQ(read.supply_gauge_pa, p.supply_gauge_pa);
}

TEST(ValveKeysTest, EveryRowRefusesABadValueAndARegulatorKeyWantsTheRegulator) {
  PneumaticParams p;
  std::vector<std::string> regulator;
  const KeyTable valve = valve_key_table(&p, &regulator);
  int refused = 0;
  for (const NumberRow& row : valve.numbers) {
    const std::string key = "valve." + row.name;
    for (const std::string& value : bad_number_texts(row)) {
      const InputErrorParts parts = refusal_parts(
          [&] { load_scenario(kDropMass, {"valve.model=\"regulator\"", key + "=" + value}); },
          key + " = " + value);
      EXPECT_EQ(parts.key, key) << value;
      EXPECT_EQ(parts.file, kDropMass) << key;
      ++refused;
    }
  }
  for (const ChoiceRow& row : valve.choices) {
    const std::string key = "valve." + row.name;
    EXPECT_EQ(refusal_parts([&] { load_scenario(kDropMass, {"valve.model=\"regulator\"",
                                                            key + "=\"neither\""}); },
                            key)
                  .key,
              key);
  }
  EXPECT_GE(refused, 5 * static_cast<int>(valve.numbers.size()));
  // a regulator key with another valve model, which would ignore it
  for (const std::string& name : regulator) {
    const std::string key = "valve." + name;
    const InputErrorParts parts = refusal_parts(
        [&] { load_scenario(kDropMass, {"valve.model=\"iso6358\"", key + "=1"}); }, key);
    EXPECT_EQ(parts.key, key);
    EXPECT_NE(parts.problem.find("valve.model = \"regulator\""), std::string::npos) << key;
  }
}

}  // namespace
}  // namespace pamsim
