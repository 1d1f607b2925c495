// arm_model.h: the arm of the falling-mass experiment, ready for trials. Loads the MJCF,
// checks it has what a trial needs (shoulder hinge, two PAM actuators, basket, ball),
// writes the PAM parameters and calibrated line lengths into the actuators' user slots,
// sets the falling mass, and records the ids a trial uses. Built once per run and then
// only read, so all worker threads share one mjModel (each trial has its own mjData).
#pragma once

#include <array>
#include <string>
#include <vector>

#include "pam_actuator/chou_hannaford.h"
#include "pam_actuator/pam_params.h"
#include "reflex/controller.h"
#include "sim/core/mujoco_util.h"

namespace pamsim {

// Result of `pamsim calibrate`: the fishing-line lengths that make the arm rest at the
// start angle with both PAMs at the calibration pressures (models/arm_2pam_calibration.toml).
struct ArmCalibration {
  double start_angle_rad = 0.0;
  std::array<double, kMuscleCount> line_length_m{};
  std::array<double, kMuscleCount> pressure_pa{};      // the pressures it was solved for
  double antagonist_deformation_m = 0.0;               // the chosen pre-deformation
  double gravity_torque_nm = 0.0;                      // what the PAMs hold at the start
};

// Reads a calibration file. Throws InputError naming the file and key.
ArmCalibration load_calibration(const std::string& path);
std::string calibration_to_toml(const ArmCalibration& c, const std::string& provenance);

struct ArmModel {
  std::string model_path;
  MjModelPtr model;
  std::array<PamParams, kMuscleCount> pam;
  std::array<BraidGeometry, kMuscleCount> braid;   // chamber volume law per PAM
  ArmCalibration calibration;

  // ids and addresses
  std::array<int, kMuscleCount> actuator{};
  int shoulder_qpos = -1;
  int shoulder_dof = -1;
  int ball_body = -1;
  int ball_qpos = -1;
  int ball_dof = -1;
  int ball_geom = -1;
  double ball_radius_m = 0.0;
  int basket_body = -1;
  int basket_floor_site = -1;
};

// The chamber volume law of a PAM from its [geometry] table (Table I + assumed braid angle).
// Throws InputError naming the params file if the table is missing.
BraidGeometry braid_of(const PamParams& pam);

// Loads and prepares the arm. `ball_mass_kg` sets the falling mass (inertia scaled with it).
ArmModel load_arm_model(const std::string& mjcf_path,
                        const std::array<PamParams, kMuscleCount>& pam,
                        const ArmCalibration& calibration, double ball_mass_kg);

// The ball waits, held kinematically, at `hold_pos` (world, m): upright and at rest.
void hold_ball(const ArmModel& arm, mjData* d, const double hold_pos[3]);

// True while the ball touches any geom of the basket (the impact event).
bool ball_touches_basket(const ArmModel& arm, const mjModel* m, const mjData* d);

// Angle of the shoulder [rad], 0 = horizontal, positive up.
inline double shoulder_angle(const ArmModel& arm, const mjData* d) {
  return d->qpos[arm.shoulder_qpos];
}

}  // namespace pamsim
