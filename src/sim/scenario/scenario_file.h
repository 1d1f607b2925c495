// scenario_file.h: reads a scenario (core/scenario.h) from a TOML file plus `--set key=value`
// overrides and validates every key once, before anything runs. Keys (units in their names;
// the papers' MPa and mm at the file, SI inside):
//   seed                          integer >= 0
//   metrics                       metric sets (core/metrics.h); default: the drop's
//                                 ["drop", "reflex", "length_estimate"] with a [drop] table,
//                                 else ["tracking", "length_estimate"] (+ "reflex" with a
//                                 stretch_reflex controller)
//   model.file                    MJCF (path, relative to the scenario file)
//   model.joint                   the joint logged and measured; default: the model's first
//                                 hinge or slide joint
//   model.calibration             optional: start_angle_deg and <actuator>_line_mm (calibrate)
//   model.pneumatics              valve and chamber parameters (models/pams/pneumatics.toml)
//   pneumatics.<table>.<field>    optional: a field of model.pneumatics' file, in its units
//                                 (chamber.tube_dead_volume_cm3), in place of the file's;
//                                 validated as the file's own (base/file_changes.h)
//   sim.timestep_s                physics step, (0, 0.01], default 0.001
//   sim.duration_s                (0, 3600], default 3
//   sim.control_hz                control and logging rate, default 100; a whole divisor of
//                                 the physics rate
//   sim.max_steps                 the most physics steps a trial may take (duration_s /
//                                 timestep_s), in [1, 1e10], default 1e7
//   muscles.<actuator>.params     PAM parameter file (models/pams/...), required for every
//                                 PAM actuator of the model
//   muscles.<actuator>.plant      optional: the physical muscle's file (pam_actuator/
//                                 plant_params.h, the AVBDL law); default: the plant obeys
//                                 the params file's spring law (plant = estimator). Or a
//                                 table: file = the path, and any of the file's own fields
//                                 (geometry.wall_thickness_mm, friction.extension.A0_mm2,
//                                 ...), which replace the file's; a --set of such a field
//                                 on a scenario that gives the path alone makes it the table
//   muscles.<actuator>.label      name in columns and metrics, default the actuator's name
//   muscles.<actuator>.line_mm    fishing-line length; or .line = "equilibrium" (solved so
//                                 the start state is static); default: model.calibration's
//   muscles.<actuator>.command    the commanded pressure (core/schedule.h), a table:
//       kind = "constant"  MPa
//       kind = "ramp"      from_MPa, to_MPa, duration_s, start_s (default 0)
//       kind = "sine"      offset_MPa, amplitude_MPa, period_s, phase_deg (0), start_s (0)
//       kind = "steps"     times_s = [...], MPa = [...]
//       kind = "table"     file: a CSV "time_s,MPa", piecewise linear
//   bodies.<body>.mass_kg         (0, 1000]; the model's inertia scaled with it
//   bodies.<body>.inertia_kg_m2   [I1, I2, I3] principal moments, in place of the model's
//   holds.<body>                  a free body held at rest until released: above_site and
//                                 height_m in [0, 10] (its bottom, for a sphere), or
//                                 position_m = [x, y, z]
//   events.<name>                 action = "mark" | "release" | "add_mass" | "controller_off"
//                                 | "controller_on" | "end"; body (release, add_mass);
//                                 mass_kg (add_mass); after = another event's name; and
//       when.at_s                 a time >= 0, or
//       when.contact = [a, b]     two bodies touch, or
//       when.joint with below_deg / above_deg (hinge) or below_mm / above_mm (slide), or
//       when.body with below_z_m  a body's origin below a height
//   controller.kind               a registered kind (reflex/controller_registry.h):
//                                 "none" | "stretch_reflex" (default) | one added
//   controller.p_max_MPa          valve range for the reflex's commands, > 0
//   reflex.*                      the stretch reflex (reflex/stretch_reflex_controller.h)
//   reflex.pairs                  [[agonist, antagonist], ...] by actuator name; default
//                                 [["agonist", "antagonist"]] when both muscles exist
//   sensors.*                     the sensors (sensing/sensors.h)
//   valve.model                   "iso6358" | "first_order" | "regulator" (pneumatics.h)
//   valve.supply_MPa, valve.command_max_MPa   a rig's own supply and regulator range, in
//                                 place of model.pneumatics' (command max <= supply)
//   valve.dead_time_ms, valve.valve_time_constant_ms, valve.proportional_band_kPa   the
//                                 regulator's loop (valve.model = "regulator") in place of
//                                 model.pneumatics' [regulator]: a point of its bracket
//   valve.feedback ("instant" | "delayed"), valve.sense ("chamber" | "outlet"),
//   valve.sample_period_ms, valve.{supply,exhaust,tube}_sonic_conductance_dm3_per_s_bar,
//   valve.{supply,exhaust,tube}_critical_pressure_ratio, valve.outlet_volume_cm3   the
//                                 same for the loop's feedback path and restrictions
//                                 (pneumatics.toml [regulator] documents each)
// Shorthands kept from pamsim 0.1 (their keys keep their meaning):
//   drop.{enabled, mass_kg, height_m, time_s} (and body = "ball", basket = "basket",
//     site = "basket_floor"): the falling mass: bodies.<body>.mass_kg, a hold of the body
//     height_m above the site, events "release" (at time_s, if enabled) and "impact" (the
//     body touches the basket, after the release); a pamsim 0.1 file (muscles given by
//     model.<actuator>_params, no holds or events) without a [drop] table gets the drop
//     with these defaults, as it did
//   model.<actuator>_params = muscles.<actuator>.params (the agonist and antagonist of
//     these files are labelled "ago" and "anta", as before)
//   pressure.<actuator>_MPa = a constant muscles.<actuator>.command
// A shorthand and its long form may not both be given in the file; a --set of the
// shorthand replaces the long form.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "sim/core/scenario.h"

namespace pamsim {

// Throws InputError "<file>: <key> <problem>" on the first error.
Scenario load_scenario(const std::string& path, const std::vector<std::string>& overrides = {});
// The same from the scenario's text, as if read from `path` (relative paths resolve against
// its folder): a sweep runs every point on the base scenario it validated, even if the file
// changes on disk meanwhile.
Scenario load_scenario_text(const std::string& text, const std::string& path,
                            const std::vector<std::string>& overrides = {});

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
