// pneumatic_key_table_test.cc: the pneumatics file's key table (pneumatic_key_table) is what
// its reader reads by: every row documented once, every default read back as it is, and a
// bad value of every row, generated from the row itself (each side of its range, a
// non-number, NaN; an unknown name for a choice), refused in one line naming the file and
// the row's key.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <set>
#include <string>
#include <vector>

#include "base/format.h"
#include "base/input_error.h"
#include "base/key_table_test_util.h"
#include "pneumatics/pneumatic_params.h"

namespace pamsim {
namespace {

namespace fs = std::filesystem;

// `text` as a pneumatics file in the temp folder, named after the test (CTest runs the tests
// as processes side by side)
std::string write_file(const std::string& text) {
  const std::string test = ::testing::UnitTest::GetInstance()->current_test_info()->name();
  const fs::path path = fs::temp_directory_path() / ("pamsim_pneumatic_keys_" + test + ".toml");
  std::ofstream(path) << text;
  return path.string();
}

// The file with one key set to `value` (TOML text); the InputError's parts, or a failure.
InputErrorParts refusal_of(const std::string& table, const std::string& key,
                           const std::string& value) {
  const std::string path = write_file("[" + table + "]\n" + key + " = " + value + "\n");
  return refusal_parts([&] { load_pneumatic_params(path); }, table + "." + key + " = " + value);
}

TEST(PneumaticKeyTableTest, EveryKeyHasOneDocumentedRow) {
  std::set<std::string> keys;
  for (const KeyDoc& d : pneumatic_key_docs()) {
    EXPECT_TRUE(keys.insert(d.key).second) << d.key << " has two rows";
    EXPECT_FALSE(d.meaning.empty()) << d.key;
    EXPECT_FALSE(d.allowed.empty()) << d.key;
    EXPECT_FALSE(d.fallback.empty()) << d.key;
  }
  EXPECT_GE(keys.size(), 30u);
  EXPECT_TRUE(keys.count("regulator.dead_time_ms"));
}

// A file that writes every default as the reference prints it reads back to the defaults.
TEST(PneumaticKeyTableTest, TheDefaultsAsDocumentedReadBackAsTheyAre) {
  std::string text, table;
  for (const KeyDoc& d : pneumatic_key_docs()) {
    if (d.fallback == "(unset)") continue;
    const std::string t = d.key.substr(0, d.key.find('.'));
    if (t != table) text += "[" + (table = t) + "]\n";
    text += d.key.substr(t.size() + 1) + " = " + d.fallback + "\n";
  }
  PneumaticParams read = load_pneumatic_params(write_file(text));
  PneumaticParams defaults;
  const std::vector<KeyTable> read_rows = pneumatic_key_table(&read);
  const std::vector<KeyTable> default_rows = pneumatic_key_table(&defaults);
  for (std::size_t t = 0; t < default_rows.size(); ++t) {
    for (std::size_t k = 0; k < default_rows[t].numbers.size(); ++k) {
      const NumberRow& d = default_rows[t].numbers[k];
      const NumberRow& r = read_rows[t].numbers[k];
      if (d.optional_target) continue;
      EXPECT_NEAR(*r.target, *d.target, 1e-12 * std::fabs(*d.target)) << d.name;
    }
    for (std::size_t k = 0; k < default_rows[t].choices.size(); ++k) {
      EXPECT_EQ(read_rows[t].choices[k].get(), default_rows[t].choices[k].get());
    }
  }
}

TEST(PneumaticKeyTableTest, EveryNumberRowRefusesWhatItsRangeAndTypeExclude) {
  PneumaticParams p;
  const std::string path = write_file("");
  for (const KeyTable& table : pneumatic_key_table(&p)) {
    for (const NumberRow& row : table.numbers) {
      const std::string key = table.name + "." + row.name;
      for (const std::string& value : bad_number_texts(row)) {
        const InputErrorParts parts = refusal_of(table.name, row.name, value);
        EXPECT_EQ(parts.key, key) << value;
        EXPECT_EQ(parts.file, path) << key;
        const bool out_of_range = parts.problem.rfind("must be in " + row.range.text(), 0) == 0 &&
                                  parts.problem.find(", got ") != std::string::npos;
        EXPECT_TRUE(out_of_range || parts.problem.rfind("must be a number, got a ", 0) == 0 ||
                    parts.problem.rfind("must be finite, got ", 0) == 0)
            << key << " = " << value << ": " << parts.problem;
      }
    }
  }
}

TEST(PneumaticKeyTableTest, EveryChoiceRowTakesItsNamesAndRefusesOthers) {
  PneumaticParams p;
  for (const KeyTable& table : pneumatic_key_table(&p)) {
    for (const ChoiceRow& row : table.choices) {
      for (const std::string& name : row.allowed) {
        EXPECT_NO_THROW(load_pneumatic_params(
            write_file("[" + table.name + "]\n" + row.name + " = \"" + name + "\"\n")))
            << row.name << " = " << name;
      }
      for (const std::string& value : {std::string("\"neither\""), std::string("1")}) {
        const InputErrorParts parts = refusal_of(table.name, row.name, value);
        EXPECT_EQ(parts.key, table.name + "." + row.name) << value;
      }
    }
  }
}

TEST(PneumaticKeyTableTest, AnUnknownKeyOrTableIsNamedWithWhatIsAllowed) {
  const InputErrorParts key = refusal_of("regulator", "dead_time_s", "0.005");
  EXPECT_EQ(key.key, "regulator.dead_time_s");
  EXPECT_NE(key.problem.find("unknown key (allowed: dead_time_ms,"), std::string::npos);
  const InputErrorParts table = refusal_of("regulators", "dead_time_ms", "5");
  EXPECT_EQ(table.key, "regulators");
  EXPECT_EQ(table.problem,
            "unknown table (allowed: supply, gas, valve, chamber, first_order, "
            "regulator, solver)");
}

}  // namespace
}  // namespace pamsim
