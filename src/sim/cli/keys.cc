// keys.cc: `pamsim keys [SCENARIO] [--set key=value ...] [--json]`: every scenario key with
// its unit, default, allowed values and meaning (scenario/scenario_key_docs.h); with a
// scenario, every key it can take (its muscles', holds' and events' keys by name) with the
// value in effect and whether that is the default. `--pneumatics`: the pneumatics file's keys
// instead (model.pneumatics, pneumatics.<table>.<field>), from its reader's key table;
// `--plant`: a plant file's (muscles.<m>.plant, muscles.<m>.plant.<table>.<field>);
// `--params`: a muscle's estimator parameter file's (muscles.<m>.params);
// `--identify`, `--tune`, `--sweep`: an identification, tuning or sweep file's top-level keys,
// from their rows.
#include <CLI/CLI.hpp>
#include <iostream>
#include <nlohmann/json.hpp>

#include "base/input_error.h"
#include "pam_actuator/pam_params.h"
#include "pam_actuator/plant_params.h"
#include "pneumatics/pneumatic_params.h"
#include "sim/cli/cli_options.h"
#include "sim/cli/commands.h"
#include "sim/optimize/identify_file.h"
#include "sim/optimize/tuning_file.h"
#include "sim/sweep/sweep.h"
#include "sim/scenario/scenario_file.h"
#include "sim/scenario/scenario_key_docs.h"

namespace pamsim {
namespace {

struct KeysOptions {
  std::string scenario;
  std::vector<std::string> overrides;
  bool json = false;
  bool pneumatics = false;
  bool plant = false;
  bool params = false;
  bool identify = false;
  bool tune = false;
  bool sweep = false;
};

nlohmann::json doc_json(const KeyDoc& d) {
  return {{"key", d.key}, {"unit", d.unit}, {"default", d.fallback}, {"allowed", d.allowed},
          {"meaning", d.meaning}};
}

void print_doc(const std::string& head, const KeyDoc& d) {
  std::cout << head << (d.unit.empty() ? "" : "  [" + d.unit + "]") << "\n"
            << "    " << d.meaning << "; allowed: " << d.allowed << "; default: " << d.fallback
            << "\n";
}

// every documented key of a file kind, as text or one JSON array
void print_docs(const std::vector<KeyDoc>& docs, bool json) {
  nlohmann::json all = nlohmann::json::array();
  for (const KeyDoc& d : docs) {
    if (json) all.push_back(doc_json(d));
    else print_doc(d.key, d);
  }
  if (json) std::cout << all.dump(2) << "\n";
}

// --pneumatics, --plant, --params, --identify, --tune or --sweep: another file's keys,
// which take no scenario
bool print_file_keys(const KeysOptions& opt) {
  const int files =
      opt.pneumatics + opt.plant + opt.params + opt.identify + opt.tune + opt.sweep;
  if (files == 0) return false;
  const std::string flags = "--pneumatics, --plant, --params, --identify, --tune and --sweep";
  if (files > 1) throw InputError(flags + " list different files' keys: give one");
  if (!(opt.scenario.empty() && opt.overrides.empty())) {
    throw InputError(flags + " list a file's keys: they take no scenario or --set");
  }
  IdentifyDefinition identify;   // the rows' defaults are the structs' own
  TuneDefinition tune;
  SweepDefinition sweep;
  print_docs(opt.pneumatics ? pneumatic_key_docs()
             : opt.plant    ? plant_key_docs()
             : opt.params   ? pam_key_docs()
             : opt.identify ? key_table_docs({identify_search_table(&identify)})
             : opt.tune     ? key_table_docs({tune_search_table(&tune)})
                            : key_table_docs({sweep_design_table(&sweep),
                                              sweep_sampling_table(&sweep)}),
             opt.json);
  return true;
}

void keys(const KeysOptions& opt) {
  if (print_file_keys(opt)) return;
  if (opt.scenario.empty()) {
    if (!opt.overrides.empty()) throw InputError("--set needs a scenario");
    return print_docs(scenario_key_docs(), opt.json);
  }
  nlohmann::json all = nlohmann::json::array();
  for (const ScenarioKeyValue& kv : scenario_key_values(opt.scenario, opt.overrides)) {
    const KeyDoc* d = scenario_key_doc(kv.key);
    if (opt.json) {
      nlohmann::json j = d ? doc_json(*d) : nlohmann::json{{"key", kv.key}};
      j["key"] = kv.key;
      j["value"] = kv.value.empty() ? nlohmann::json(nullptr) : nlohmann::json(kv.value);
      j["is_default"] = kv.is_default;
      all.push_back(j);
      continue;
    }
    const std::string head = kv.key + " = " + (kv.value.empty() ? "(not set)" : kv.value) +
                             (kv.is_default ? "  (default)" : "");
    if (d) print_doc(head, *d);
    else std::cout << head << "\n";
  }
  if (opt.json) std::cout << all.dump(2) << "\n";
}

}  // namespace

void add_keys_command(CLI::App& app) {
  const auto [cmd, opt] = add_command<KeysOptions>(
      app, "keys",
      "List the scenario keys (unit, default, allowed values, meaning); with a "
      "scenario, the values it runs with",
      keys);
  cmd->add_option("scenario", opt->scenario, "Scenario file (TOML)");
  add_overrides_option(cmd, &opt->overrides, "Override a scenario key: --set reflex.v_thr_mm_s=60");
  cmd->add_flag("--json", opt->json, "One JSON array on stdout");
  cmd->add_flag("--pneumatics", opt->pneumatics,
                "The pneumatics file's keys (tables supply, gas, valve, chamber, first_order, "
                "regulator, solver) instead of the scenario's");
  cmd->add_flag("--plant", opt->plant,
                "A plant file's keys (the muscle's geometry, bladder and friction) instead of "
                "the scenario's");
  cmd->add_flag("--params", opt->params,
                "A muscle's parameter file's keys (the spring law its estimator inverts, the "
                "strain gauge, the geometry) instead of the scenario's");
  cmd->add_flag("--identify", opt->identify,
                "An identification file's search and judgement keys (generations, "
                "population, seed, polish_iterations, interval, explained_noise_factor) "
                "instead of the scenario's");
  cmd->add_flag("--tune", opt->tune,
                "A tuning file's search keys (algorithm, generations, population, seed, seeds, "
                "held_out_seeds) instead of the scenario's");
  cmd->add_flag("--sweep", opt->sweep,
                "A sweep file's design keys (design, seeds, max_trials, samples, design_seed) "
                "instead of the scenario's");
}

}  // namespace pamsim
