// keys.cc: `pamsim keys [SCENARIO] [--set key=value ...] [--json]`: every scenario key with
// its unit, default, allowed values and meaning (scenario/scenario_key_docs.h); with a
// scenario, every key it can take (its muscles', holds' and events' keys by name) with the
// value in effect and whether that is the default. `--pneumatics`: the pneumatics file's keys
// instead (model.pneumatics, pneumatics.<table>.<field>), from its reader's key table;
// `--plant`: a plant file's (muscles.<m>.plant, muscles.<m>.plant.<table>.<field>);
// `--params`: a muscle's estimator parameter file's (muscles.<m>.params);
// `--calibration`: a calibration file's (model.calibration, as `pamsim calibrate` writes it);
// `--identify`, `--tune`, `--sweep`: an identification, tuning or sweep file's top-level keys,
// from their rows, then the keys of its tables' entries ([[parameter]], [[recording]],
// [[axis]]...: "parameter[].from"), from their readers' lists. `--channels [SCENARIO]`:
// trajectory.csv's channels (trial_channels.h), or the columns a scenario's log has.
#include <CLI/CLI.hpp>
#include <iostream>
#include <nlohmann/json.hpp>

#include "base/input_error.h"
#include "pam_actuator/pam_params.h"
#include "pam_actuator/plant_params.h"
#include "pneumatics/pneumatic_params.h"
#include "sim/cli/cli_options.h"
#include "sim/cli/commands.h"
#include "sim/core/trial.h"
#include "sim/core/trial_model.h"
#include "sim/optimize/identify_file.h"
#include "sim/optimize/identify_file_recordings.h"
#include "sim/optimize/search_space.h"
#include "sim/optimize/tuning_file.h"
#include "sim/scenario/calibration_file.h"
#include "sim/scenario/randomize.h"
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
  bool calibration = false;
  bool identify = false;
  bool tune = false;
  bool sweep = false;
  bool channels = false;
};

nlohmann::json doc_json(const KeyDoc& d) {
  return {{"key", d.key},         {"unit", d.unit},       {"default", d.fallback},
          {"allowed", d.allowed}, {"meaning", d.meaning}, {"trial_only", d.trial_only}};
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
    if (json)
      all.push_back(doc_json(d));
    else
      print_doc(d.key, d);
  }
  if (json) std::cout << all.dump(2) << "\n";
}

// `docs`, then each array of tables' entry keys ("parameter[].from")
std::vector<KeyDoc> with_entries(
    std::vector<KeyDoc> docs,
    const std::vector<std::pair<const char*, const std::vector<EntryKey>*>>& arrays) {
  for (const auto& [array, keys] : arrays) {
    for (const KeyDoc& d : entry_key_docs(array, *keys)) docs.push_back(d);
  }
  return docs;
}

// an identification, tuning or sweep file's keys: its top-level rows, then its tables'
std::vector<KeyDoc> search_file_docs(const KeysOptions& opt) {
  IdentifyDefinition identify;  // the rows' defaults are the structs' own
  TuneDefinition tune;
  SweepDefinition sweep;
  if (opt.identify) {
    return with_entries(key_table_docs({identify_search_table(&identify)}),
                        {{"parameter", &parameter_entry_keys()},
                         {"recording", &recording_entry_keys()},
                         {"tensile", &tensile_entry_keys()},
                         {"candidate", &candidate_entry_keys()}});
  }
  if (opt.tune) {
    return with_entries(key_table_docs({tune_search_table(&tune)}),
                        {{"parameter", &parameter_entry_keys()},
                         {"objective", &objective_entry_keys()},
                         {"constraint", &constraint_entry_keys()},
                         {"reference", &reference_entry_keys()},
                         {"randomize", &randomize_entry_keys()}});
  }
  return with_entries(key_table_docs({sweep_design_table(&sweep), sweep_sampling_table(&sweep)}),
                      {{"axis", &axis_entry_keys()},
                       {"axis", &case_axis_entry_keys()},
                       {"axis[].case", &case_entry_keys()},
                       {"randomize", &randomize_entry_keys()}});
}

// --pneumatics, --plant, --params, --calibration, --identify, --tune or --sweep: another
// file's keys, which take no scenario
bool print_file_keys(const KeysOptions& opt) {
  const int files = opt.pneumatics + opt.plant + opt.params + opt.calibration + opt.identify +
                    opt.tune + opt.sweep;
  if (files == 0) return false;
  const std::string flags =
      "--pneumatics, --plant, --params, --calibration, --identify, --tune and --sweep";
  if (files > 1) throw InputError(flags + " list different files' keys: give one");
  if (!(opt.scenario.empty() && opt.overrides.empty())) {
    throw InputError(flags + " list a file's keys: they take no scenario or --set");
  }
  print_docs(opt.pneumatics    ? pneumatic_key_docs()
             : opt.plant       ? plant_key_docs()
             : opt.params      ? pam_key_docs()
             : opt.calibration ? calibration_key_docs()
                               : search_file_docs(opt),
             opt.json);
  return true;
}

// --channels: trajectory.csv's channels as the table has them, or a scenario's columns
void print_channels(const KeysOptions& opt) {
  std::vector<ChannelDoc> docs = channel_docs();
  if (!opt.scenario.empty()) {
    const Scenario sc = load_scenario(opt.scenario, opt.overrides);
    docs = channel_docs(trial_log_layout(load_trial_model(sc), sc), sc.controller_channels());
  } else if (!opt.overrides.empty()) {
    throw InputError("--set needs a scenario");
  }
  nlohmann::json all = nlohmann::json::array();
  for (const ChannelDoc& d : docs) {
    if (opt.json) {
      all.push_back({{"column", d.column},
                     {"unit", d.unit},
                     {"si_per_unit", d.si_per_unit},
                     {"meaning", d.meaning},
                     {"source", d.source},
                     {"measured", d.measured}});
    } else {
      std::cout << d.column << (d.unit.empty() ? "" : "  [" + d.unit + "]") << "\n    " << d.meaning
                << "; from " << d.source << (d.measured ? " (measured)" : "") << "\n";
    }
  }
  if (opt.json) std::cout << all.dump(2) << "\n";
}

void keys(const KeysOptions& opt) {
  if (opt.channels) {
    if (opt.pneumatics + opt.plant + opt.params + opt.calibration + opt.identify + opt.tune +
        opt.sweep) {
      throw InputError("--channels lists trajectory.csv's columns: it takes no other file's flag");
    }
    return print_channels(opt);
  }
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
    if (d)
      print_doc(head, *d);
    else
      std::cout << head << "\n";
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
  cmd->add_flag("--calibration", opt->calibration,
                "A calibration file's keys (the start angle, each muscle's line length and "
                "pressure, as `pamsim calibrate` writes them) instead of the scenario's");
  cmd->add_flag("--identify", opt->identify,
                "An identification file's keys (its search and judgement keys, then those of "
                "[[parameter]], [[recording]], [[tensile]], [[candidate]]) instead of the "
                "scenario's");
  cmd->add_flag("--tune", opt->tune,
                "A tuning file's keys (its search keys, then those of [[parameter]], "
                "[[objective]], [[constraint]], [[reference]], [[randomize]]) instead of the "
                "scenario's");
  cmd->add_flag("--channels", opt->channels,
                "trajectory.csv's channels (column, unit, SI factor, meaning, source); with a "
                "scenario, the columns its log has");
  cmd->add_flag("--sweep", opt->sweep,
                "A sweep file's keys (its design keys, then those of [[axis]], [[axis.case]], "
                "[[randomize]]) instead of the scenario's");
}

}  // namespace pamsim
