// instrument_keys_test.cc: the instruments' keys (sensing/instrument_keys.h) through the
// scenario reader, on the shipped drop whose instruments are all hardware: every key the
// reader asks for under sensors.gauge, .pressure, .fiber and .encoder (the creep lists aside)
// has exactly one row and every row is read; a bad value of every row, generated from the row
// (each side of its range, another type, NaN; an integer's fraction, a choice's unknown name),
// is refused in one line naming the scenario file and the key; a value in the file's unit
// reaches its SI field; and an ideal instrument refuses its hardware's keys.
#include <gtest/gtest.h>

#include <map>
#include <set>
#include <string>
#include <vector>

#include "base/config_reader.h"
#include "base/input_error.h"
#include "base/key_table_test_util.h"
#include "base/units.h"
#include "base/format.h"
#include "sensing/instrument_keys.h"
#include "sensing/instrument_kinds.h"
#include "sim/scenario/scenario_file.h"
#include "sim/test_paths.h"

namespace pamsim {
namespace {

using pamsim_test::kDropMass;
using pamsim_test::kScenarios;

// the key set to `value` as an override of the shipped drop; the refusal's parts
InputErrorParts refusal_of(const std::string& key, const std::string& value) {
  return refusal_parts([&] { load_scenario(kDropMass, {key + "=" + value}); }, key + " = " + value);
}

bool is_instrument_key(const std::string& key) {
  for (const char* prefix :
       {"sensors.gauge.", "sensors.pressure.", "sensors.fiber.", "sensors.encoder."}) {
    if (key.rfind(prefix, 0) == 0) return true;
  }
  return false;
}

// Every instrument's tables and its creep series' rows (instrument_kinds.h), bound to `s` and
// to `lists`, which must outlive them
std::vector<KeyTable> all_instrument_tables(SensorConfig* s,
                                            std::vector<std::vector<double>>* lists) {
  std::vector<KeyTable> tables = instrument_key_tables(s);
  lists->resize(2 * instrument_kinds().size());
  for (std::size_t k = 0; k < instrument_kinds().size(); ++k) {
    const InstrumentKind& kind = instrument_kinds()[k];
    if (kind.creep) tables.push_back(creep_key_table(kind, &(*lists)[2 * k], &(*lists)[2 * k + 1]));
  }
  return tables;
}

TEST(InstrumentKeysTest, EveryKeyTheReaderAsksForHasExactlyOneRow) {
  SensorConfig s;
  std::vector<std::vector<double>> lists;
  const std::map<std::string, int> rows = row_keys(all_instrument_tables(&s, &lists));
  std::set<std::string> asked;
  for (const ScenarioKeyValue& kv : scenario_key_values(kDropMass, {})) {
    if (is_instrument_key(kv.key)) asked.insert(kv.key);
  }
  expect_rows_are_the_asked_keys(rows, asked);
  EXPECT_EQ(rows.size(), 45u) << "41 rows and two creep series of two lists";
}

TEST(InstrumentKeysTest, EveryRowRefusesABadValueNamingTheFileAndTheKey) {
  SensorConfig s;
  int refused = 0;
  const auto expect_refused = [&](const std::string& key, const std::string& value) {
    const InputErrorParts parts = refusal_of(key, value);
    EXPECT_EQ(parts.key, key) << value;
    EXPECT_EQ(parts.file, kDropMass) << key;
    ++refused;
  };
  std::vector<std::vector<double>> lists;
  for (const KeyTable& t : all_instrument_tables(&s, &lists)) {
    for (const ListRow& row : t.lists) {  // a value out of range, a list of text
      const double bad = row.range.lo_open ? row.range.lo : row.range.lo - 1;
      expect_refused(t.name + "." + row.name, "[" + format_value(bad) + "]");
      expect_refused(t.name + "." + row.name, "[\"x\"]");
    }
    for (const NumberRow& row : t.numbers) {
      for (const std::string& value : bad_number_texts(row)) {
        expect_refused(t.name + "." + row.name, value);
      }
    }
    for (const IntRow& row : t.ints) {
      for (const std::string& value : bad_int_texts(row)) {
        expect_refused(t.name + "." + row.name, value);
      }
    }
    for (const BoolRow& row : t.bools) {
      for (const char* value : {"1", "\"x\""}) expect_refused(t.name + "." + row.name, value);
    }
    for (const ChoiceRow& row : t.choices) {
      for (const char* value : {"\"none\"", "1"}) expect_refused(t.name + "." + row.name, value);
    }
  }
  EXPECT_GE(refused, 140);
}

TEST(InstrumentKeysTest, AValueInTheFilesUnitReachesItsSiField) {
  const Scenario sc = load_scenario(
      kDropMass, {"sensors.gauge.board.width_mm=25", "sensors.gauge.contact.wrap_deg=45",
                  "sensors.gauge.calibration.steps=4", "sensors.pressure.hysteresis_MPa=0.003",
                  "sensors.pressure.response_time_ms=2", "sensors.fiber.span_mm=30",
                  "sensors.encoder.resolution_mm=0.02", "sensors.gauge.contact.model=\"fixed\""});
  const SensorConfig& s = sc.sensing.sensors;
  EXPECT_EQ(s.gauge_hardware.board.width_m, units::mm_to_m(25.0));
  EXPECT_EQ(s.gauge_hardware.contact.wrap_deg, 45.0);
  EXPECT_FALSE(s.gauge_hardware.contact.sliding);
  EXPECT_EQ(s.gauge_hardware.calibration_steps, 4);
  EXPECT_EQ(s.pressure_hardware.hysteresis_pa, units::mpa_to_pa(0.003));
  EXPECT_EQ(s.pressure_hardware.response_time_s, 2e-3);
  EXPECT_EQ(s.fiber_hardware.span_m, units::mm_to_m(30.0));
  EXPECT_EQ(s.encoder.resolution_m, units::mm_to_m(0.02));
  EXPECT_TRUE(s.gauge_hardware.enabled && s.pressure_hardware.enabled && s.fiber_hardware.enabled &&
              s.encoder.enabled);
}

TEST(InstrumentKeysTest, AnIdealInstrumentRefusesItsHardwaresKeys) {
  const std::string ideal = kScenarios + "drop_mass_ideal.toml";
  for (const std::string& key :
       {std::string("sensors.gauge.board.width_mm"), std::string("sensors.pressure.hysteresis_MPa"),
        std::string("sensors.fiber.span_mm"), std::string("sensors.encoder.resolution_mm")}) {
    const InputErrorParts parts = refusal_parts([&] { load_scenario(ideal, {key + "=1"}); }, key);
    EXPECT_EQ(parts.key, key);
    EXPECT_NE(parts.problem.find("is used only by"), std::string::npos) << parts.problem;
  }
}

}  // namespace
}  // namespace pamsim
