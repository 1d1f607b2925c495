// cli_keys_test.cc: `pamsim keys` lists the documented keys and a scenario's values; a
// misspelled key gets the right suggestion; a value refused because of another key names it
// and where its value came from. (That the documentation matches the reader:
// scenario_key_docs_test.cc.)
#include <gtest/gtest.h>

#include <filesystem>
#include <functional>
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <utility>
#include <vector>

#include <toml++/toml.h>

#include "sim/cli_util.h"
#include "sim/scenario/scenario_key_docs.h"

namespace {

namespace fs = std::filesystem;
using pamsim_test::CliResult;
using pamsim_test::fresh_dir;
using pamsim_test::line_count;
using pamsim_test::run_pamsim;

TEST(CliKeysTest, KeysListsTheDocumentationAndAScenariosValues) {
  const CliResult all = run_pamsim("keys --json");
  ASSERT_EQ(all.exit_code, 0) << all.err;
  const nlohmann::json docs = nlohmann::json::parse(all.out);
  EXPECT_EQ(docs.size(), pamsim::scenario_key_docs().size());

  const CliResult drop =
      run_pamsim("keys scenarios/drop_mass.toml --set reflex.duration_s=0.3 --json");
  ASSERT_EQ(drop.exit_code, 0) << drop.err;
  std::map<std::string, nlohmann::json> by_key;
  for (const auto& j : nlohmann::json::parse(drop.out)) by_key[j["key"]] = j;
  EXPECT_EQ(by_key["reflex.duration_s"]["value"], "0.3");
  EXPECT_EQ(by_key["reflex.duration_s"]["is_default"], false);
  EXPECT_EQ(by_key["sim.max_steps"]["value"], "1e+07");
  EXPECT_EQ(by_key["sim.max_steps"]["is_default"], true);
  EXPECT_EQ(by_key["reflex.v_thr_mm_s"]["unit"], "mm/s");
  // its muscles' keys by name
  EXPECT_TRUE(by_key.count("muscles.agonist.label"));

  const CliResult text = run_pamsim("keys scenarios/drop_mass.toml");
  ASSERT_EQ(text.exit_code, 0) << text.err;
  EXPECT_NE(text.out.find("reflex.v_thr_mm_s = 70.0  [mm/s]"), std::string::npos) << text.out;

  // bad input: one line, exit 2
  const CliResult bad = run_pamsim("keys scenarios/drop_mass.toml --set reflex.bogus=1");
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_EQ(line_count(bad.err), 1) << bad.err;
  EXPECT_EQ(run_pamsim("keys --set seed=1").exit_code, 2);
  EXPECT_EQ(run_pamsim("keys /nonexistent.toml").exit_code, 2);
}

// The pneumatics file's reference comes from its reader's key table: the shipped file's keys
// are all in it, with the units their names carry.
TEST(CliKeysTest, KeysPneumaticsListsThePneumaticsFilesKeys) {
  const CliResult r = run_pamsim("keys --pneumatics --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  std::map<std::string, nlohmann::json> by_key;
  for (const auto& j : nlohmann::json::parse(r.out)) by_key[j["key"]] = j;
  EXPECT_EQ(by_key["regulator.dead_time_ms"]["unit"], "ms");
  EXPECT_EQ(by_key["regulator.dead_time_ms"]["allowed"], "[0, 1000]");
  EXPECT_EQ(by_key["solver.method"]["default"], "\"bdf\"");
  const toml::table shipped = toml::parse_file("models/pams/pneumatics.toml");
  for (const auto& [table, node] : shipped) {
    for (const auto& [key, value] : *node.as_table()) {
      EXPECT_TRUE(by_key.count(std::string(table.str()) + "." + std::string(key.str())))
          << table << "." << key;
    }
  }
  const CliResult both = run_pamsim("keys --pneumatics scenarios/drop_mass.toml");
  EXPECT_EQ(both.exit_code, 2);
  EXPECT_EQ(line_count(both.err), 1) << both.err;
}

// Every key of every shipped plant and estimator parameter file is in the file's reference,
// which comes from the rows its reader reads.
TEST(CliKeysTest, KeysPlantAndParamsListEveryKeyTheShippedFilesGive) {
  for (const auto& [flag, prefix] : std::vector<std::pair<std::string, std::string>>{
           {"--plant", "plant_"}, {"--params", "table4_"}}) {
    const CliResult r = run_pamsim("keys " + flag + " --json");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    std::map<std::string, nlohmann::json> by_key;
    for (const auto& j : nlohmann::json::parse(r.out)) by_key[j["key"]] = j;
    int files = 0;
    for (const auto& entry : std::filesystem::directory_iterator("models/pams")) {
      if (entry.path().filename().string().rfind(prefix, 0) != 0) continue;
      ++files;
      std::vector<std::string> keys;  // the file's dotted keys, tables' own aside
      std::function<void(const toml::table&, const std::string&)> collect =
          [&](const toml::table& t, const std::string& at) {
            for (const auto& [k, v] : t) {
              const std::string key = at + std::string(k.str());
              if (v.is_table())
                collect(*v.as_table(), key + ".");
              else
                keys.push_back(key);
            }
          };
      collect(toml::parse_file(entry.path().string()), "");
      for (const std::string& key : keys) {
        EXPECT_EQ(by_key.count(key), 1u) << flag << ": " << entry.path() << ": " << key;
      }
    }
    EXPECT_GE(files, 2) << flag;
  }
  EXPECT_EQ(run_pamsim("keys --plant --params").exit_code, 2);
}

TEST(CliKeysTest, AMisspelledKeyGetsTheKeyMeant) {
  struct Case {
    std::string set, suggestion;
  };
  for (const Case& c : std::vector<Case>{
           {"reflex.v_thr_mm_sec=60", "did you mean reflex.v_thr_mm_s?"},
           {"reflx.v_thr_mm_s=60", "did you mean reflex.v_thr_mm_s?"},
           {"sensors.presure_noise_MPa=0.002", "did you mean sensors.pressure_noise_MPa?"},
           {"sim.duraton_s=2", "did you mean sim.duration_s?"},
           // a key the reader asks only whether present: still suggested
           {"valve.dead_tim_ms=5", "did you mean valve.dead_time_ms?"},
       }) {
    const CliResult r =
        run_pamsim("run scenarios/drop_mass.toml --out /nonexistent/x --set " + c.set);
    EXPECT_EQ(r.exit_code, 2) << c.set;
    EXPECT_EQ(line_count(r.err), 1) << r.err;
    EXPECT_NE(r.err.find("is not a known key; " + c.suggestion), std::string::npos)
        << c.set << " -> " << r.err;
  }
  // a refusal caused by another key's value says which, and where that came from
  const CliResult file =
      run_pamsim("run scenarios/drop_mass.toml --out /nonexistent/x --set sim.duration_s=1");
  EXPECT_EQ(file.exit_code, 2);
  EXPECT_NE(file.err.find("drop.time_s = 1 (file) with sim.duration_s = 1 (--set)"),
            std::string::npos)
      << file.err;
  const fs::path dir = fresh_dir("keys_other");
  const std::string no_time =
      pamsim_test::scenario_variant(dir, "drop_mass.toml", "time_s = 1.0", "");
  const CliResult other =
      run_pamsim("run " + no_time + " --out /nonexistent/x --set sim.duration_s=1");
  EXPECT_EQ(other.exit_code, 2);
  EXPECT_NE(other.err.find("drop.time_s = 1 (default) with sim.duration_s = 1 (--set)"),
            std::string::npos)
      << other.err;
  // nothing near: no guess
  const CliResult far =
      run_pamsim("run scenarios/drop_mass.toml --out /nonexistent/x --set zzz.qqq=1");
  EXPECT_EQ(far.exit_code, 2);
  EXPECT_EQ(far.err.find("did you mean"), std::string::npos) << far.err;
}

}  // namespace
