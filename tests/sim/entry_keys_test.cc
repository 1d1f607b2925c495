// entry_keys_test.cc: the keys of the sweep, tuning and identification files' tables of
// tables ([[parameter]], [[recording]], [[axis]]...), each listed once, in one place beside
// its reader (base/key_table.h's EntryKey): every table of the shipped files refuses a key its
// list lacks in one line naming "<array>[0].<key>" and reads the file with the key gone; and
// `pamsim keys --identify/--tune/--sweep` lists each list's keys.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <functional>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "base/input_error.h"
#include "base/key_table_test_util.h"
#include "cli_util.h"
#include "sim/optimize/identify_file.h"
#include "sim/optimize/identify_file_recordings.h"
#include "sim/optimize/search_space.h"
#include "sim/optimize/tuning_file.h"
#include "sim/scenario/randomize.h"
#include "sim/sweep/sweep.h"
#include "sim/test_paths.h"
#include "source_mirror.h"

namespace pamsim {
namespace {

namespace fs = std::filesystem;
using pamsim_test::CliResult;
using pamsim_test::run_pamsim;

struct ArrayCase {
  std::string file;     // a shipped file, from the source tree
  std::string header;   // the line of the table the key goes under
  std::string array;    // its name in messages
  std::function<void(const std::string&)> load;
};

std::vector<ArrayCase> cases() {
  const auto tune = [](const std::string& p) { load_tune_definition(p); };
  const auto identify = [](const std::string& p) { load_identify_definition(p); };
  const auto sweep = [](const std::string& p) { load_sweep(p); };
  return {{"scenarios/tune_reflex.toml", "[[parameter]]", "parameter", tune},
          {"scenarios/tune_reflex.toml", "[[objective]]", "objective", tune},
          {"scenarios/tune_reflex.toml", "[[constraint]]", "constraint", tune},
          {"scenarios/tune_reflex.toml", "[[reference]]", "reference", tune},
          {"examples/identify/identify.toml", "[[recording]]", "recording", identify},
          {"examples/identify/identify.toml", "[[tensile]]", "tensile", identify},
          {"examples/identify/identify.toml", "[[candidate]]", "candidate", identify},
          {"scenarios/sweep_reflex.toml", "[[axis]]", "axis", sweep},
          {"scenarios/sweep_robustness.toml", "[[randomize]]", "randomize", sweep}};
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
    std::ofstream(copy) << text;   // and without it, read as shipped
    EXPECT_NO_THROW(c.load(copy.string()));
    fs::remove_all(root);
    EXPECT_EQ(parts.key, c.array + "[0].no_such_key");
  }
}

TEST(EntryKeysTest, PamsimKeysListsEveryTablesKeys) {
  const std::vector<std::pair<std::string, std::vector<std::pair<std::string,
                                                                  const std::vector<EntryKey>*>>>>
      files = {{"--identify", {{"parameter", &parameter_entry_keys()},
                               {"recording", &recording_entry_keys()},
                               {"tensile", &tensile_entry_keys()},
                               {"candidate", &candidate_entry_keys()}}},
               {"--tune", {{"objective", &objective_entry_keys()},
                           {"constraint", &constraint_entry_keys()},
                           {"reference", &reference_entry_keys()},
                           {"randomize", &randomize_entry_keys()}}},
               {"--sweep", {{"axis", &axis_entry_keys()},
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
