// calibration_file.h: reads and writes the calibration file of `pamsim calibrate`
// (models/arm_2pam_calibration.toml): start_angle_deg, and per calibrated muscle
// <actuator>_line_mm and <actuator>_pressure_MPa, with antagonist_deformation_mm,
// gravity_torque_Nm and written_by for the record. Its keys are rows (base/key_table.h):
// the reader, the range checks and `pamsim keys --calibration` come from them.
#pragma once

#include <string>
#include <vector>

#include "base/key_table.h"
#include "sim/core/calibration.h"

namespace pamsim {

// The file's rows, bound to `c`'s fields: its own keys, then each of c->lines' two keys
// (<actuator>_line_mm, <actuator>_pressure_MPa), one table, the file's top level.
std::vector<KeyTable> calibration_key_tables(ArmCalibration* c);

// The keys as a reference shows them, a calibrated muscle's as <actuator>_line_mm.
std::vector<KeyDoc> calibration_key_docs();

// Throws InputError "<path>: <key>: <problem>" (missing file or key, a line <= 0, a start
// angle outside (-90, 90) deg, a pressure without its line, an unknown key).
ArmCalibration load_calibration(const std::string& path);
std::string calibration_to_toml(const ArmCalibration& c, const std::string& provenance);

}  // namespace pamsim
