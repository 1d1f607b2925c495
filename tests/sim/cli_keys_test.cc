// cli_keys_test.cc: `pamsim keys` and "did you mean": the documented keys (io/scenario_keys.h)
// are exactly the keys the scenario reader asks for, over the shipped scenarios and variants
// that reach every optional key (schedules of each kind, events of each condition, holds,
// valve and reflex options), so neither list can drift from the other; the documented
// literal defaults are the reader's; a misspelled key gets the right suggestion.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <map>
#include <nlohmann/json.hpp>
#include <set>
#include <string>
#include <vector>

#include "cli_util.h"
#include "pam_actuator/input_error.h"
#include "pam_actuator/toml_file.h"
#include "sim/io/scenario_file.h"
#include "sim/io/scenario_keys.h"

namespace {

namespace fs = std::filesystem;
using pamsim_test::CliResult;
using pamsim_test::fresh_dir;
using pamsim_test::line_count;
using pamsim_test::run_pamsim;
using pamsim_test::write_text;

const std::string kSource = PAMSIM_SOURCE_DIR;

// A copy of a shipped scenario in `dir` with `from` replaced by `to`, its model paths absolute.
std::string variant(const fs::path& dir, const std::string& scenario, const std::string& from,
                    const std::string& to) {
  std::string text = pamsim::read_text_file(kSource + "/scenarios/" + scenario);
  for (std::size_t at; (at = text.find("\"../models/")) != std::string::npos;) {
    text.replace(at, 11, "\"" + kSource + "/models/");
  }
  const std::size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  if (at != std::string::npos) text.replace(at, from.size(), to);
  const fs::path path = dir / ("variant_" + std::to_string(std::hash<std::string>{}(to)) + ".toml");
  write_text(path, text);
  return path.string();
}

struct Read {
  std::string scenario;
  std::vector<std::string> overrides;
};

// Scenarios that, together, make the reader ask for every key it knows.
std::vector<Read> every_kind_of_scenario(const fs::path& dir) {
  const std::string s = kSource + "/scenarios/";
  write_text(dir / "schedule.csv", "time_s,MPa\n0,0.4\n1,0.5\n");
  return {
      {s + "drop_mass.toml", {}},   // the 0.1 shorthands, drop, reflex, sensors
      {s + "drop_mass_fiber.toml", {}},
      {s + "drop_mass.toml",
       {"valve.dead_time_ms=5", "valve.valve_time_constant_ms=10",
        "valve.proportional_band_kPa=20", "valve.supply_MPa=0.7", "valve.command_max_MPa=0.7",
        "controller.p_max_MPa=0.6", "reflex.pairs=[[\"agonist\", \"antagonist\"]]",
        // an event of each condition, and each action's keys
        "events.a.when.at_s=0.5", "events.a.action=\"add_mass\"", "events.a.body=\"basket\"",
        "events.a.mass_kg=0.1", "events.b.when.contact=[\"ball\", \"basket\"]",
        "events.b.after=\"a\"", "events.c.when.joint=\"shoulder\"", "events.c.when.below_deg=-60",
        "events.d.when.joint=\"shoulder\"", "events.d.when.above_deg=0",
        "events.e.when.body=\"ball\"", "events.e.when.below_z_m=-1"}},
      {s + "reaching.toml",   // the long forms: plant, label, ramp; holds by position
       {"muscles.agonist.command={kind=\"constant\", MPa=0.4}",
        "muscles.antagonist.command={kind=\"steps\", times_s=[0.0, 1.0], MPa=[0.4, 0.5]}",
        "muscles.agonist.line_mm=150", "bodies.ball.mass_kg=0.2"}},
      {s + "reaching.toml",
       {"muscles.agonist.command={kind=\"table\", file=\"" + (dir / "schedule.csv").string() + "\"}",
        "muscles.antagonist.line=\"equilibrium\""}},
      {variant(dir, "reaching.toml", "position_m = [0.5, 0.5, 0.5]",
               "above_site = \"basket_floor\"\nheight_m = 0.3"),
       {}},
      {s + "pulley_sine_5kg.toml",   // sine with phase and start; a slide joint's conditions
       {"muscles.pam.command.phase_deg=90", "muscles.pam.command.start_s=1",
        "events.low.when.joint=\"weight_slide\"", "events.low.when.below_mm=-500",
        "events.high.when.joint=\"weight_slide\"", "events.high.when.above_mm=500",
        "events.high.action=\"end\""}},
  };
}

TEST(CliKeysTest, TheDocumentedKeysAreExactlyTheKeysTheReaderAsksFor) {
  const fs::path dir = fresh_dir("keys_every");
  std::set<std::string> documented;
  for (const pamsim::KeyDoc& d : pamsim::scenario_key_docs()) {
    EXPECT_TRUE(documented.insert(d.key).second) << "documented twice: " << d.key;
  }
  std::set<std::string> asked;
  for (const Read& r : every_kind_of_scenario(dir)) {
    std::vector<pamsim::ScenarioKeyValue> values;
    try {
      values = pamsim::scenario_key_values(r.scenario, r.overrides);
    } catch (const pamsim::InputError& e) {
      ADD_FAILURE() << r.scenario << ": " << e.what();
      continue;
    }
    for (const pamsim::ScenarioKeyValue& kv : values) {
      const std::string pattern = pamsim::scenario_key_pattern(kv.key);
      EXPECT_FALSE(pattern.empty()) << "the reader asks for " << kv.key
                                    << ", which scenario_keys.cc does not document";
      asked.insert(pattern);
      // a literal documented default is the reader's
      const auto doc = std::find_if(pamsim::scenario_key_docs().begin(),
                                    pamsim::scenario_key_docs().end(),
                                    [&](const pamsim::KeyDoc& d) { return d.key == pattern; });
      if (kv.is_default && doc != pamsim::scenario_key_docs().end() && doc->fallback[0] != '(') {
        EXPECT_EQ(doc->fallback, kv.value) << kv.key << " in " << r.scenario;
      }
    }
  }
  for (const std::string& key : documented) {
    EXPECT_TRUE(asked.count(key)) << key << " is documented, but no scenario of the test made "
                                            "the reader ask for it (stale, or add a variant)";
  }
}

TEST(CliKeysTest, KeysListsTheDocumentationAndAScenariosValues) {
  const CliResult all = run_pamsim("keys --json");
  ASSERT_EQ(all.exit_code, 0) << all.err;
  const nlohmann::json docs = nlohmann::json::parse(all.out);
  EXPECT_EQ(docs.size(), pamsim::scenario_key_docs().size());

  const CliResult drop = run_pamsim("keys scenarios/drop_mass.toml --set reflex.duration_s=0.3 --json");
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
    const CliResult r = run_pamsim("run scenarios/drop_mass.toml --out /nonexistent/x --set " + c.set);
    EXPECT_EQ(r.exit_code, 2) << c.set;
    EXPECT_EQ(line_count(r.err), 1) << r.err;
    EXPECT_NE(r.err.find("is not a known key; " + c.suggestion), std::string::npos)
        << c.set << " -> " << r.err;
  }
  // a refusal caused by another key's value says which, and where that came from
  const CliResult file = run_pamsim("run scenarios/drop_mass.toml --out /nonexistent/x --set sim.duration_s=1");
  EXPECT_EQ(file.exit_code, 2);
  EXPECT_NE(file.err.find("drop.time_s = 1 (file) with sim.duration_s = 1 (--set)"),
            std::string::npos) << file.err;
  const fs::path dir = fresh_dir("keys_other");
  const std::string no_time = variant(dir, "drop_mass.toml", "time_s = 1.0", "");
  const CliResult other = run_pamsim("run " + no_time + " --out /nonexistent/x --set sim.duration_s=1");
  EXPECT_EQ(other.exit_code, 2);
  EXPECT_NE(other.err.find("drop.time_s = 1 (default) with sim.duration_s = 1 (--set)"),
            std::string::npos) << other.err;
  // nothing near: no guess
  const CliResult far = run_pamsim("run scenarios/drop_mass.toml --out /nonexistent/x --set zzz.qqq=1");
  EXPECT_EQ(far.exit_code, 2);
  EXPECT_EQ(far.err.find("did you mean"), std::string::npos) << far.err;
}

}  // namespace
