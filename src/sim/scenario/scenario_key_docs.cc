// scenario_key_docs.cc: see scenario_key_docs.h. Every key is documented by its row
// (base/key_table.h; the shorthands by their long forms' rows, renamed) but those that hand a
// value on to another file's rows: pneumatics.<table>.<field> and a muscle's plant given as a
// table of the plant file's fields (muscles.<actuator>.plant.*), whose lines are here.
#include "sim/scenario/scenario_key_docs.h"
#include "sim/scenario/scenario_hil.h"
#include "sim/scenario/scenario_key_tables.h"
#include "sim/scenario/schedule_key_tables.h"

#include <algorithm>
#include <set>
#include <string>

#include "base/config_reader.h"  // split_key
#include "reflex/controller_registry.h"
#include "sensing/instrument_keys.h"
#include "sensing/instrument_kinds.h"
#include "sensing/sensor_keys.h"

namespace pamsim {
namespace {

bool matches(const std::string& pattern, const std::string& key) {
  const std::vector<std::string> p = split_key(pattern), k = split_key(key);
  if (p.size() != k.size()) return false;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const bool placeholder = p[i].size() > 2 && p[i].front() == '<' && p[i].back() == '>';
    // model.<actuator>_params, pressure.<actuator>_MPa: a placeholder with a suffix
    const auto close = p[i].find('>');
    if (!placeholder && p[i].front() == '<' && close != std::string::npos) {
      const std::string suffix = p[i].substr(close + 1);
      if (k[i].size() <= suffix.size() ||
          k[i].compare(k[i].size() - suffix.size(), suffix.size(), suffix) != 0) {
        return false;
      }
      continue;
    }
    if (!placeholder && p[i] != k[i]) return false;
  }
  return true;
}

// seed, metrics, model, sim, valve, muscles
std::vector<KeyDoc> model_docs() {
  Scenario scenario;  // the rows' defaults are the struct's own
  std::vector<KeyDoc> docs = key_table_docs(
      {top_level_key_table(&scenario), metrics_key_table(&scenario), model_key_table(&scenario)});
  const std::vector<KeyDoc> by_hand = {
      {"pneumatics.<table>.<field>", "(the file's)", "(model.pneumatics')",
       "as in the pneumatics file (pamsim keys --pneumatics)",
       "a field of the pneumatics file, e.g. chamber.tube_dead_volume_cm3, gas.polytropic_index",
       true},
      {"muscles.<actuator>.plant", "", "(the params file's law)",
       "path to a plant file; or a table: file and any of that file's fields in its units "
       "(muscles.<m>.plant.geometry.wall_thickness_mm = 1.5), each validated as the file's own",
       "the physical muscle (AVBDL law with friction)"},
      {"muscles.<actuator>.plant.file", "", "(required in the table form)", "path to a plant file",
       "the plant file whose fields muscles.<actuator>.plant.<table>.<field> change"},
      {"muscles.<actuator>.plant.<table>.<field>", "(the file's)", "(the plant file's)",
       "as in the plant file (pam_actuator/plant_params.h)",
       "a field of the plant file, e.g. geometry.wall_thickness_mm, bladder.diameter_mm"},
      {"muscles.<actuator>.plant.<table>.<stroke>.<field>", "(the file's)", "(the plant file's)",
       "as in the plant file (pam_actuator/plant_params.h)",
       "a field of the plant file's friction strokes, e.g. friction.extension.A0_mm2"},
  };
  docs.insert(docs.end(), by_hand.begin(), by_hand.end());
  MuscleSpec muscle;  // the shorthands: their long forms' rows, renamed
  for (const KeyDoc& d :
       key_table_docs({params_shorthand_key_table(&muscle, "<actuator>"),
                       pressure_shorthand_key_table(&muscle.command, "<actuator>")})) {
    docs.push_back(d);
  }
  return docs;
}

// muscles.<actuator>.command: its kind's row, then each kind's rows (schedule_key_tables.h)
std::vector<KeyDoc> schedule_docs() {
  PressureSchedule defaults;
  std::vector<KeyDoc> docs = key_table_docs({schedule_kind_key_table(&defaults)});
  for (ScheduleKind kind : schedule_kinds()) {
    const std::string with_kind = std::string("kind = \"") + to_string(kind) + "\": ";
    for (const KeyDoc& d : key_table_docs({schedule_key_table(kind, &defaults)})) {
      const auto same =
          std::find_if(docs.begin(), docs.end(), [&](const KeyDoc& e) { return e.key == d.key; });
      if (same == docs.end()) {  // a key of one kind, or the first kind that has it
        docs.push_back({d.key, d.unit, d.fallback, with_kind + d.allowed, with_kind + d.meaning});
      } else {  // one key, several kinds (start_s, MPa): one line
        same->allowed += "; " + with_kind + d.allowed;
        same->meaning += "; " + with_kind + d.meaning;
        if (same->fallback != d.fallback) same->fallback = "(by kind)";
      }
    }
  }
  return docs;
}

// the muscles' names and lines, bodies and holds: their rows (scenario_key_tables.h)
std::vector<KeyDoc> body_and_hold_docs() {
  BodyKeys body;
  HoldSpec hold;
  std::vector<double> position;
  MuscleLineKeys line;
  MuscleSpec muscle;
  return key_table_docs({muscle_name_key_table(&muscle), muscle_line_key_table(&line, &muscle),
                         body_key_table(&body), hold_key_table(&hold, &position)});
}

// events
std::vector<KeyDoc> event_docs() {
  EventSpec event;
  EventThresholds thresholds;
  return key_table_docs({event_key_table(&event), event_when_key_table(&event, &thresholds)});
}

// valve.*'s numbers and choices: the pneumatics file's rows (scenario_key_tables.h), each
// defaulting to the file's value
std::vector<KeyDoc> valve_docs() {
  PneumaticParams defaults;
  const std::vector<KeyTable> tables = valve_key_tables(&defaults);
  std::vector<KeyDoc> docs = key_table_docs({tables.at(0)});
  for (KeyDoc& d : docs) d.fallback = "(model.pneumatics')";
  Scenario scenario;  // the row's default is the struct's own
  const std::vector<KeyDoc> model = key_table_docs({valve_model_key_table(&scenario)});
  docs.insert(docs.begin(), model.begin(), model.end());
  for (KeyDoc d : key_table_docs({tables.at(1)})) {
    d.fallback = "(model.pneumatics' [regulator])";
    d.allowed += "; valve.model = \"regulator\"";
    docs.push_back(d);
  }
  return docs;
}

// joints.<joint>.*: a hinge's rows and a slide's (scenario_key_tables.h)
std::vector<KeyDoc> joint_docs() {
  JointSpec defaults;
  std::vector<KeyDoc> docs;
  const std::pair<KeyTable, const char*> kinds[] = {{hinge_key_table(&defaults), "; a hinge"},
                                                    {slide_key_table(&defaults), "; a slide"}};
  for (const auto& [table, kind] : kinds) {
    for (KeyDoc d : key_table_docs({table})) {
      d.fallback = "(the model's)";
      d.allowed += kind;
      docs.push_back(d);
    }
  }
  return docs;
}

// [sim] and the drop's numbers (scenario_key_tables.h)
std::vector<KeyDoc> time_and_drop_docs() {
  Scenario scenario;  // the rows' defaults are the struct's own
  double max_steps = kDefaultMaxSteps;
  DropShorthand drop;
  return key_table_docs({sim_key_table(&scenario, &max_steps), drop_key_table(&drop)});
}

std::vector<KeyDoc> hil_docs() {
  HilSpec defaults;  // the rows' defaults are the struct's own
  return key_table_docs({hil_key_table(&defaults)});
}

std::vector<KeyDoc> sensor_docs() {
  SensorConfig defaults;  // the rows' defaults are the struct's own
  return key_table_docs({sensor_key_table(&defaults)});
}

// the instruments as hardware: their rows (sensing/instrument_keys.h), then the keys outside
// them, the creep series and the instruments' seed
std::vector<KeyDoc> instrument_docs() {
  SensorConfig defaults;  // the rows' defaults are the structs' own
  std::vector<KeyDoc> docs = key_table_docs(instrument_key_tables(&defaults));
  KeyTable own = gauge_contact_key_table(&defaults.gauge_hardware.contact);  // a muscle's
  own.name = "muscles.<actuator>.gauge.contact";
  for (NumberRow& row : own.numbers) row.fallback_doc = "(sensors.gauge.contact's)";
  for (const KeyDoc& d : key_table_docs({own})) docs.push_back(d);
  for (const InstrumentKind& kind : instrument_kinds()) {  // the creep series' rows
    if (!kind.creep) continue;
    std::vector<double> weights, times;
    prony_lists(*kind.creep(&defaults), &weights, &times);
    for (const KeyDoc& d : key_table_docs({creep_key_table(kind, &weights, &times)})) {
      docs.push_back(d);
    }
  }
  return docs;
}

// controller.kind and each kind's keys (reflex/controller_kind.h, in the kind's own file); a
// key that several kinds read (the reflex kinds share reflex.*) is listed once, as the first
// kind documents it
std::vector<KeyDoc> controller_docs() {
  std::string kind = default_controller_kind();
  std::vector<KeyDoc> docs = key_table_docs({controller_kind_key_table(&kind)});
  std::set<std::string> listed;
  for (const ControllerKind& kind : controller_kinds()) {
    for (const KeyDoc& d : kind.docs) {
      if (listed.insert(d.key).second) docs.push_back(d);
    }
  }
  return docs;
}

std::vector<KeyDoc> all_docs() {
  std::vector<KeyDoc> docs;
  for (const std::vector<KeyDoc>& part :
       {model_docs(), schedule_docs(), valve_docs(), joint_docs(), time_and_drop_docs(),
        body_and_hold_docs(), event_docs(), controller_docs(), sensor_docs(), instrument_docs(),
        hil_docs()}) {
    docs.insert(docs.end(), part.begin(), part.end());
  }
  return docs;
}

}  // namespace

const std::vector<KeyDoc>& scenario_key_docs() {
  static const std::vector<KeyDoc> docs = all_docs();
  return docs;
}

bool is_scenario_table(const std::string& key) {
  const std::size_t depth = split_key(key).size();
  for (const KeyDoc& d : scenario_key_docs()) {
    std::vector<std::string> parts = split_key(d.key);
    if (parts.size() <= depth) continue;
    std::string prefix = parts[0];
    for (std::size_t i = 1; i < depth; ++i) prefix += "." + parts[i];
    if (matches(prefix, key)) return true;
  }
  return false;
}

bool trial_only_key(const std::string& key) {
  if (const KeyDoc* d = scenario_key_doc(key)) return d->trial_only;
  const std::size_t depth = split_key(key).size();
  bool any = false;
  for (const KeyDoc& d : scenario_key_docs()) {
    const std::vector<std::string> parts = split_key(d.key);
    if (parts.size() <= depth) continue;
    std::string prefix = parts[0];
    for (std::size_t i = 1; i < depth; ++i) prefix += "." + parts[i];
    if (!matches(prefix, key)) continue;
    if (!d.trial_only) return false;
    any = true;
  }
  return any;
}

const KeyDoc* scenario_key_doc(const std::string& key) {
  for (const KeyDoc& d : scenario_key_docs()) {
    if (matches(d.key, key)) return &d;
  }
  return nullptr;
}

}  // namespace pamsim
