// calibration.cc: see calibration.h.
#include "sim/core/calibration.h"

#include <cmath>

#include "pam_actuator/input_error.h"
#include "pam_actuator/units.h"
#include "sim/io/config_reader.h"
#include "sim/core/pam_callback.h"

namespace pamsim {

ArmCalibration solve_calibration(const ArmModel& arm, const CalibrationRequest& req) {
  if (!(std::fabs(req.start_angle_rad) < units::kPi / 2)) {
    throw InputError("calibrate: --angle-deg must be within (-90, 90), got " +
                     format_value(units::rad_to_deg(req.start_angle_rad)));
  }
  if (!(req.pressure_agonist_pa >= 0 && req.pressure_antagonist_pa >= 0)) {
    throw InputError("calibrate: pressures must be >= 0 MPa");
  }
  if (!(req.antagonist_deformation_m > 0)) {
    throw InputError("calibrate: --antagonist-deformation-mm must be > 0, got " +
                     format_value(units::m_to_mm(req.antagonist_deformation_m)));
  }
  const mjModel* m = arm.model.get();
  MjDataPtr data = make_data(m);
  mjData* d = data.get();

  // gravity torque and moment arms at the start angle, at rest
  d->qpos[arm.shoulder_qpos] = req.start_angle_rad;
  mj_forward(m, d);
  const double gravity_torque = d->qfrc_bias[arm.shoulder_dof];
  const int ago = arm.actuator[kAgonist];
  const int anta = arm.actuator[kAntagonist];
  const double r_ago = d->actuator_moment[ago * m->nv + arm.shoulder_dof];
  const double r_anta = d->actuator_moment[anta * m->nv + arm.shoulder_dof];

  // antagonist: the chosen pre-deformation, its force by Eq. (3)
  const SpringModel& s_ago = arm.pam[kAgonist].spring;
  const SpringModel& s_anta = arm.pam[kAntagonist].spring;
  const double p_ago = req.pressure_agonist_pa;
  const double p_anta = req.pressure_antagonist_pa;
  const double f_anta = spring_force(s_anta, p_anta, req.antagonist_deformation_m);

  // agonist: the force that balances gravity, r_ago (-f_ago) + r_anta (-f_anta) = tau_g
  const double f_ago = -(gravity_torque + r_anta * f_anta) / r_ago;
  const DeformationEstimate est = invert_spring_model(s_ago, p_ago, f_ago);
  if (est.status != InversionStatus::kOk) {
    throw InputError("calibrate: the agonist cannot hold the arm at " +
                     format_value(units::rad_to_deg(req.start_angle_rad)) + " deg: it needs " +
                     format_value(f_ago) + " N at " + format_value(units::pa_to_mpa(p_ago)) +
                     " MPa (" + to_string(est.status) + ")");
  }

  // line length = tendon length - PAM length, PAM length = l_n(p) + d (Eq. (1)-(2))
  ArmCalibration c;
  c.start_angle_rad = req.start_angle_rad;
  c.pressure_pa = {p_ago, p_anta};
  c.antagonist_deformation_m = req.antagonist_deformation_m;
  c.gravity_torque_nm = gravity_torque;
  c.line_length_m[kAgonist] = d->actuator_length[ago] - (natural_length(s_ago, p_ago) + est.d_m);
  c.line_length_m[kAntagonist] =
      d->actuator_length[anta] - (natural_length(s_anta, p_anta) + req.antagonist_deformation_m);
  for (int i = 0; i < kMuscleCount; ++i) {
    if (!(c.line_length_m[i] > 0)) {
      throw InputError(arm.model_path + ": the tendon is shorter than the PAM it holds; "
                       "move the PAM anchors further from the shaft");
    }
  }
  return c;
}

void apply_calibration(ArmModel* arm, const ArmCalibration& calibration) {
  mjModel* m = arm->model.get();
  for (int i = 0; i < kMuscleCount; ++i) {
    store_pam_in_model(m, arm->actuator[i], arm->pam[i].spring, calibration.line_length_m[i], i,
                       arm->model_path.c_str());
  }
  arm->calibration = calibration;
}

}  // namespace pamsim
