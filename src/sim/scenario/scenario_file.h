// scenario_file.h: reads a scenario (core/scenario.h) from a TOML file plus `--set key=value`
// overrides and validates every key once, before anything runs. Units are in the keys' names
// (the papers' MPa and mm at the file, SI inside). Each key's unit, range, default and
// meaning is written once: as a row of its table (base/key_table.h: the model's, muscles',
// bodies', holds', joints', events', [sim], [drop] and [valve] in scenario_key_tables.h, the
// schedules' in schedule_key_tables.h, the sensors' and instruments' in sensing/, a controller
// kind's in its own file); only the keys that hand a value on to another file (a plant as a
// table of its fields, pneumatics.*) are described in scenario_key_docs.cc.
// `pamsim keys` prints them all. pamsim 0.1's shorthands are listed at load_scenario.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "sim/core/scenario.h"

namespace pamsim {

// Shorthands of pamsim 0.1 files (their keys keep their meaning):
//   drop.{enabled, mass_kg, height_m, time_s} (and body = "ball", basket = "basket",
//     site = "basket_floor"): the falling mass: bodies.<body>.mass_kg, a hold of the body
//     height_m above the site, events "release" (at time_s, if enabled) and "impact" (the
//     body touches the basket, after the release); a pamsim 0.1 file (muscles given by
//     model.<actuator>_params, no holds or events) without a [drop] table gets the drop
//     with these defaults
//   model.<actuator>_params = muscles.<actuator>.params (the agonist and antagonist of
//     these files are labelled "ago" and "anta")
//   pressure.<actuator>_MPa = a constant muscles.<actuator>.command
// A shorthand and its long form may not both be given in the file; a --set of the
// shorthand replaces the long form.
// Throws InputError "<file>: <key> <problem>" on the first error.
Scenario load_scenario(const std::string& path, const std::vector<std::string>& overrides = {});
// The same from the scenario's text, as if read from `path` (relative paths resolve against
// its folder): a sweep runs every point on the base scenario it validated, even if the file
// changes on disk meanwhile.
Scenario load_scenario_text(const std::string& text, const std::string& path,
                            const std::vector<std::string>& overrides = {});

// The controller of the scenario (`text` read as if from `path`, with `overrides`) given the
// settings `assignments` ("reflex.v_thr_mm_s=50"), as a `set` event gives them (each a key
// its kind lets change during a trial, ControllerKind::live; the rest keep the scenario's
// values): what `pamsim view`'s sliders hand the trial. Throws InputError "<file>: <where>
// ..." for a key that cannot change or a value its row refuses.
std::shared_ptr<const ControllerConfig> load_controller_settings(
    const std::string& text, const std::string& path, const std::vector<std::string>& overrides,
    const std::vector<std::string>& assignments, const std::string& where);

// For `pamsim calibrate`, which solves the line lengths: reads the scenario without its
// calibration file (which may not exist yet) and with placeholder lines.
Scenario load_scenario_for_calibration(const std::string& path,
                                       const std::vector<std::string>& overrides = {});

// A scenario (its `text`, read as if from `path`) with `overrides` applied, as a TOML file to
// be written into `dir`: `header` (comment lines) first, then the document's keys with the
// overrides set, file paths rewritten relative to `dir` and floats in shortest form; last,
// as comments ("# sim.timestep_s = 0.001"), every key the scenario left at its default, with
// the value in effect. Reads the scenario to find them, so it throws InputError like
// load_scenario on a bad one. Loading the result gives the same Scenario.
std::string resolved_scenario_toml(const std::string& text, const std::string& path,
                                   const std::vector<std::string>& overrides,
                                   const std::string& dir, const std::string& header);

// What a run records of its scenario, from one reading of `text`: the Scenario (as
// load_scenario_text gives it), its resolved TOML (resolved_scenario_toml) and the files its
// path keys name (key, path as resolved; is_scenario_path_key).
struct RecordedScenario {
  Scenario scenario;
  std::string resolved_toml;
  std::vector<std::pair<std::string, std::string>> input_paths;
};
RecordedScenario load_recorded_scenario(const std::string& text, const std::string& path,
                                        const std::vector<std::string>& overrides,
                                        const std::string& dir, const std::string& header);

// Every key the reader asks for when reading the scenario at `path` with `overrides`
// (given or not): the keys it accepts for that scenario's muscles, events and options, in
// key order, each with its value as TOML text: the file's (or the override's), else the
// default in effect, else "" (an optional key not given). Tables asked for as a whole
// ("drop", "muscles.agonist.command") are left out.
struct ScenarioKeyValue {
  std::string key;
  std::string value;
  bool is_default = false;
};
std::vector<ScenarioKeyValue> scenario_key_values(const std::string& path,
                                                  const std::vector<std::string>& overrides = {});

// True for the keys that hold file paths (relative to the scenario file), for tools that
// move a scenario elsewhere (a sweep's best.toml): model.file, model.calibration,
// model.pneumatics, model.<m>_params, muscles.<m>.params, muscles.<m>.plant,
// muscles.<m>.command.file.
bool is_scenario_path_key(const std::string& key);

}  // namespace pamsim
