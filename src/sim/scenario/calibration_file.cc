// calibration_file.cc: see calibration_file.h.
#include "sim/scenario/calibration_file.h"

#include <algorithm>
#include <sstream>
#include <utility>

#include "base/config_reader.h"
#include "base/toml_file.h"
#include "base/units.h"

namespace pamsim {
namespace {

constexpr char kLineSuffix[] = "_line_mm";

// The actuators a calibration file calibrates, from its <actuator>_line_mm keys, in the
// file's order.
std::vector<std::string> calibrated_actuators(const toml::table& doc) {
  std::vector<std::pair<toml::source_index, std::string>> found;
  const std::string suffix = kLineSuffix;
  for (const auto& [key, node] : doc) {
    const std::string name(key.str());
    if (name.size() > suffix.size() && ends_with(name, suffix)) {
      found.emplace_back(node.source().begin.line, name.substr(0, name.size() - suffix.size()));
    }
  }
  std::stable_sort(found.begin(), found.end());
  std::vector<std::string> actuators;
  for (const auto& f : found) actuators.push_back(f.second);
  return actuators;
}

}  // namespace

std::vector<KeyTable> calibration_key_tables(ArmCalibration* c) {
  NumberRow start{"start_angle_deg",
                  "deg",
                  units::kPi,
                  KeyRange{-90.0, 90.0, true, true},
                  "the calibrated joint's angle at rest at the start",
                  &c->start_angle_rad};
  start.required = true;
  start.divisor = 180.0;  // units::deg_to_rad's rounding
  KeyTable t{
      "",
      {start,
       {"antagonist_deformation_mm", "mm", units::kMPerMm, kAnyRange,
        "the antagonist's chosen pre-stretch at the start (a small pre-tension)",
        &c->antagonist_deformation_m},
       {"gravity_torque_Nm", "N m", 1.0, kAnyRange,
        "what the PAMs hold against gravity at the start, for the record", &c->gravity_torque_nm}},
      {}};
  t.texts = {{"written_by", "the program and version that wrote the file", &c->written_by}};
  for (CalibratedLine& line : c->lines) {
    NumberRow length{line.actuator + kLineSuffix,
                     "mm",
                     units::kMPerMm,
                     kPositiveRange,
                     "the muscle's line length (tendon length minus PAM length) at the start",
                     &line.line_length_m};
    NumberRow pressure{line.actuator + "_pressure_MPa",
                       "MPa",
                       units::kPaPerMPa,
                       kAnyRange,
                       "the muscle's pressure the line length was solved for",
                       &line.pressure_pa};
    length.required = pressure.required = true;
    t.numbers.push_back(length);
    t.numbers.push_back(pressure);
  }
  return {t};
}

std::vector<KeyDoc> calibration_key_docs() {
  ArmCalibration c;
  c.lines = {CalibratedLine{"<actuator>", 0.0, 0.0}};
  return key_table_docs(calibration_key_tables(&c));
}

ArmCalibration load_calibration(const std::string& path) {
  const toml::table doc = parse_toml_file(path);
  ArmCalibration c;
  for (std::string& actuator : calibrated_actuators(doc)) {
    c.lines.push_back(CalibratedLine{std::move(actuator), 0.0, 0.0});
  }
  read_key_tables(doc, path, calibration_key_tables(&c));
  return c;
}

std::string calibration_to_toml(const ArmCalibration& c, const std::string& provenance) {
  std::ostringstream out;
  out.precision(12);
  out << "# Arm calibration: fishing-line lengths (tendon length minus PAM length) that hold the\n"
      << "# arm at rest at start_angle_deg with both PAMs at the given pressures and the\n"
      << "# antagonist stretched by antagonist_deformation_mm (a design choice: a small\n"
      << "# pre-tension so neither line is slack at the start). Written by `pamsim calibrate`.\n"
      << "written_by = " << toml::value<std::string>(provenance) << "\n"  // TOML-escaped
      << "start_angle_deg = " << units::rad_to_deg(c.start_angle_rad) << "\n";
  for (const CalibratedLine& l : c.lines) {
    out << l.actuator << "_pressure_MPa = " << units::pa_to_mpa(l.pressure_pa) << "\n";
  }
  out << "antagonist_deformation_mm = " << units::m_to_mm(c.antagonist_deformation_m) << "\n"
      << "gravity_torque_Nm = " << c.gravity_torque_nm << "\n";
  for (const CalibratedLine& l : c.lines) {
    out << l.actuator << "_line_mm = " << units::m_to_mm(l.line_length_m) << "\n";
  }
  return out.str();
}

}  // namespace pamsim
