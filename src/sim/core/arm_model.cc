// arm_model.cc: see arm_model.h.
#include "sim/core/arm_model.h"

#include <cmath>
#include <sstream>

#include "pam_actuator/input_error.h"
#include "pam_actuator/units.h"
#include "sim/io/config_reader.h"
#include "sim/core/pam_callback.h"

namespace pamsim {
namespace {

const char* kActuatorNames[kMuscleCount] = {"agonist", "antagonist"};

}  // namespace

ArmCalibration load_calibration(const std::string& path) {
  ConfigReader in(path);
  ArmCalibration c;
  c.start_angle_rad = units::deg_to_rad(in.require_double("start_angle_deg"));
  c.line_length_m[kAgonist] = units::mm_to_m(in.require_double("agonist_line_mm"));
  c.line_length_m[kAntagonist] = units::mm_to_m(in.require_double("antagonist_line_mm"));
  c.pressure_pa[kAgonist] = units::mpa_to_pa(in.require_double("agonist_pressure_MPa"));
  c.pressure_pa[kAntagonist] = units::mpa_to_pa(in.require_double("antagonist_pressure_MPa"));
  c.antagonist_deformation_m = units::mm_to_m(in.require_double("antagonist_deformation_mm"));
  c.gravity_torque_nm = in.get_double("gravity_torque_Nm", 0.0);
  in.get_string("written_by", "");
  in.check(c.line_length_m[kAgonist] > 0, "agonist_line_mm", "must be > 0");
  in.check(c.line_length_m[kAntagonist] > 0, "antagonist_line_mm", "must be > 0");
  in.check(std::fabs(c.start_angle_rad) < units::kPi / 2, "start_angle_deg",
           "must be within (-90, 90) deg");
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
      << "written_by = \"" << provenance << "\"\n"
      << "start_angle_deg = " << units::rad_to_deg(c.start_angle_rad) << "\n"
      << "agonist_pressure_MPa = " << units::pa_to_mpa(c.pressure_pa[kAgonist]) << "\n"
      << "antagonist_pressure_MPa = " << units::pa_to_mpa(c.pressure_pa[kAntagonist]) << "\n"
      << "antagonist_deformation_mm = " << units::m_to_mm(c.antagonist_deformation_m) << "\n"
      << "gravity_torque_Nm = " << c.gravity_torque_nm << "\n"
      << "agonist_line_mm = " << units::m_to_mm(c.line_length_m[kAgonist]) << "\n"
      << "antagonist_line_mm = " << units::m_to_mm(c.line_length_m[kAntagonist]) << "\n";
  return out.str();
}

BraidGeometry braid_of(const PamParams& pam) {
  if (!pam.geometry) {
    throw InputError(pam.name + ": PAM parameters need a [geometry] table for the chamber volume");
  }
  return braid_from_initial_shape(pam.geometry->length_m, pam.geometry->sleeve_diameter_m,
                                  pam.geometry->braid_angle_rad);
}

ArmModel load_arm_model(const std::string& mjcf_path,
                        const std::array<PamParams, kMuscleCount>& pam,
                        const ArmCalibration& calibration, double ball_mass_kg) {
  ArmModel arm;
  arm.model_path = mjcf_path;
  arm.model = load_mjcf(mjcf_path);
  arm.calibration = calibration;
  arm.pam = pam;
  mjModel* m = arm.model.get();
  const char* path = mjcf_path.c_str();

  // the PAMs: parameters and line lengths into the actuators, pressures in userdata[0..1]
  for (int i = 0; i < kMuscleCount; ++i) {
    arm.actuator[i] = require_id(m, mjOBJ_ACTUATOR, kActuatorNames[i], mjcf_path);
    arm.braid[i] = braid_of(arm.pam[i]);
    store_pam_in_model(m, arm.actuator[i], arm.pam[i].spring, calibration.line_length_m[i], i,
                       path);
  }

  // the shoulder
  const int shoulder = require_id(m, mjOBJ_JOINT, "shoulder", mjcf_path);
  if (m->jnt_type[shoulder] != mjJNT_HINGE) {
    throw InputError(mjcf_path + ": joint 'shoulder' must be a hinge");
  }
  arm.shoulder_qpos = m->jnt_qposadr[shoulder];
  arm.shoulder_dof = m->jnt_dofadr[shoulder];

  // the falling mass
  arm.ball_body = require_id(m, mjOBJ_BODY, "ball", mjcf_path);
  const int ball_joint = m->body_jntadr[arm.ball_body];
  if (ball_joint < 0 || m->jnt_type[ball_joint] != mjJNT_FREE) {
    throw InputError(mjcf_path + ": body 'ball' must have a free joint");
  }
  arm.ball_qpos = m->jnt_qposadr[ball_joint];
  arm.ball_dof = m->jnt_dofadr[ball_joint];
  arm.ball_geom = require_id(m, mjOBJ_GEOM, "ball", mjcf_path);
  if (m->geom_type[arm.ball_geom] != mjGEOM_SPHERE) {
    throw InputError(mjcf_path + ": geom 'ball' must be a sphere");
  }
  arm.ball_radius_m = m->geom_size[3 * arm.ball_geom];
  const double scale = ball_mass_kg / m->body_mass[arm.ball_body];
  m->body_mass[arm.ball_body] = ball_mass_kg;
  for (int k = 0; k < 3; ++k) m->body_inertia[3 * arm.ball_body + k] *= scale;

  // the basket
  arm.basket_body = require_id(m, mjOBJ_BODY, "basket", mjcf_path);
  arm.basket_floor_site = require_id(m, mjOBJ_SITE, "basket_floor", mjcf_path);
  return arm;
}

void hold_ball(const ArmModel& arm, mjData* d, const double hold_pos[3]) {
  double* q = d->qpos + arm.ball_qpos;
  q[0] = hold_pos[0];
  q[1] = hold_pos[1];
  q[2] = hold_pos[2];
  q[3] = 1.0;
  q[4] = q[5] = q[6] = 0.0;
  for (int k = 0; k < 6; ++k) d->qvel[arm.ball_dof + k] = 0.0;
}

bool ball_touches_basket(const ArmModel& arm, const mjModel* m, const mjData* d) {
  for (int c = 0; c < d->ncon; ++c) {
    const mjContact& con = d->contact[c];
    const int other = con.geom1 == arm.ball_geom ? con.geom2
                      : con.geom2 == arm.ball_geom ? con.geom1 : -1;
    if (other >= 0 && m->geom_bodyid[other] == arm.basket_body) return true;
  }
  return false;
}

}  // namespace pamsim
