// calibration_file.cc: see calibration_file.h.
#include "sim/scenario/calibration_file.h"

#include <cmath>
#include <sstream>

#include "base/units.h"
#include "base/config_reader.h"

namespace pamsim {
ArmCalibration load_calibration(const std::string& path) {
  ConfigReader in(path);
  ArmCalibration c;
  c.start_angle_rad = units::deg_to_rad(in.require_double("start_angle_deg"));
  in.check(std::fabs(c.start_angle_rad) < units::kPi / 2, "start_angle_deg",
           "must be within (-90, 90) deg");
  c.antagonist_deformation_m = units::mm_to_m(in.get_double("antagonist_deformation_mm", 0.0));
  c.gravity_torque_nm = in.get_double("gravity_torque_Nm", 0.0);
  in.get_string("written_by", "");

  // <actuator>_line_mm with its <actuator>_pressure_MPa, in the file's order
  for (const std::string& key : in.child_keys("")) {
    if (!ends_with(key, "_line_mm")) continue;
    CalibratedLine line;
    line.actuator = key.substr(0, key.size() - std::string("_line_mm").size());
    line.line_length_m = units::mm_to_m(in.require_double(key));
    in.check(line.line_length_m > 0, key, "must be > 0");
    line.pressure_pa = units::mpa_to_pa(in.require_double(line.actuator + "_pressure_MPa"));
    c.lines.push_back(line);
  }
  in.reject_unknown();
  return c;
}

std::string calibration_to_toml(const ArmCalibration& c, const std::string& provenance) {
  std::ostringstream out;
  out.precision(12);
  out << "# Arm calibration: fishing-line lengths (tendon length minus PAM length) that hold the\n"
      << "# arm at rest at start_angle_deg with both PAMs at the given pressures and the\n"
      << "# antagonist stretched by antagonist_deformation_mm (a design choice: a small\n"
      << "# pre-tension so neither line is slack at the start). Written by `pamsim calibrate`.\n"
      << "written_by = " << toml::value<std::string>(provenance) << "\n"   // TOML-escaped
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
