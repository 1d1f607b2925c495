// scenario_file.cc: see scenario_file.h. The top level (seed, model, sim, valve, controller,
// reflex, metrics); muscles, events and sensors are read by scenario_muscles.cc,
// scenario_events.cc and scenario_sensors.cc.
#include "sim/scenario/scenario_file.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>

#include "base/toml_file.h"
#include "reflex/controller_registry.h"
#include "sim/core/metrics.h"
#include "sim/core/trial_model.h"
#include "sim/scenario/scenario_key_docs.h"  // trial_only_key
#include "sim/scenario/scenario_key_docs.h"
#include "sim/scenario/scenario_reading.h"
#include "sim/scenario/scenario_hil.h"
#include "sim/scenario/scenario_key_tables.h"

namespace pamsim {
namespace {

// sim.*: each key by its row (scenario_key_tables.h), then what joins them
void read_time(ConfigReader& in, Scenario* sc) {
  double max_steps = kDefaultMaxSteps;
  read_key_rows(in, sim_key_table(sc, &max_steps));
  // every derived count must be a count: a trial of at most sim.max_steps physics steps
  const double steps = sc->duration_s / sc->timestep_s;
  in.check(steps <= max_steps, "sim.timestep_s",
           "of " + format_value(sc->timestep_s) + " s makes " + format_value(steps) +
               " physics steps for " + in.described("sim.duration_s", sc->duration_s) +
               " s, more than " + in.described("sim.max_steps", max_steps) +
               " (raise it to allow)");
  const double ratio = 1.0 / (sc->control_hz * sc->timestep_s);
  in.check(ratio >= 1.0 - 1e-9 && std::fabs(ratio - std::round(ratio)) < 1e-6, "sim.control_hz",
           "must divide the physics rate 1/sim.timestep_s into whole steps: " +
               in.described("sim.control_hz", sc->control_hz) + " Hz at " +
               in.described("sim.timestep_s", sc->timestep_s) + " s");
}

// valve.*: a rig's own supply and regulator range, and a point of the regulator's bracket,
// over the pneumatics file's values
void read_valve(ConfigReader& in, const std::string& valve, Scenario* sc) {
  // each key by the pneumatics file's own row; the regulator's refused with another valve
  // model, which would ignore them, and where not given, no default of the scenario's
  const std::vector<KeyTable> tables = valve_key_tables(&sc->pneumatics);
  const KeyTable& regulator = tables.at(1);
  for (const std::string& key : key_names(regulator)) {
    in.check(!in.has(key) || sc->valve_model == ValveModel::kRegulator, key,
             "is used only by valve.model = \"regulator\", not \"" + valve + "\"");
  }
  read_key_rows(in, tables.at(0));
  read_key_rows(in, rows_given(in, regulator));
  // a rig's supply and command range, and the loop's restrictions, must make sense together
  for (const char* key :
       {"valve.supply_MPa", "valve.command_max_MPa", "valve.supply_critical_pressure_ratio",
        "valve.exhaust_critical_pressure_ratio", "valve.tube_critical_pressure_ratio"}) {
    if (!in.has(key)) continue;
    in_file(in, [&] {
      validate_pneumatic_params(sc->pneumatics, key);
      return 0;
    });
  }
}

// model.pneumatics, with any of its fields changed by pneumatics.<table>.<field>
void read_pneumatics(ConfigReader& in, Scenario* sc) {
  toml::table changes;
  if (in.has("pneumatics")) {
    const toml::node* t = in.raw("pneumatics");
    if (!t->is_table()) in.fail("pneumatics", "must be a table of the pneumatics file's fields");
    changes = *t->as_table();
  }
  sc->pneumatics = in_file(
      in, [&] { return load_pneumatic_params(sc->pneumatics_file, changes, "pneumatics."); });
}

void read_model(ConfigReader& in, Scenario* sc) {
  read_key_rows(in, model_key_table(sc));
  read_pneumatics(in, sc);
  read_key_rows(in, valve_model_key_table(sc));
  read_valve(in, valve_model_name(sc->valve_model), sc);
}

// controller.kind, then the kind's own keys (reflex/controller_registry.h)
void read_controller(ConfigReader& in, Scenario* sc) {
  std::string kind = default_controller_kind();
  read_key_rows(in, controller_kind_key_table(&kind));
  const ControllerKind* chosen = find_controller_kind(kind);  // one of them: the row's choices
  // another kind's section would be ignored: refused (kinds may share one: the reflex kinds
  // all read [reflex], each its own keys of it, and reject_unknown names the rest)
  for (const ControllerKind& other : controller_kinds()) {
    for (const std::string& section : other.sections) {
      const auto& own = chosen->sections;
      if (std::find(own.begin(), own.end(), section) != own.end()) continue;
      in.check(!in.has(section), section,
               "is the " + other.name +
                   " controller's section, but "
                   "controller.kind is \"" +
                   kind + "\"");
    }
  }
  ControllerScenario context;
  context.control_hz = sc->control_hz;
  context.command_max_pa = sc->pneumatics.command_max_gauge_pa;
  for (const MuscleSpec& m : sc->muscles) {
    context.muscles.push_back({m.actuator, m.key, m.command.max_pa()});
  }
  sc->controller_kind = kind;
  sc->controller = chosen->read(in, context);
  // the low-pass the controller needs, applied by the sensing (validated with it)
  sc->sensing.velocity_lowpass_hz = sc->controller->velocity_lowpass_hz;
}

// The controller `assignments` ("reflex.v_thr_mm_s=50") make of the scenario `in` read as
// `sc`: its kind's reader on the document with them set, each a key the kind lets change
// during a trial (ControllerKind::live). Refusals name `where` ("events.faster.set").
std::shared_ptr<const ControllerConfig> controller_with(const ConfigReader& in, const Scenario& sc,
                                                        const std::vector<std::string>& assignments,
                                                        const std::string& where) {
  const ControllerKind* kind = find_controller_kind(sc.controller_kind);
  std::string live;
  for (const LiveSetting& setting : kind->live) live += (live.empty() ? "" : ", ") + setting.key;
  for (const std::string& a : assignments) {
    const std::string key = a.substr(0, a.find('='));
    const bool ok = std::any_of(kind->live.begin(), kind->live.end(),
                                [&](const LiveSetting& setting) { return setting.key == key; });
    in.check(ok, where,
             "sets " + key + ", which cannot change during a trial (controller.kind \"" +
                 sc.controller_kind + "\" lets " + (live.empty() ? "none" : live) + ")");
  }
  ConfigReader changed_in(toml_text(in.document()), in.name());
  Scenario changed = sc;
  try {
    changed_in.apply_overrides(assignments);
    read_controller(changed_in, &changed);
  } catch (const InputError& e) {
    std::string why = e.what();
    if (why.rfind(in.name() + ": ", 0) == 0) why = why.substr(in.name().size() + 2);
    in.fail(where, "is refused: " + why);
  }
  return changed.controller;
}

// every `set` event's controller (EventSpec::controller)
void read_controller_changes(ConfigReader& in, Scenario* sc) {
  for (EventSpec& e : sc->events) {
    if (e.action == EventAction::kSet)
      e.controller = controller_with(in, *sc, e.set, e.key + ".set");
  }
}

void read_metrics(ConfigReader& in, Scenario* sc, bool has_drop) {
  std::vector<std::string> defaults = {"drop", "reflex", "length_estimate"};
  if (!has_drop) {
    defaults = {"tracking", "length_estimate"};
    if (sc->controller_records("stretch_trigger")) defaults.push_back("reflex");
  }
  sc->metrics = defaults;
  read_key_rows(in, metrics_key_table(sc));
  make_metric_sets(*sc);  // throws "<file>: metrics ..." for a set whose events are missing
  // a line's working load is read only by the tension set: refused where it would be ignored
  const bool tension = std::count(sc->metrics.begin(), sc->metrics.end(), "tension") > 0;
  for (const MuscleSpec& m : sc->muscles) {
    in.check(tension || std::isnan(m.line_limit_n), m.key + ".line_limit_N",
             "needs the metric set \"tension\" in metrics (it would be ignored)");
  }
}

// The overrides in order, a plant's two forms kept apart: a --set of a plant's field
// (muscles.<m>.plant.<table>.<field>) where the plant is a path alone makes the path
// muscles.<m>.plant.file first; a --set of the path where the plant is a table already (its
// fields changed) sets its file.
void apply_scenario_overrides(ConfigReader& in, const std::vector<std::string>& overrides) {
  for (const std::string& o : overrides) {
    const std::size_t eq = o.find('=');
    const std::string key = o.substr(0, eq);
    const std::vector<std::string> parts = split_key(key);
    const bool plant = parts.size() >= 3 && parts[0] == "muscles" && parts[2] == "plant";
    if (plant && parts.size() > 3) in.nest_value("muscles." + parts[1] + ".plant", "file");
    const std::size_t start = eq == std::string::npos ? eq : o.find_first_not_of(' ', eq + 1);
    const std::string value = start == std::string::npos ? "" : o.substr(start);
    const bool path = !value.empty() && (value[0] == '"' || value[0] == '\'');
    in.apply_override(
        plant && parts.size() == 3 && path && in.is_table(key) ? key + ".file=" + value : o);
  }
}

// `t` less its trial-only keys (trial_only_key, scenario_key_docs.h), each table walked to its
// leaves; a table left empty goes too where it is a trial-only table itself ([sensors], which
// an override makes), and stays where its presence is read ([drop], [holds])
void drop_trial_only(toml::table* t, const std::string& prefix) {
  for (auto it = t->begin(); it != t->end();) {
    const std::string key = prefix + std::string(it->first.str());
    if (toml::table* sub = it->second.as_table()) {
      drop_trial_only(sub, key + ".");
      it = sub->empty() && trial_only_key(key) ? t->erase(it) : std::next(it);
    } else {
      it = trial_only_key(key) ? t->erase(it) : std::next(it);
    }
  }
}

// Scenario::model_keys: the file's path, then the document as read less its trial-only keys
std::string model_keys(const ConfigReader& in) {
  toml::table doc = in.document();
  drop_trial_only(&doc, "");
  return in.name() + "\n" + toml_text(doc);
}

Scenario read_scenario(ConfigReader& in, const std::vector<std::string>& overrides,
                       bool lines_needed = true) {
  apply_scenario_overrides(in, overrides);
  Scenario sc;
  sc.path = in.name();
  read_key_rows(in, top_level_key_table(&sc));

  read_time(in, &sc);
  read_model(in, &sc);
  read_muscles(in, &sc, lines_needed);
  // a pamsim 0.1 file (muscles by model.<m>_params, no holds or events) always had the drop,
  // with its defaults when it gave no [drop] table
  bool pamsim01 = !in.is_table("holds") && !in.is_table("events");
  bool shorthand_params = false;
  for (const std::string& k : in.child_keys("model")) shorthand_params |= ends_with(k, "_params");
  pamsim01 = pamsim01 && shorthand_params;
  const bool has_drop = in.is_table("drop") || pamsim01;
  read_drop(in, &sc, pamsim01);
  read_bodies_and_holds(in, &sc);
  read_joints(in, &sc);
  read_events(in, &sc);
  read_controller(in, &sc);
  read_controller_changes(in, &sc);
  read_sensors(in, &sc);
  read_metrics(in, &sc, has_drop);
  read_hil(in, &sc);
  in.reject_unknown();
  // (pamsim calibrate's reading has placeholder lines: it shares no model with the others)
  if (lines_needed) sc.model_keys = model_keys(in);
  return sc;
}

}  // namespace

Scenario load_scenario(const std::string& path, const std::vector<std::string>& overrides) {
  ConfigReader in(path);
  return read_scenario(in, overrides);
}

Scenario load_scenario_text(const std::string& text, const std::string& path,
                            const std::vector<std::string>& overrides) {
  ConfigReader in(text, path);
  return read_scenario(in, overrides);
}

std::shared_ptr<const ControllerConfig> load_controller_settings(
    const std::string& text, const std::string& path, const std::vector<std::string>& overrides,
    const std::vector<std::string>& assignments, const std::string& where) {
  ConfigReader in(text, path);
  const Scenario sc = read_scenario(in, overrides);
  return controller_with(in, sc, assignments, where);
}

Scenario load_scenario_for_calibration(const std::string& path,
                                       const std::vector<std::string>& overrides) {
  ConfigReader in(path);
  return read_scenario(in, overrides, false);
}

RecordedScenario load_recorded_scenario(const std::string& text, const std::string& path,
                                        const std::vector<std::string>& overrides,
                                        const std::string& dir, const std::string& header) {
  ConfigReader in(text, path);
  RecordedScenario r;
  r.scenario = read_scenario(in, overrides);  // validates, and finds the defaults
  const std::map<std::string, std::string> defaults = in.defaults_used();
  // file paths: recorded as read, then written relative to the new file's folder
  namespace fs = std::filesystem;
  const fs::path to = fs::weakly_canonical(fs::absolute(dir));
  for (const auto& key : in.leaf_keys()) {
    if (!is_scenario_path_key(key)) continue;
    r.input_paths.emplace_back(key, in.get_path(key, ""));
    const fs::path target = fs::weakly_canonical(fs::absolute(r.input_paths.back().second));
    std::string relative = target.lexically_relative(to).generic_string();
    if (relative.empty()) relative = target.generic_string();
    in.apply_override(key + "=" + toml_value_text(toml::value<std::string>(relative)));
  }
  r.resolved_toml = header + toml_text(in.document());
  if (!defaults.empty()) {
    r.resolved_toml += "\n# Keys left at their defaults, with the values in effect:\n";
    for (const auto& [key, value] : defaults) r.resolved_toml += "# " + key + " = " + value + "\n";
  }
  return r;
}

std::string resolved_scenario_toml(const std::string& text, const std::string& path,
                                   const std::vector<std::string>& overrides,
                                   const std::string& dir, const std::string& header) {
  return load_recorded_scenario(text, path, overrides, dir, header).resolved_toml;
}

std::vector<ScenarioKeyValue> scenario_key_values(const std::string& path,
                                                  const std::vector<std::string>& overrides) {
  ConfigReader in(path);
  read_scenario(in, overrides);
  const std::vector<std::string> asked = in.asked_keys();  // sorted
  std::vector<ScenarioKeyValue> out;
  for (std::size_t i = 0; i < asked.size(); ++i) {
    const std::string& key = asked[i];
    const toml::node_view<const toml::node> node = in.document().at_path(key);
    // a name that may hold a table (muscles.<m>.plant) is a key where the file gives a value
    const bool is_table_name = !(node && !node.is_table()) &&
                               (in.is_table(key) || is_scenario_table(key) ||
                                (i + 1 < asked.size() && asked[i + 1].rfind(key + ".", 0) == 0));
    if (is_table_name) continue;
    ScenarioKeyValue kv{key, "", false};
    if (node) {
      kv.value = toml_value_text(*node.node());
    } else if (const auto d = in.defaults_used().find(key); d != in.defaults_used().end()) {
      kv.value = d->second;
      kv.is_default = true;
    }
    out.push_back(kv);
  }
  return out;
}

bool is_scenario_path_key(const std::string& key) {
  if (key == "model.file" || key == "model.calibration" || key == "model.pneumatics") return true;
  if (key.rfind("model.", 0) == 0 && ends_with(key, "_params")) return true;
  if (key.rfind("muscles.", 0) == 0) {
    return ends_with(key, ".params") || ends_with(key, ".plant") || ends_with(key, ".plant.file") ||
           ends_with(key, ".command.file");
  }
  return false;
}

}  // namespace pamsim
