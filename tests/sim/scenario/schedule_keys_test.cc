// schedule_keys_test.cc: muscles.<actuator>.command's rows (scenario/schedule_key_tables.h)
// through the scenario reader, for every kind of schedule: every key the reader asks for has
// exactly one row and every row is read; a bad value of every row, generated from the row,
// is refused in one line naming the scenario file and the key; a required key left out is
// named; a value reaches its field in SI; what joins keys (a pressure per time) is still
// checked.
#include <gtest/gtest.h>

#include <map>
#include <set>
#include <string>
#include <vector>

#include "base/config_reader.h"
#include "base/input_error.h"
#include "base/key_table_test_util.h"
#include "base/units.h"
#include "sim/scenario/scenario_file.h"
#include "sim/scenario/schedule_key_tables.h"
#include "sim/test_paths.h"

namespace pamsim {
namespace {

using pamsim_test::kReaching;

const std::string kCommand = "muscles.agonist.command";

// a whole command table for `kind`, every key given, as a --set of reaching.toml's agonist
const std::map<ScheduleKind, std::string> kGood = {
    {ScheduleKind::kConstant, "{kind=\"constant\", MPa=0.3}"},
    {ScheduleKind::kRamp, "{kind=\"ramp\", from_MPa=0.2, to_MPa=0.5, start_s=1.5, duration_s=3}"},
    {ScheduleKind::kSine,
     "{kind=\"sine\", offset_MPa=0.4, amplitude_MPa=0.1, period_s=2, phase_deg=90, "
     "start_s=0.5}"},
    {ScheduleKind::kSteps, "{kind=\"steps\", times_s=[0.5, 1.5], MPa=[0.3, 0.45]}"}};

// the good table of `kind` with `key = value` in place of its own (or added)
std::string with(ScheduleKind kind, const std::string& key, const std::string& value) {
  std::string table = kGood.at(kind);
  std::size_t at = table.find(" " + key + "=");
  if (at == std::string::npos) at = table.find("{" + key + "=");
  const std::string entry = key + "=" + value;
  if (at == std::string::npos) return table.substr(0, table.size() - 1) + ", " + entry + "}";
  std::size_t end = at + 1;
  int depth = 0;
  for (; end < table.size(); ++end) {  // the entry's end: a comma or the brace outside lists
    if (table[end] == '[') ++depth;
    if (table[end] == ']') --depth;
    if (depth == 0 && (table[end] == ',' || table[end] == '}')) break;
  }
  return table.substr(0, at + 1) + entry + table.substr(end);
}

std::vector<std::string> set_command(const std::string& table) { return {kCommand + "=" + table}; }

TEST(ScheduleKeysTest, EveryKeyTheReaderAsksForHasExactlyOneRowOfItsKind) {
  for (const auto& [kind, table] : kGood) {
    PressureSchedule s;
    std::vector<KeyTable> tables = {schedule_kind_key_table(&s), schedule_key_table(kind, &s)};
    for (KeyTable& t : tables) t.name = kCommand;
    std::set<std::string> asked;
    for (const ScenarioKeyValue& kv : scenario_key_values(kReaching, set_command(table))) {
      if (kv.key.rfind(kCommand + ".", 0) == 0) asked.insert(kv.key);
    }
    SCOPED_TRACE(to_string(kind));
    expect_rows_are_the_asked_keys(row_keys(tables), asked);
    EXPECT_GE(asked.size(), 2u);
  }
}

TEST(ScheduleKeysTest, EveryRowRefusesABadValueNamingTheFileAndTheKey) {
  int refused = 0;
  const auto expect_refused = [&](ScheduleKind kind, const std::string& name,
                                  const std::string& value) {
    const std::string table = with(kind, name, value);
    const InputErrorParts parts =
        refusal_parts([&] { load_scenario(kReaching, set_command(table)); }, table);
    EXPECT_EQ(parts.key, kCommand + "." + name) << table;
    EXPECT_EQ(parts.file, kReaching) << table;
    ++refused;
  };
  for (const auto& [kind, table] : kGood) {
    PressureSchedule s;
    const KeyTable rows = schedule_key_table(kind, &s);
    for (const NumberRow& row : rows.numbers) {
      for (const std::string& value : bad_number_texts(row)) expect_refused(kind, row.name, value);
      if (row.required) {  // left out
        std::string without = table;
        const std::size_t at = without.find(", " + row.name + "=");
        ASSERT_NE(at, std::string::npos) << row.name;
        without.erase(at, without.find_first_of(",}", at + 2) - at);
        const InputErrorParts parts =
            refusal_parts([&] { load_scenario(kReaching, set_command(without)); }, without);
        EXPECT_EQ(parts.key, kCommand + "." + row.name) << without;
        EXPECT_NE(parts.problem.find("is required"), std::string::npos) << parts.problem;
        ++refused;
      }
    }
    for (const ListRow& row : rows.lists) {
      for (const char* value : {"[-1.0, 2.0]", "\"x\"", "[]"}) {
        expect_refused(kind, row.name, value);
      }
    }
  }
  expect_refused(ScheduleKind::kConstant, "kind", "\"stairs\"");
  EXPECT_GE(refused, 40) << "every number row's four bad values, the lists', the kinds'";
}

TEST(ScheduleKeysTest, AValueReachesItsFieldInSIAndWhatJoinsKeysIsStillChecked) {
  const auto agonist = [](ScheduleKind kind) {
    return load_scenario(kReaching, set_command(kGood.at(kind))).muscles.front().command;
  };
  EXPECT_EQ(agonist(ScheduleKind::kConstant).p0_pa, 0.3e6);
  const PressureSchedule ramp = agonist(ScheduleKind::kRamp);
  EXPECT_EQ(ramp.kind, ScheduleKind::kRamp);
  EXPECT_DOUBLE_EQ(ramp.p1_pa, 0.5e6);
  EXPECT_EQ(ramp.start_s, 1.5);
  EXPECT_EQ(ramp.duration_s, 3.0);
  const PressureSchedule sine = agonist(ScheduleKind::kSine);
  EXPECT_EQ(sine.phase_rad, units::deg_to_rad(90.0));
  EXPECT_DOUBLE_EQ(sine.amplitude_pa, 0.1e6);
  EXPECT_EQ(sine.period_s, 2.0);
  const PressureSchedule steps = agonist(ScheduleKind::kSteps);
  EXPECT_EQ(steps.times_s, (std::vector<double>{0.5, 1.5}));
  EXPECT_DOUBLE_EQ(steps.values_pa.at(1), 0.45e6);
  // one pressure per time, and the valve's range, join keys: still refused
  const std::string uneven = with(ScheduleKind::kSteps, "MPa", "[0.3]");
  EXPECT_EQ(refusal_parts([&] { load_scenario(kReaching, set_command(uneven)); }, uneven).key,
            kCommand + ".MPa");
  const std::string high = with(ScheduleKind::kConstant, "MPa", "5");
  EXPECT_EQ(refusal_parts([&] { load_scenario(kReaching, set_command(high)); }, high).key,
            kCommand);
}

}  // namespace
}  // namespace pamsim
