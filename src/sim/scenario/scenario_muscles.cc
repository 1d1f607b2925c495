// scenario_muscles.cc: muscles.<actuator>.* (parameter file, label, line, command schedule)
// and the pamsim 0.1 shorthands model.<actuator>_params and pressure.<actuator>_MPa.
#include <cmath>
#include <optional>
#include <set>

#include "base/format.h"
#include "base/toml_file.h"
#include "pam_actuator/plant_params.h"
#include "base/units.h"
#include "sim/scenario/calibration_file.h"
#include "sim/scenario/scenario_key_tables.h"
#include "sim/scenario/scenario_reading.h"
#include "sim/scenario/schedule_key_tables.h"

namespace pamsim {
namespace {

// How far a plant's length and braid angle may be from its estimator file's [geometry]:
// the files' rounding, not a physical allowance
constexpr double kPlantLengthTolerance_m = 0.5e-3;
constexpr double kPlantAngleTolerance_rad = 0.5 * units::kPi / 180.0;

std::string strip(const std::string& s, const std::string& prefix, const std::string& suffix) {
  return s.substr(prefix.size(), s.size() - prefix.size() - suffix.size());
}

// the label pamsim 0.1 gave the arm's muscles in its columns
std::string legacy_label(const std::string& actuator) {
  if (actuator == "agonist") return "ago";
  if (actuator == "antagonist") return "anta";
  return actuator;
}

// The long key, or the shorthand in its place: refused if both are in the file, the
// shorthand wins if it came from --set (the long form it replaces is then ignored, all of
// it). Returns the key to read, or "" if neither is given.
std::string long_or_short(ConfigReader& in, const std::string& long_key,
                          const std::string& short_key) {
  const bool has_long = in.has(long_key), has_short = in.has(short_key);
  if (has_long && has_short && !in.overridden(short_key)) {
    in.fail(short_key, "is the shorthand of " + long_key + "; give one of them");
  }
  if (has_long && has_short) in.raw(long_key);  // marks the replaced long form read
  if (has_short) return short_key;
  return has_long ? long_key : "";
}

PressureSchedule read_command(ConfigReader& in, const std::string& key) {
  in.check(in.is_table(key), key,
           "must be a table: { kind = \"constant\", MPa = ... } or another "
           "schedule (core/schedule.h)");
  PressureSchedule s;
  KeyTable kind = schedule_kind_key_table(&s);
  kind.name = key;
  read_key_rows(in, kind);
  KeyTable rows = schedule_key_table(s.kind, &s);
  rows.name = key;
  read_key_rows(in, rows);
  if (s.kind == ScheduleKind::kSteps) {
    in.check(!s.times_s.empty() && s.times_s.size() == s.values_pa.size(), key + ".MPa",
             "must give one pressure per time in times_s, at least one");
  } else if (s.kind == ScheduleKind::kTable) {
    const std::string file = s.source;  // its row's, resolved
    s = in_file(in, [&] {
      try {
        return read_schedule_column(file, s.column, s.hold);
      } catch (const InputError& e) {
        throw InputError(key + ".file: " + e.what());  // the key, then the CSV's own line
      }
    });
  }
  return s;
}

// the names of the muscles: muscles.<name> tables and the shorthands' <name>s
std::vector<std::string> muscle_names(const ConfigReader& in) {
  std::vector<std::string> names = in.child_keys("muscles");
  std::set<std::string> seen(names.begin(), names.end());
  for (const auto& [table, suffix] : {std::pair{"model", "_params"}, {"pressure", "_MPa"}}) {
    for (const std::string& k : in.child_keys(table)) {
      if (!ends_with(k, suffix)) continue;
      const std::string name = strip(k, "", suffix);
      if (seen.insert(name).second) names.push_back(name);
    }
  }
  return names;
}

// muscles.<m>.plant: the physical plant's file and law; the estimator must describe this
// muscle: its file's [geometry] length (Table I) and braid angle (assumed there), where it
// gives them, are the plant's (the diameter may differ: plant_agonist.toml)
void read_muscle_plant(ConfigReader& in, MuscleSpec* muscle) {
  MuscleSpec& m = *muscle;
  const std::string key = m.key + ".plant";
  // a path, or a table: its file and the fields it changes (plant_params.h)
  const bool changes = in.is_table(key);
  m.plant_file = in.get_input_path(changes ? key + ".file" : key, "");
  if (changes && m.plant_file.empty()) {
    in.fail(key + ".file", "is required (the plant file whose fields " + key + " changes)");
  }
  toml::table fields;
  if (changes) {
    fields = *in.raw(key)->as_table();
    fields.erase("file");
    m.plant_changes = toml_text(fields);
  }
  m.plant = in_file(in, [&] {
    try {
      return load_plant_params(m.plant_file, fields, key + ".").avbdl;
    } catch (const InputError& e) {
      // a changed field is named by its scenario key already; the file's own by the file
      if (e.parts().file.empty() && e.parts().key.rfind(key + ".", 0) == 0) throw;
      throw InputError(key + ": " + e.what());
    }
  });
  if (!m.pam.geometry) return;
  const PamGeometry& g = *m.pam.geometry;
  const auto mismatch = [&](const char* what, double plant, double estimator, const char* unit) {
    return std::string("has a ") + what + " of " + format_value(plant) + " " + unit +
           ", but its estimator's file (" + m.params_file + ", [geometry]) describes " +
           format_value(estimator) + " " + unit +
           ": change both, fitting an estimator to the "
           "changed plant (pamsim tensile --plant FILE --set ..., then pamsim fit) and giving "
           "it as its params file";
  };
  in.check(std::abs(m.plant.length_m - g.length_m) <= kPlantLengthTolerance_m, m.key + ".plant",
           mismatch("length", units::m_to_mm(m.plant.length_m), units::m_to_mm(g.length_m), "mm"));
  in.check(std::abs(m.plant.braid_angle_rad - g.braid_angle_rad) <= kPlantAngleTolerance_rad,
           m.key + ".plant",
           mismatch("braid angle", units::rad_to_deg(m.plant.braid_angle_rad),
                    units::rad_to_deg(g.braid_angle_rad), "deg"));
}

// the command: a schedule, or the shorthand's constant, within what the valve accepts (it
// would clamp the rest silently)
void read_muscle_command(ConfigReader& in, const Scenario& sc, const std::string& name,
                         MuscleSpec* muscle) {
  MuscleSpec& m = *muscle;
  const std::string command_key =
      long_or_short(in, m.key + ".command", "pressure." + name + "_MPa");
  in.check(!command_key.empty(), m.key + ".command", "is required");
  if (command_key == m.key + ".command") {
    m.command = read_command(in, command_key);
  } else {
    read_key_rows(in, pressure_shorthand_key_table(&m.command, name));
  }
  in_file(in, [&] {
    validate(m.command, command_key, sc.pneumatics.command_max_gauge_pa);
    return 0;
  });
}

// an extensible line: its diameter and its material's modulus, both or neither, and its creep
// (the rows' values, each in its range: scenario_key_tables.h)
void set_line_stiffness(ConfigReader& in, const MuscleLineKeys& keys, MuscleSpec* m) {
  const std::string d_key = m->key + ".line_diameter_mm", e_key = m->key + ".line_modulus_MPa";
  if (!keys.diameter_m && !keys.modulus_pa) {
    for (const char* creep : {".line_creep", ".line_creep_time_s", ".line_strength_MPa"}) {
      in.check(!in.has(m->key + creep), m->key + creep,
               "needs an extensible line (line_diameter_mm and line_modulus_MPa)");
    }
    return;
  }
  in.check(keys.diameter_m && keys.modulus_pa, keys.diameter_m ? e_key : d_key,
           "is required with " + (keys.diameter_m ? d_key : e_key) + " (an extensible line)");
  const double radius_m = *keys.diameter_m / 2.0;
  m->line_axial_stiffness_n = *keys.modulus_pa * units::kPi * radius_m * radius_m;
  if (keys.strength_pa) m->line_break_n = *keys.strength_pa * units::kPi * radius_m * radius_m;
  // (its creep, a Kelvin-Voigt element on the line's compliance: read into m by its rows)
}

// the line: fixed, solved, or the calibration's; then its stiffness and working load
void read_muscle_line(ConfigReader& in, const std::string& name, const ArmCalibration* calibration,
                      bool lines_needed, MuscleSpec* muscle) {
  MuscleSpec& m = *muscle;
  MuscleLineKeys keys;
  KeyTable table = muscle_line_key_table(&keys, &m);
  table.name = m.key;
  read_key_rows(in, rows_given(in, table));  // .line sets m.line
  const bool solved = m.line == LineSource::kEquilibrium;
  in.check(!(keys.line_m && solved), m.key + ".line", "and line_mm may not both be given");
  if (keys.line_m) {
    m.line_length_m = *keys.line_m;
  } else if (solved) {
    // its length is solved when the model is bound (trial_lines.cc)
  } else if (!lines_needed) {
    m.line_length_m = 1.0;  // a placeholder: `pamsim calibrate` solves it
  } else {
    const CalibratedLine* c = calibration ? calibration->line(name) : nullptr;
    in.check(
        c != nullptr, m.key + ".line_mm",
        "is required (or .line = \"equilibrium\", or model.calibration with " + name + "_line_mm)");
    m.line_length_m = c->line_length_m;
  }
  set_line_stiffness(in, keys, &m);
  if (keys.limit_n) m.line_limit_n = *keys.limit_n;
}

MuscleSpec read_muscle(ConfigReader& in, const Scenario& sc, const std::string& name,
                       const ArmCalibration* calibration, bool lines_needed) {
  MuscleSpec m;
  m.key = "muscles." + name;
  m.actuator = name;

  // parameter file, by its row or the shorthand's (and the legacy label of the shorthand's arm)
  KeyTable names = muscle_name_key_table(&m);
  names.name = m.key;
  const std::string params_key = long_or_short(in, m.key + ".params", "model." + name + "_params");
  const bool legacy = params_key == "model." + name + "_params";
  KeyTable params = legacy ? params_shorthand_key_table(&m, name) : rows_named(names, {"params"});
  read_key_rows(in, params);
  m.pam = in_file(in, [&] { return load_pam_params(m.params_file); });
  in.check(m.pam.strain_gauge.has_value(), params_key,
           "(" + m.params_file + ") needs a [strain_gauge] table (Eq. (8)): the sensing reads it");
  // the physical plant, when it is not the estimator's law
  if (in.has(m.key + ".plant")) read_muscle_plant(in, &m);
  m.label = legacy ? legacy_label(name) : name;
  read_key_rows(in, rows_named(names, {"label"}));
  in.check(!m.label.empty() && m.label.find_first_of(" ,\"") == std::string::npos, m.key + ".label",
           "must be a non-empty name without spaces, commas or quotes");

  read_muscle_command(in, sc, name, &m);
  read_muscle_line(in, name, calibration, lines_needed, &m);
  read_key_rows(in, rows_named(names, {"spans"}));
  return m;
}

// model.antagonist_deformation_mm: the calibration's pair and pressures, which the trial
// model solves again (trial_lines.cc); their muscles take no line of their own
void read_recalibration(ConfigReader& in, const std::optional<ArmCalibration>& calibration,
                        Scenario* sc) {
  const std::string key = "model.antagonist_deformation_mm";
  in.check(calibration.has_value(), key, "needs model.calibration: the lines it solves again");
  in.check(calibration->lines.size() == 2, key,
           "needs a calibration of two lines (agonist, antagonist); " + sc->calibration_file +
               " has " + std::to_string(calibration->lines.size()));
  for (int k = 0; k < 2; ++k) {
    const CalibratedLine& line = calibration->lines[k];
    const std::string muscle = "muscles." + line.actuator;
    in.check(!in.has(muscle + ".line_mm") && !in.has(muscle + ".line"), key,
             "solves " + muscle + "'s line: it may not give line_mm or line as well");
    sc->calibrated_pair[k] = line.actuator;
    sc->calibrated_pressure_pa[k] = line.pressure_pa;
  }
}

}  // namespace

void read_muscles(ConfigReader& in, Scenario* sc, bool lines_needed) {
  std::optional<ArmCalibration> calibration;
  if (!sc->calibration_file.empty() && lines_needed) {
    calibration = in_file(in, [&] { return load_calibration(sc->calibration_file); });
    sc->has_start_position = true;
    sc->start_position = calibration->start_angle_rad;
  }
  if (sc->antagonist_deformation_m) {  // (calibrate solves the lines by its own options)
    in.check(lines_needed, "model.antagonist_deformation_mm",
             "is not read by pamsim calibrate: give --antagonist-deformation-mm");
    read_recalibration(in, calibration, sc);
  }
  for (const std::string& name : muscle_names(in)) {
    sc->muscles.push_back(
        read_muscle(in, *sc, name, calibration ? &*calibration : nullptr, lines_needed));
  }
  in.check(!sc->muscles.empty(), "muscles", "is required: a table per PAM actuator of the model");
  std::set<std::string> labels;
  for (const MuscleSpec& m : sc->muscles) {
    in.check(labels.insert(m.label).second, m.key + ".label", "repeats label \"" + m.label + "\"");
  }
}

}  // namespace pamsim
