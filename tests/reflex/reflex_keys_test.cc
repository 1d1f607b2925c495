// reflex_keys_test.cc: the reflexes' keys (reflex_keys.h) through the reflex kinds' own
// reader (ControllerKind::read): every key the reader asks for under reflex.* has exactly one
// row (reflex.pairs aside, a list the kind reads itself), every row is asked for, a bad value
// of every row (generated from the row: each side of its range, another type, NaN; an
// unknown name for a choice, a number for a true/false key) is refused in one line naming
// the file and the key, and a value in the file's unit reaches its SI field.
#include <gtest/gtest.h>

#include <map>
#include <set>
#include <string>
#include <vector>

#include "base/config_reader.h"
#include "base/input_error.h"
#include "base/key_table_test_util.h"
#include "reflex/controller_registry.h"
#include "reflex/reflex_keys.h"

namespace pamsim {
namespace {

// what the kinds' reader needs of a scenario: two muscles, agonist and antagonist
ControllerScenario two_muscles() {
  ControllerScenario sc;
  sc.command_max_pa = 0.8e6;
  sc.muscles = {{"agonist", "muscles.agonist", 0.3e6}, {"antagonist", "muscles.antagonist", 0.3e6}};
  return sc;
}

// the rows of the kind that has both reflexes, bound to throw-away structs
struct AllRows {
  ReflexConfig reflex;
  double lowpass_hz = 0.0;
  TensionReflexParams ib;
  std::vector<KeyTable> tables = {stretch_reflex_key_table(&reflex, &lowpass_hz),
                                  tension_reflex_key_table(&ib)};
};

// the required keys, so that a document reads at all
const char* const kRequired = "[reflex.ib]\nf_thr_N = 50\nk_MPa_per_N = 0.002\n";

std::shared_ptr<const ControllerConfig> read_both(ConfigReader& in) {
  return find_controller_kind("stretch_tension_reflex")->read(in, two_muscles());
}

// the document with `key = value` added; the refusal's parts, or a failure
InputErrorParts refusal_of(const std::string& key, const std::string& value) {
  ConfigReader in(std::string(kRequired), "scenario.toml");
  in.apply_override(key + "=" + value);
  return refusal_parts([&] { read_both(in); }, key + " = " + value);
}

TEST(ReflexKeysTest, EveryKeyTheReaderAsksForHasExactlyOneRow) {
  std::map<std::string, int> rows;
  AllRows all;
  for (const KeyTable& t : all.tables) {
    for (const NumberRow& r : t.numbers) ++rows[t.name + "." + r.name];
    for (const ChoiceRow& r : t.choices) ++rows[t.name + "." + r.name];
    for (const BoolRow& r : t.bools) ++rows[t.name + "." + r.name];
  }
  for (const auto& [key, count] : rows) EXPECT_EQ(count, 1) << key;
  ConfigReader in(std::string(kRequired), "scenario.toml");
  read_both(in);
  std::set<std::string> asked;
  for (const std::string& key : in.asked_keys()) {
    if (key.rfind("reflex.", 0) != 0 || key == "reflex.pairs" || key == "reflex.ib") continue;
    asked.insert(key);
    EXPECT_EQ(rows.count(key), 1u) << key << " is read but has no row";
  }
  for (const auto& [key, count] : rows) EXPECT_EQ(asked.count(key), 1u) << key << " not read";
  EXPECT_GE(rows.size(), 20u);
}

TEST(ReflexKeysTest, EveryRowRefusesABadValueNamingTheFileAndTheKey) {
  AllRows all;
  int refused = 0;
  for (const KeyTable& t : all.tables) {
    for (const NumberRow& row : t.numbers) {
      for (const std::string& value : bad_number_texts(row)) {
        const InputErrorParts parts = refusal_of(t.name + "." + row.name, value);
        EXPECT_EQ(parts.key, t.name + "." + row.name) << value;
        EXPECT_EQ(parts.file, "scenario.toml") << row.name;
        ++refused;
      }
    }
    for (const ChoiceRow& row : t.choices) {
      EXPECT_EQ(refusal_of(t.name + "." + row.name, "\"nope\"").key, t.name + "." + row.name);
      EXPECT_EQ(refusal_of(t.name + "." + row.name, "1").key, t.name + "." + row.name);
    }
    for (const BoolRow& row : t.bools) {
      EXPECT_EQ(refusal_of(t.name + "." + row.name, "1").key, t.name + "." + row.name);
    }
  }
  EXPECT_GE(refused, 40);
}

// The paper's units at the file, SI in the struct: Table II's fiber threshold and gain, and
// the Ib gain, each in one hop from its row.
TEST(ReflexKeysTest, AValueInTheFilesUnitReachesItsSiField) {
  ConfigReader in(std::string(kRequired) + "[reflex]\nsensor = \"fiber\"\nv_thr_mm_s = 30\n",
                  "scenario.toml");
  const auto config = read_both(in);
  const auto& read = dynamic_cast<const StretchReflexScenarioConfig&>(*config);
  EXPECT_DOUBLE_EQ(read.reflex.v_thr_m_s, 0.030);                  // the file's 30 mm/s
  EXPECT_DOUBLE_EQ(read.reflex.k_pa_s_per_m, 1e6 / 300.0 / 1e-3);  // Table II's fiber gain
  EXPECT_DOUBLE_EQ(read.ib.k_pa_per_n, 2000.0);                    // 0.002 MPa/N
  EXPECT_DOUBLE_EQ(read.ib.f_thr_N, 50.0);
  // the summary reports the file's units again, as given
  std::map<std::string, double> summary;
  for (const SummaryField& f : read.summary_fields()) {
    if (std::holds_alternative<double>(f.value)) summary[f.key] = std::get<double>(f.value);
  }
  EXPECT_EQ(summary.at("v_thr_mm_s"), 30.0);
  EXPECT_EQ(summary.at("ib_k_MPa_per_N"), 0.002);
}

// 68 of the tenths from 0.1 to 999.9 do not survive x * 1e-3 / 1e-3 exactly; from_si gives
// each back as written.
TEST(ReflexKeysTest, TheFilesValueComesBackAsWritten) {
  ReflexConfig r;
  double lowpass_hz = 0.0;
  const KeyTable t = stretch_reflex_key_table(&r, &lowpass_hz);
  for (int tenths = 1; tenths < 10000; ++tenths) {
    const double mm_s = tenths / 10.0;
    r.v_thr_m_s = mm_s * 1e-3;
    ASSERT_EQ(file_value(t, "v_thr_mm_s"), mm_s);
  }
}

}  // namespace
}  // namespace pamsim
