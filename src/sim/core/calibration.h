// calibration.h: solve the fishing-line lengths of an antagonistic pair so that the arm
// rests at the start angle (-36 deg in the paper, Sec. IV-D) with both PAMs at the
// calibration pressures, the model's other joints at their start keys. (`pamsim calibrate`;
// the result is read back by model.calibration.)
//
// At rest the PAM torques balance gravity: sum_i r_i F_i = qfrc_bias, where r_i is the
// actuator's moment arm on the joint (from MuJoCo) and F_i = -f_i the pulling actuator
// force. The antagonist's deformation is a design choice (a small pre-tension); its force
// f_anta = f(p, d_anta) by Eq. (3); the agonist force then follows from the balance, its
// deformation from inverting Eq. (3), and each line length from l_tendon - (l_n(p) + d)
// (Eq. (1)-(2)). Exact: no iteration, no hand tuning.
#pragma once

#include <string>
#include <vector>

#include "sim/core/scenario.h"
#include "sim/core/trial_model.h"

namespace pamsim {

// One muscle's calibrated line: <actuator>_line_mm and <actuator>_pressure_MPa in the file.
struct CalibratedLine {
  std::string actuator;
  double line_length_m = 0.0;
  double pressure_pa = 0.0;  // the pressure it was solved for
};

// The calibration file (models/arm_2pam_calibration.toml): the joint's start angle and the
// line lengths, in the pair's order (agonist, antagonist).
struct ArmCalibration {
  double start_angle_rad = 0.0;
  std::vector<CalibratedLine> lines;
  double antagonist_deformation_m = 0.0;  // the chosen pre-deformation
  double gravity_torque_nm = 0.0;         // what the PAMs hold at the start
  std::string written_by;                 // the file's record of what wrote it
  // The line of an actuator, or nullptr.
  const CalibratedLine* line(const std::string& actuator) const;
};

struct CalibrationRequest {
  double start_angle_rad = -0.6283185307179586;  // -36 deg
  double pressure_agonist_pa = 0.4e6;
  double pressure_antagonist_pa = 0.4e6;
  double antagonist_deformation_m = 1.0e-3;
  std::string where = "calibrate";  // what its errors name first: the command, or a key
};

// Solves the line lengths of `pair` (muscle indices of `model`, whose current line lengths
// are ignored) on the model's joint. Throws InputError when no physical solution exists
// (e.g. the agonist cannot produce the needed force at that pressure) or the request is
// out of range.
ArmCalibration solve_calibration(const TrialModel& model, const Scenario& scenario,
                                 const ReflexPair& pair, const CalibrationRequest& request);

}  // namespace pamsim
