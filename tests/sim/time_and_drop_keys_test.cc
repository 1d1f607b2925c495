// time_and_drop_keys_test.cc: [sim] and the drop's numbers (time_and_drop_keys.h) through the
// scenario reader: every key the reader asks for under sim. and drop. (the drop's names
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
#include "sim/scenario/time_and_drop_keys.h"
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

}  // namespace
}  // namespace pamsim
