// calibration.cc: see calibration.h.
#include "sim/core/calibration.h"

#include <cmath>

#include "base/format.h"
#include "base/input_error.h"
#include "base/units.h"
#include "sim/core/muscle_law.h"

namespace pamsim {
namespace {

// Throws InputError for a start angle outside (-90, 90) deg, a negative pressure, a
// pre-deformation <= 0, or a joint that is not a hinge.
void check_calibration_request(const TrialModel& tm, const CalibrationRequest& req) {
  if (!(std::fabs(req.start_angle_rad) < units::kPi / 2)) {
    throw InputError(req.where + ": --angle-deg must be within (-90, 90), got " +
                     format_value(units::rad_to_deg(req.start_angle_rad)));
  }
  if (!(req.pressure_agonist_pa >= 0 && req.pressure_antagonist_pa >= 0)) {
    throw InputError(req.where + ": pressures must be >= 0 MPa");
  }
  if (!(req.antagonist_deformation_m > 0)) {
    throw InputError(req.where + ": --antagonist-deformation-mm must be > 0, got " +
                     format_value(units::m_to_mm(req.antagonist_deformation_m)));
  }
  if (!tm.joint.hinge)
    throw InputError(req.where + ": joint '" + tm.joint.name + "' is not a hinge");
}

// Throws InputError where a solved line is not longer than 0 (a tendon shorter than its PAM).
void check_line_lengths(const TrialModel& tm, const ArmCalibration& c) {
  for (const CalibratedLine& line : c.lines) {
    if (!(line.line_length_m > 0)) {
      throw InputError(tm.model_path +
                       ": the tendon is shorter than the PAM it holds; "
                       "move the PAM anchors further from the shaft");
    }
  }
}

}  // namespace

const CalibratedLine* ArmCalibration::line(const std::string& actuator) const {
  for (const CalibratedLine& l : lines) {
    if (l.actuator == actuator) return &l;
  }
  return nullptr;
}

ArmCalibration solve_calibration(const TrialModel& tm, const Scenario& sc, const ReflexPair& pair,
                                 const CalibrationRequest& req) {
  check_calibration_request(tm, req);
  const mjModel* m = tm.model.get();
  MjDataPtr data = make_data(m);
  mjData* d = data.get();

  // gravity torque and moment arms at the start angle, at rest, every other joint at its
  // start key (joints.<j>.start_deg|mm; one on the calibrated joint is the request's angle
  // here, and refused when a scenario reads its calibration)
  tm.place_at_start(sc, d);
  d->qpos[tm.joint.qpos] = req.start_angle_rad;
  mj_forward(m, d);
  const int dof = tm.joint.dof;
  const double gravity_torque = d->qfrc_bias[dof];
  const BoundMuscle& ago = tm.muscles[pair.agonist];
  const BoundMuscle& anta = tm.muscles[pair.antagonist];
  const double r_ago = d->actuator_moment[ago.actuator * m->nv + dof];
  const double r_anta = d->actuator_moment[anta.actuator * m->nv + dof];

  // antagonist: the chosen pre-deformation past its plant's free length, its force by the
  // plant's law (Eq. (3) when the plant is the spring law)
  const MuscleSpec& m_ago = sc.muscles[ago.spec];
  const MuscleSpec& m_anta = sc.muscles[anta.spec];
  const double p_ago = req.pressure_agonist_pa;
  const double p_anta = req.pressure_antagonist_pa;
  const double l_anta = plant_free_length(m_anta, p_anta) + req.antagonist_deformation_m;
  const double f_anta = plant_static_force(m_anta, p_anta, l_anta);
  if (!std::isfinite(f_anta)) {
    throw InputError(req.where + ": the antagonist's plant has no force " +
                     format_value(units::m_to_mm(req.antagonist_deformation_m)) +
                     " mm past its free length at " + format_value(units::pa_to_mpa(p_anta)) +
                     " MPa");
  }

  // agonist: the force that balances gravity, r_ago (-f_ago) + r_anta (-f_anta) = tau_g
  const double f_ago = -(gravity_torque + r_anta * f_anta) / r_ago;
  const double l_ago = plant_length_at_force(m_ago, p_ago, f_ago);
  if (!(l_ago > 0)) {
    throw InputError(req.where + ": the agonist cannot hold the arm at " +
                     format_value(units::rad_to_deg(req.start_angle_rad)) + " deg: it needs " +
                     format_value(f_ago) + " N at " + format_value(units::pa_to_mpa(p_ago)) +
                     " MPa");
  }

  // line length = tendon length - PAM length
  ArmCalibration c;
  c.start_angle_rad = req.start_angle_rad;
  c.antagonist_deformation_m = req.antagonist_deformation_m;
  c.gravity_torque_nm = gravity_torque;
  c.lines.push_back({m_ago.actuator, d->actuator_length[ago.actuator] - l_ago, p_ago});
  c.lines.push_back({m_anta.actuator, d->actuator_length[anta.actuator] - l_anta, p_anta});
  check_line_lengths(tm, c);
  return c;
}

}  // namespace pamsim
