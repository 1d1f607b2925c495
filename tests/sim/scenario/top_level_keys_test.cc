// top_level_keys_test.cc: an identification, a tuning and a sweep file's top-level keys as
// rows (identify_file.h's identify_search_table, tuning_file.h's tune_search_table, sweep.h's
// sweep_design_table and sweep_sampling_table): a bad value of every row, generated from the
// row, is refused in one line naming the file and the key; a value reaches its field; and
// `pamsim keys --identify` / `--tune` / `--sweep` list each row once with the struct's
// default.
#include <gtest/gtest.h>

#include <filesystem>
#include <functional>
#include <map>
#include <string>

#include <nlohmann/json.hpp>

#include "base/key_table_test_util.h"
#include "sim/cli_util.h"
#include "sim/identify_test_arm.h"
#include "sim/optimize/identify_file.h"
#include "sim/optimize/tuning_file.h"
#include "sim/sweep/sweep.h"
#include "sim/test_paths.h"

namespace pamsim {
namespace {

// a key of a table of tables ("parameter[].from"), listed after the file's rows
bool is_entry_key_doc(const std::string& key) { return key.find("[].") != std::string::npos; }

namespace fs = std::filesystem;

// A one-parameter identification of the example arm's step recording, with `top` (top-level
// lines) first.
std::string search_keys_file(const fs::path& dir, const std::string& top) {
  if (!fs::exists(dir / "steps.csv")) record_arm(dir / "steps.csv", kSteps);
  pamsim_test::write_text(dir / "id.toml",
                          top + "\nbase = \"" + kArm +
                              "\"\noverrides = [\"sim.duration_s=2\"]\n"
                              "[[parameter]]\nkey = \"bodies.ball.mass_kg\"\nfrom = 0.1\nto = 0.4\n"
                              "[[recording]]\nfile = \"steps.csv\"\nset = ['" +
                              kSteps + "']\n");
  return (dir / "id.toml").string();
}

// Each row's bad values, as the top-level line "<key> = <value>" of the file `file_with`
// writes, refused by `load` naming that file and the key; the number of refusals.
int expect_every_row_refused(const KeyTable& table,
                             const std::function<std::string(const std::string&)>& file_with,
                             const std::function<void(const std::string&)>& load) {
  int refused = 0;
  const auto expect_refused = [&](const std::string& key, const std::string& value) {
    const std::string path = file_with(key + " = " + value);
    const InputErrorParts parts = refusal_parts([&] { load(path); }, key + " = " + value);
    EXPECT_EQ(parts.key, key) << value;
    EXPECT_EQ(parts.file, path) << key;
    ++refused;
  };
  for (const NumberRow& row : table.numbers) {
    for (const std::string& value : bad_number_texts(row)) expect_refused(row.name, value);
  }
  for (const IntRow& row : table.ints) {
    for (const std::string& value : bad_int_texts(row)) expect_refused(row.name, value);
  }
  for (const ChoiceRow& row : table.choices) {
    for (const char* value : {"\"neither\"", "1"}) expect_refused(row.name, value);
  }
  for (const BoolRow& row : table.bools) {
    for (const char* value : {"1", "\"true\""}) expect_refused(row.name, value);
  }
  return refused;
}

TEST(IdentifyKeysTest, EveryRowRefusesABadValueNamingTheFileAndTheKey) {
  const fs::path dir = pamsim_test::fresh_dir("identify_keys_bad");
  IdentifyDefinition defaults;
  const int refused = expect_every_row_refused(
      identify_search_table(&defaults),
      [&](const std::string& line) { return search_keys_file(dir, line); },
      [](const std::string& path) { load_identify_definition(path); });
  EXPECT_EQ(refused, 2 * 5 + 7 * 4 + 2 * 1);
}

// A one-parameter tuning of the reflex threshold, with `top` first.
std::string tune_keys_file(const fs::path& dir, const std::string& top) {
  pamsim_test::write_text(dir / "tune.toml",
                          top + "\nbase = \"" + pamsim_test::kDropMass +
                              "\"\n"
                              "[[parameter]]\nkey = \"reflex.v_thr_mm_s\"\nfrom = 40\nto = 100\n"
                              "[[objective]]\nmetric = \"peak_drop_deg\"\n");
  return (dir / "tune.toml").string();
}

TEST(TuneKeysTest, EveryRowRefusesABadValueAndNsga2sPopulationIsAMultipleOfFour) {
  const fs::path dir = pamsim_test::fresh_dir("tune_keys_bad");
  TuneDefinition defaults;
  const int refused = expect_every_row_refused(
      tune_search_table(&defaults),
      [&](const std::string& line) { return tune_keys_file(dir, line); },
      [](const std::string& path) { load_tune_definition(path); });
  EXPECT_EQ(refused, 5 * 4 + 2);
  const std::string nsga2 = tune_keys_file(dir, "algorithm = \"nsga2\"\npopulation = 10");
  EXPECT_EQ(refusal_parts([&] { load_tune_definition(nsga2); }, "population 10").key, "population");
  const TuneDefinition def = load_tune_definition(
      tune_keys_file(dir, "algorithm = \"nsga2\"\npopulation = 12\nseed = 4294967295"));
  EXPECT_EQ(def.algorithm, TuneAlgorithm::kNsga2);
  EXPECT_EQ(def.population, 12u);
  EXPECT_EQ(def.seed, 4294967295u);
  EXPECT_EQ(def.generations, 10u) << "a key not given keeps the struct's default";
  const pamsim_test::CliResult r = pamsim_test::run_pamsim("keys --tune --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  std::map<std::string, int> listed;
  for (const auto& j : nlohmann::json::parse(r.out)) {
    if (!is_entry_key_doc(j["key"])) ++listed[j["key"]];  // the tables' (entry_keys_test)
  }
  EXPECT_EQ(listed, row_keys({tune_search_table(&defaults)}));
}

TEST(IdentifyKeysTest, AValueReachesItsFieldAndKeysListsEveryRowOnce) {
  const fs::path dir = pamsim_test::fresh_dir("identify_keys_read");
  const IdentifyDefinition def = load_identify_definition(
      search_keys_file(dir,
                       "seed = 4294967295\npolish_iterations = 0\nexplained_noise_factor = 2.5\n"
                       "interval = 0.9\nprofile_offsets = false"));
  EXPECT_EQ(def.seed, 4294967295u);
  EXPECT_EQ(def.polish_iterations, 0);
  EXPECT_EQ(def.explained_noise_factor, 2.5);
  EXPECT_EQ(def.interval, 0.9);
  EXPECT_FALSE(def.profile_offsets);
  EXPECT_EQ(def.generations, 20u) << "a key not given keeps the struct's default";
  EXPECT_EQ(def.population, default_population(def)) << "sized to the parameters searched";
  EXPECT_EQ(load_identify_definition(search_keys_file(dir, "population = 5")).population, 5u);
  const pamsim_test::CliResult r = pamsim_test::run_pamsim("keys --identify --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  std::map<std::string, int> listed;
  std::map<std::string, std::string> fallback;
  for (const auto& j : nlohmann::json::parse(r.out)) {
    if (is_entry_key_doc(j["key"])) continue;  // the tables' keys (entry_keys_test)
    ++listed[j["key"]];
    fallback[j["key"]] = j["default"];
  }
  IdentifyDefinition defaults;
  EXPECT_EQ(listed, row_keys({identify_search_table(&defaults)}));
  EXPECT_EQ(fallback["explained_noise_factor"], "3.0");
  EXPECT_EQ(fallback["generations"], "20");
  EXPECT_EQ(fallback["runs"], "3");
  EXPECT_EQ(fallback["population"].rfind("(the larger of 8 and 4 + floor(3 ln m)", 0), 0u)
      << fallback["population"];
  const pamsim_test::CliResult both = pamsim_test::run_pamsim("keys --identify --pneumatics");
  EXPECT_EQ(both.exit_code, 2);
  EXPECT_EQ(pamsim_test::line_count(both.err), 1) << both.err;
}

// A one-axis sweep of the drop-mass scenario with `top` first: a grid, or with `sampled` a
// random design of two samples unless `top` gives them.
std::string sweep_keys_file(const fs::path& dir, const std::string& top, bool sampled) {
  const bool own_samples = top.rfind("samples", 0) == 0;
  const std::string design = !sampled      ? ""
                             : own_samples ? "design = \"random\"\n"
                                           : "design = \"random\"\nsamples = 2\n";
  pamsim_test::write_text(dir / "sweep.toml",
                          design + top + "\nbase = \"" + pamsim_test::kDropMass +
                              "\"\n[[axis]]\n"
                              "key = \"reflex.v_thr_mm_s\"\n" +
                              (sampled ? "from = 50.0\nto = 80.0\n" : "values = [60.0]\n"));
  return (dir / "sweep.toml").string();
}

TEST(SweepKeysTest, EveryRowRefusesABadValueAndAGridRefusesTheSamplingKeys) {
  const fs::path dir = pamsim_test::fresh_dir("sweep_keys_bad");
  SweepDefinition defaults;
  const auto load = [](const std::string& path) { load_sweep(path); };
  int refused = expect_every_row_refused(
      sweep_design_table(&defaults),
      [&](const std::string& line) { return sweep_keys_file(dir, line, false); }, load);
  refused += expect_every_row_refused(
      sweep_sampling_table(&defaults),
      [&](const std::string& line) { return sweep_keys_file(dir, line, true); }, load);
  EXPECT_EQ(refused, 4 * 4 + 2);
  for (const std::string& key : key_names(sweep_sampling_table(&defaults))) {
    const std::string path = sweep_keys_file(dir, key + " = 3", false);
    EXPECT_EQ(refusal_parts([&] { load_sweep(path); }, key + " with a grid").key, key);
  }
  const SweepDefinition s =
      load_sweep(sweep_keys_file(dir, "design_seed = 7\nseeds = 3\nmax_trials = 10", true));
  EXPECT_EQ(s.design, SweepDesign::kRandom);
  EXPECT_EQ(s.samples, 2);
  EXPECT_EQ(s.design_seed, 7u);
  EXPECT_EQ(s.seeds, 3);
  EXPECT_EQ(s.max_trials, 10);
  const pamsim_test::CliResult r = pamsim_test::run_pamsim("keys --sweep --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  std::map<std::string, int> listed;
  for (const auto& j : nlohmann::json::parse(r.out)) {
    if (!is_entry_key_doc(j["key"])) ++listed[j["key"]];  // the tables' (entry_keys_test)
  }
  EXPECT_EQ(listed, row_keys({sweep_design_table(&defaults), sweep_sampling_table(&defaults)}));
}

}  // namespace
}  // namespace pamsim
