// calibration.h: solve the fishing-line lengths of the arm so that it rests at the start
// angle (-36 deg in the paper, Sec. IV-D) with both PAMs at the calibration pressures.
//
// At rest the PAM torques balance gravity: sum_i r_i F_i = qfrc_bias, where r_i is the
// actuator's moment arm (from MuJoCo, -R for the agonist, +R for the antagonist) and
// F_i = -f_i the pulling actuator force. The antagonist's deformation is a design choice
// (a small pre-tension); its force f_anta = f(p, d_anta) by Eq. (3); the agonist force then
// follows from the balance, its deformation from inverting Eq. (3), and each line length
// from l_tendon - (l_n(p) + d) (Eq. (1)-(2)). Exact: no iteration, no hand tuning.
#pragma once

#include "sim/core/arm_model.h"

namespace pamsim {

struct CalibrationRequest {
  double start_angle_rad = -0.6283185307179586;   // -36 deg
  double pressure_agonist_pa = 0.4e6;
  double pressure_antagonist_pa = 0.4e6;
  double antagonist_deformation_m = 1.0e-3;
};

// Solves the line lengths on `arm` (whose current line lengths are ignored) and returns
// them. Throws InputError when no physical solution exists (e.g. the agonist cannot
// produce the needed force at that pressure) or the request is out of range.
ArmCalibration solve_calibration(const ArmModel& arm, const CalibrationRequest& request);

// Writes `calibration` into the arm's actuators (line lengths) and arm.calibration.
void apply_calibration(ArmModel* arm, const ArmCalibration& calibration);

}  // namespace pamsim
