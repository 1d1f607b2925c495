// calibration_file.h: reads and writes the calibration file of `pamsim calibrate`
// (models/arm_2pam_calibration.toml): start_angle_deg, and per calibrated muscle
// <actuator>_line_mm and <actuator>_pressure_MPa, with antagonist_deformation_mm,
// gravity_torque_Nm and written_by for the record.
#pragma once

#include <string>

#include "sim/core/calibration.h"

namespace pamsim {

// Throws InputError "<path>: <key> <problem>" (missing file or key, a line <= 0, a start
// angle outside (-90, 90) deg, an unknown key).
ArmCalibration load_calibration(const std::string& path);
std::string calibration_to_toml(const ArmCalibration& c, const std::string& provenance);

}  // namespace pamsim
