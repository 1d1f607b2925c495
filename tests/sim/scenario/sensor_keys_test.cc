// sensor_keys_test.cc: the sensors' keys (sensing/sensor_keys.h) through the scenario reader:
// every key the reader asks for directly under sensors. (the instruments' own tables aside)
// has exactly one row and every row is read; a bad value of
// every row, generated from the row (each side of its range, another type, NaN, an integer
// row's fraction), is refused in one line naming the scenario file and the key; and a value
// in the file's unit reaches its SI field, bit for bit as the sensors convert it.
#include <gtest/gtest.h>

#include <map>
#include <set>
#include <string>
#include <vector>

#include "base/config_reader.h"
#include "base/input_error.h"
#include "base/key_table_test_util.h"
#include "base/units.h"
#include "sensing/sensor_keys.h"
#include "sim/scenario/scenario_file.h"
#include "sim/test_paths.h"

namespace pamsim {
namespace {

using pamsim_test::kDropMass;

// the key set to `value` as an override of the shipped drop; the refusal's parts
InputErrorParts refusal_of(const std::string& key, const std::string& value) {
  return refusal_parts([&] { load_scenario(kDropMass, {key + "=" + value}); }, key + " = " + value);
}

TEST(SensorKeysTest, EveryKeyTheReaderAsksForHasExactlyOneRow) {
  SensorConfig s;
  const std::map<std::string, int> rows = row_keys({sensor_key_table(&s)});
  std::set<std::string> asked;
  for (const ScenarioKeyValue& kv : scenario_key_values(kDropMass, {})) {
    const std::vector<std::string> parts = split_key(kv.key);
    if (parts.size() == 2 && parts[0] == "sensors") {
      asked.insert(kv.key);
    }
  }
  expect_rows_are_the_asked_keys(rows, asked);
  EXPECT_EQ(rows.size(), 13u);
}

TEST(SensorKeysTest, EveryRowRefusesABadValueNamingTheFileAndTheKey) {
  SensorConfig s;
  const KeyTable table = sensor_key_table(&s);
  int refused = 0;
  for (const NumberRow& row : table.numbers) {
    for (const std::string& value : bad_number_texts(row)) {
      const InputErrorParts parts = refusal_of("sensors." + row.name, value);
      EXPECT_EQ(parts.key, "sensors." + row.name) << value;
      EXPECT_EQ(parts.file, kDropMass) << row.name;
      ++refused;
    }
  }
  for (const IntRow& row : table.ints) {
    for (const std::string& value : bad_int_texts(row)) {
      EXPECT_EQ(refusal_of("sensors." + row.name, value).key, "sensors." + row.name) << value;
      ++refused;
    }
  }
  EXPECT_GE(refused, 40);
}

TEST(SensorKeysTest, AValueInTheFilesUnitReachesItsSiField) {
  const Scenario sc = load_scenario(
      kDropMass, {"sensors.pressure_noise_MPa=0.0023", "sensors.fiber_noise_mm_s=3.1"});
  EXPECT_EQ(sc.sensing.sensors.pressure_noise_pa, units::mpa_to_pa(0.0023));
  EXPECT_EQ(sc.sensing.sensors.fiber_noise_m_s, units::mm_to_m(3.1));
}

}  // namespace
}  // namespace pamsim
