// entry_keys_test.cc: the keys of the sweep, tuning, identification and validation files'
// tables of tables ([[parameter]], [[recording]], [[axis]], [[bracket]]...), each a typed row
// of one list beside its reader (base/entry_keys.h): every table of the shipped files refuses
// a key its list lacks, and every typed row's bad values (generated from its type, range and
// names), in one line naming "<array>[0].<key>", and reads the file as shipped; and
// `pamsim keys --identify/--tune/--sweep` lists each list's keys.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "base/input_error.h"
#include "base/key_table_test_util.h"
#include "sim/cli_util.h"
#include "sim/optimize/identify_file.h"
#include "sim/optimize/identify_file_recordings.h"
#include "sim/optimize/search_space.h"
#include "sim/optimize/tuning_file.h"
#include "sim/scenario/randomize.h"
#include "sim/sweep/sweep.h"
#include "sim/validate/bands.h"
#include "sim/validate/error_budget.h"
#include "sim/validate/reaching.h"
#include "sim/test_paths.h"
#include "source_mirror.h"

namespace pamsim {
namespace {

namespace fs = std::filesystem;
using pamsim_test::CliResult;
using pamsim_test::run_pamsim;

struct ArrayCase {
  std::string file;    // a shipped file, from the source tree
  std::string header;  // the line of the table the key goes under
  std::string array;   // its name in messages
  std::function<void(const std::string&)> load;
  const std::vector<EntryKey>* keys;
};

std::vector<ArrayCase> cases() {
  const auto tune = [](const std::string& p) { load_tune_definition(p); };
  const auto identify = [](const std::string& p) { load_identify_definition(p); };
  const auto sweep = [](const std::string& p) { load_sweep(p); };
  const auto reaching = [](const std::string& p) { load_reaching_validation(p); };
  const std::string tuning = "scenarios/tune_reflex.toml", id = "examples/identify/identify.toml";
  return {
      {tuning, "[[parameter]]", "parameter", tune, &parameter_entry_keys()},
      {tuning, "[[objective]]", "objective", tune, &objective_entry_keys()},
      {tuning, "[[constraint]]", "constraint", tune, &constraint_entry_keys()},
      {tuning, "[[reference]]", "reference", tune, &reference_entry_keys()},
      {id, "[[recording]]", "recording", identify, &recording_entry_keys()},
      {id, "[[tensile]]", "tensile", identify, &tensile_entry_keys()},
      {id, "[[candidate]]", "candidate", identify, &candidate_entry_keys()},
      {"scenarios/sweep_reflex.toml", "[[axis]]", "axis", sweep, &axis_entry_keys()},
      {"scenarios/sweep_findings_gates.toml", "[[axis]]", "axis", sweep, &case_axis_entry_keys()},
      {"scenarios/sweep_findings_gates.toml", "[[axis.case]]", "axis[0].case", sweep,
       &case_entry_keys()},
      {"scenarios/sweep_robustness.toml", "[[randomize]]", "randomize", sweep,
       &randomize_entry_keys()},
      {"scenarios/validate_reaching.toml", "[[bracket]]", "bracket", reaching,
       &bracket_entry_keys()},
      {"scenarios/validate_reaching.toml", "[[budget_source]]", "budget_source", reaching,
       &budget_source_entry_keys()}};
}

// A bad value of a typed row as TOML text, and a word its refusal must hold.
struct BadValue {
  std::string text;
  std::string says;
};

// A row's bad values, from its type, range and names: a value of another type, NaN, each
// finite side of its range just outside, a name it lacks; none for an untyped row.
std::vector<BadValue> bad_values(const EntryKey& k) {
  switch (k.type) {
    case EntryType::kText:
      return {{"1", "must be a string"}};
    case EntryType::kTexts:
      return {{"1", "list of strings"}, {"[1]", "list of strings"}};
    case EntryType::kBool:
      return {{"1", "true or false"}, {"\"yes\"", "true or false"}};
    case EntryType::kTable:
      return {{"1", "must be "}};
    case EntryType::kChoice:
      return {{"\"no_such_name\"", "allowed"}, {"1", "allowed"}};
    case EntryType::kNumber: {
      std::vector<BadValue> bad = {
          {"\"x\"", "must be a number"}, {"true", "must be a number"}, {"nan", "must be finite"}};
      for (double v : outside(k.range)) bad.push_back({format_number(v), "must be in"});
      return bad;
    }
    case EntryType::kInteger: {
      std::vector<BadValue> bad = {{"1.5", "an integer"}, {"\"x\"", "an integer"}};
      for (double v : outside(k.range))
        bad.push_back({std::to_string(std::llround(v)), "must be in"});
      return bad;
    }
    case EntryType::kAny:
      break;
  }
  return {};
}

// `text` with `line` as the first entry's only line for its key: after `header`, and any line
// of the entry that gives the key already removed
std::string with_line(const std::string& text, const std::string& header, const std::string& key,
                      const std::string& line) {
  const std::size_t body = text.find(header + "\n") + header.size() + 1;
  std::string out = text.substr(0, body) + line + "\n";
  std::istringstream rest(text.substr(body));
  bool in_entry = true;
  for (std::string l; std::getline(rest, l);) {
    if (!l.empty() && l[0] == '[') in_entry = false;
    const bool gives_key = in_entry && (l.rfind(key + " =", 0) == 0 || l.rfind(key + "=", 0) == 0);
    if (!gives_key) out += l + "\n";
  }
  return out;
}

std::string read_text(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

TEST(EntryKeysTest, EveryShippedTableRefusesAKeyOutsideItsList) {
  for (const ArrayCase& c : cases()) {
    SCOPED_TRACE(c.file + " " + c.header);
    const fs::path shipped = fs::path(pamsim_test::kSource) / c.file;
    const std::string text = read_text(shipped);
    const std::size_t at = text.find(c.header + "\n");
    ASSERT_NE(at, std::string::npos);
    // beside links to the shipped file's neighbours, so that its relative paths still resolve
    const fs::path dir = fs::path(c.file).parent_path();
    const fs::path root = pamsim_test::source_mirror(pamsim_test::kSource, "entry_keys", dir);
    const fs::path copy = root / dir / "entry_keys_test.toml";
    std::string bad = text;
    bad.insert(at + c.header.size() + 1, "no_such_key = 1\n");
    std::ofstream(copy) << bad;
    const InputErrorParts parts = refusal_parts([&] { c.load(copy.string()); }, c.array);
    std::ofstream(copy) << text;  // and without it, read as shipped
    EXPECT_NO_THROW(c.load(copy.string()));
    fs::remove_all(root);
    EXPECT_EQ(parts.key, c.array + "[0].no_such_key");
  }
}

TEST(EntryKeysTest, EveryTypedRowRefusesItsBadValuesByItsKey) {
  int tried = 0;
  for (const ArrayCase& c : cases()) {
    const fs::path dir = fs::path(c.file).parent_path();
    const std::string text = read_text(fs::path(pamsim_test::kSource) / c.file);
    const fs::path root = pamsim_test::source_mirror(pamsim_test::kSource, "entry_rows", dir);
    const fs::path copy = root / dir / "entry_rows_test.toml";
    for (const EntryKey& k : *c.keys) {
      for (const BadValue& bad : bad_values(k)) {
        const std::string what = c.file + " " + c.header + " " + k.name + " = " + bad.text;
        std::ofstream(copy) << with_line(text, c.header, k.name, k.name + " = " + bad.text);
        const InputErrorParts parts = refusal_parts([&] { c.load(copy.string()); }, what);
        EXPECT_EQ(parts.key, c.array + "[0]." + k.name) << what;
        EXPECT_NE(parts.problem.find(bad.says), std::string::npos) << what << ": " << parts.problem;
        ++tried;
      }
    }
    fs::remove_all(root);
  }
  EXPECT_GE(tried, 100);
}

// Every row is typed but those whose values the reader alone can judge (the swept key's own
// type, tables of another file, one number per parameter).
TEST(EntryKeysTest, OnlyTheRowsOfAnotherKeysTypeAreUntyped) {
  std::set<std::string> untyped;
  for (const ArrayCase& c : cases()) {
    for (const EntryKey& k : *c.keys) {
      if (k.type == EntryType::kAny) untyped.insert(c.array + "." + k.name);
    }
  }
  EXPECT_EQ(untyped, (std::set<std::string>{"axis.values", "axis.case", "axis[0].case.from",
                                            "reference.values"}));
}

TEST(EntryKeysTest, PamsimKeysListsEveryTablesKeys) {
  const std::vector<
      std::pair<std::string, std::vector<std::pair<std::string, const std::vector<EntryKey>*>>>>
      files = {{"--identify",
                {{"parameter", &parameter_entry_keys()},
                 {"recording", &recording_entry_keys()},
                 {"tensile", &tensile_entry_keys()},
                 {"candidate", &candidate_entry_keys()}}},
               {"--tune",
                {{"objective", &objective_entry_keys()},
                 {"constraint", &constraint_entry_keys()},
                 {"reference", &reference_entry_keys()},
                 {"randomize", &randomize_entry_keys()}}},
               {"--sweep",
                {{"axis", &axis_entry_keys()},
                 {"axis", &case_axis_entry_keys()},
                 {"axis[].case", &case_entry_keys()}}}};
  int listed = 0;
  for (const auto& [flag, arrays] : files) {
    const CliResult r = run_pamsim("keys " + flag);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    for (const auto& [array, keys] : arrays) {
      for (const EntryKey& k : *keys) {
        const std::string line = array + "[]." + k.name + (k.unit[0] ? "  [" : "\n");
        EXPECT_NE(r.out.find(line), std::string::npos) << flag << ": " << line;
        ++listed;
      }
    }
  }
  EXPECT_GE(listed, 40);
}

}  // namespace
}  // namespace pamsim
