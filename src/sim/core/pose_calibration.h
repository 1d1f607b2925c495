// pose_calibration.h: the fishing-line lengths of every muscle of a model for its start pose
// (the scenario's joints.<j>.start_deg|mm), from MuJoCo's own tendon lengths and moment arms
// at that pose (body frames and tendon paths as the simulation has them). `pamsim calibrate
// --pose`; the leg's scenarios carry its lines.
//
// Each line is l_tendon - (l_free(p) + d) (Eq. (1)-(2)): the muscle d past its plant's free
// length at its start pressure p. Two rules for d:
//   - uniform: every muscle the same d (a taut line with a little pretension, the arm's rule
//     for its antagonist);
//   - balanced: the d nearest the uniform one (least squares) whose pulls F_i(d_i) hold the
//     pose at rest, sum_i r_ji F_i = qfrc_passive_j - qfrc_bias_j on every joint a muscle
//     crosses (r from MuJoCo's actuator_moment), solved by Gauss-Newton on the plant's static
//     law with the minimum-norm step; every line must stay taut (d > 0).
#pragma once

#include <string>
#include <vector>

#include "sim/core/scenario.h"
#include "sim/core/trial_model.h"

namespace pamsim {

struct PoseCalibrationRequest {
  double deformation_m = 2.0e-3;  // d of the uniform rule, the target of the balanced one
  double pressure_pa = -1;        // every muscle's p; < 0: each muscle's start command
  bool balance = false;
};

struct PoseLine {
  std::string muscle;  // the scenario key, "muscles.VAS"
  double tendon_m = 0, free_length_m = 0, deformation_m = 0;
  double force_n = 0;      // its plant's pull at the start
  double pressure_pa = 0;  // its start command
  double line_m() const { return tendon_m - free_length_m - deformation_m; }
};

struct PoseCalibration {
  std::vector<PoseLine> lines;      // in the model's muscle order
  std::vector<std::string> joints;  // the joints the muscles cross
  std::vector<double> residual_nm;  // per joint: sum r F - (passive - bias), at the end
  int iterations = 0;               // Gauss-Newton's (0 for the uniform rule)
};

// Throws InputError naming the problem: a deformation <= 0, a pressure not finite, a line <= 0 (the
// tendon is shorter than its muscle), a pose the muscles cannot hold with every line taut.
PoseCalibration solve_pose_calibration(const TrialModel& model, const Scenario& scenario,
                                       const PoseCalibrationRequest& request);

// The lines as scenario keys ([muscles.<m>] line_mm, to 4 decimals), each with its tendon,
// deformation and pull as a comment, after `header` (comment lines).
std::string pose_calibration_toml(const PoseCalibration& c, const std::string& header);

}  // namespace pamsim
