// identify_start.cc: start_values of identify_outputs.h: each parameter's value in the model
// as it stands (the base scenario with the file's overrides), where identification starts
// from: a sensor's neutral value, a plant's field as the scenario changes it (else as its
// file gives it), the pneumatics file's field from that file, a valve's field as the
// scenario's valve runs it, a joint's losses and a body's mass from the loaded model, any
// other key from the scenario (its value or default).
#include <cmath>

#include "base/config_reader.h"
#include "base/no_value.h"
#include "base/toml_file.h"
#include "sim/core/trial_model.h"
#include "sim/scenario/scenario_file.h"
#include "sim/scenario/scenario_key_tables.h"
#include "sim/optimize/identify_outputs.h"

namespace pamsim {
namespace {

// the number at dotted `path` of the TOML file `file`, NaN if there is none
double file_value(const std::string& file, const std::string& path) {
  const toml::table root = parse_toml_file(file);
  const auto node = root.at_path(path);
  return node && node.is_number() ? node.value<double>().value_or(kNaN) : kNaN;
}

// a plant's field at dotted `path`: the scenario's own change of it (muscles.<m>.plant as a
// table, or a --set of the field), else the plant file's
double plant_value(const MuscleSpec& m, const std::string& path) {
  if (!m.plant_changes.empty()) {
    const toml::table changes = parse_toml_text(m.plant_changes, m.key + ".plant");
    const auto node = changes.at_path(path);
    if (node && node.is_number()) return node.value<double>().value_or(kNaN);
  }
  return file_value(m.plant_file, path);
}

// joints.<j>.damping_* / frictionloss_*, bodies.<b>.mass_kg: the bound model's
double model_value(const TrialModel& tm, const std::vector<std::string>& parts) {
  const mjModel* m = tm.model.get();
  if (parts.size() != 3) return kNaN;
  if (parts[0] == "bodies" && parts[2] == "mass_kg") {
    const int b = mj_name2id(m, mjOBJ_BODY, parts[1].c_str());
    return b >= 0 ? m->body_mass[b] : kNaN;
  }
  if (parts[0] != "joints") return kNaN;
  const int j = mj_name2id(m, mjOBJ_JOINT, parts[1].c_str());
  if (j < 0) return kNaN;
  const int dof = m->jnt_dofadr[j];
  if (parts[2].rfind("damping_", 0) == 0) return m->dof_damping[dof];
  if (parts[2].rfind("frictionloss_", 0) == 0) return m->dof_frictionloss[dof];
  return kNaN;
}

// valve.<field>: the value the scenario's valve runs with (its own, else the pneumatics
// file's), through the rows that read it, in the key's unit
double valve_value(const Scenario& sc, const std::vector<std::string>& parts) {
  if (parts.size() != 2 || parts[0] != "valve") return kNaN;
  PneumaticParams pneumatics = sc.pneumatics;
  for (const KeyTable& table : valve_key_tables(&pneumatics)) {
    for (const NumberRow& row : table.numbers) {
      if (row.name == parts[1] && row.target) return *row.target * row.divisor / row.to_si;
    }
  }
  return kNaN;
}

double scenario_value(const IdentifyDefinition& def, const std::string& key) {
  for (const ScenarioKeyValue& kv : scenario_key_values(def.base_path, def.overrides)) {
    if (kv.key != key || kv.value.empty()) continue;
    char* end = nullptr;
    const double v = std::strtod(kv.value.c_str(), &end);
    return end != kv.value.c_str() ? v : kNaN;
  }
  return kNaN;
}

double start_of(const IdentifyDefinition& def, std::size_t i, const Scenario& sc,
                const TrialModel& tm) {
  const ChannelParameter::Kind kind = def.channel_parameters[i].kind;
  if (kind != ChannelParameter::Kind::kNone) {
    return kind == ChannelParameter::Kind::kGain ? 1.0 : 0.0;
  }
  const std::string& key = def.parameters[i].key;
  const std::vector<std::string> parts = split_key(key);
  if (parts.size() > 3 && parts[0] == "muscles" && parts[2] == "plant") {
    for (const MuscleSpec& m : sc.muscles) {
      if (m.actuator == parts[1] && !m.plant_file.empty()) {
        return plant_value(m, key.substr(("muscles." + parts[1] + ".plant.").size()));
      }
    }
  }
  if (parts.size() > 1 && parts[0] == "pneumatics") {
    return file_value(sc.pneumatics_file, key.substr(std::string("pneumatics.").size()));
  }
  const double from_valve = valve_value(sc, parts);
  if (!std::isnan(from_valve)) return from_valve;
  const double from_model = model_value(tm, parts);
  return std::isnan(from_model) ? scenario_value(def, key) : from_model;
}

}  // namespace

std::vector<double> start_values(const IdentifyDefinition& def) {
  const Scenario sc = load_scenario_text(def.base_text, def.base_path, def.overrides);
  const TrialModel tm = load_trial_model(sc);
  std::vector<double> out;
  for (std::size_t i = 0; i < def.parameters.size(); ++i) out.push_back(start_of(def, i, sc, tm));
  return out;
}

}  // namespace pamsim
