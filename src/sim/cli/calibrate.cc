// calibrate.cc: `pamsim calibrate SCENARIO.toml [--angle-deg A]
// [--antagonist-deformation-mm D] [-o FILE]`: solves the line lengths of the scenario's
// first reflex pair (its agonist and antagonist) for its model, PAMs and pressures at t = 0
// (see core/calibration.h) and writes them (by default to the scenario's model.calibration).
// With --pose [--deformation-mm D] [--balance]: every muscle's line for the scenario's start
// pose (core/pose_calibration.h), as [muscles.<m>] line_mm keys (by default to standard
// output).
#include <CLI/CLI.hpp>

#include <cmath>
#include <iostream>

#include "base/atomic_file.h"
#include "base/input_error.h"
#include "base/units.h"
#include "sim/core/calibration.h"
#include "sim/core/pose_calibration.h"
#include "sim/cli/cli_options.h"
#include "sim/cli/commands.h"
#include "base/config_reader.h"
#include "sim/scenario/calibration_file.h"
#include "sim/io/outputs.h"
#include "sim/scenario/scenario_file.h"

namespace pamsim {
namespace {

struct CalibrateOptions {
  std::string scenario;
  std::vector<std::string> overrides;
  double angle_deg = -36.0;
  double antagonist_deformation_mm = 1.0;
  std::string out;
  bool force = false;
  bool pose = false;
  double deformation_mm = 2.0;
  double pressure_mpa = -1;  // --pressure-MPa; < 0: each muscle's start command
  bool balance = false;
  bool pressure_mpa_given = false;
};

// --pose: every muscle's line for the start pose, as scenario keys.
void calibrate_pose(const CalibrateOptions& opt) {
  const Scenario sc = load_scenario_for_calibration(opt.scenario, opt.overrides);
  const TrialModel model = load_trial_model(sc);
  PoseCalibrationRequest req;
  req.deformation_m = units::mm_to_m(opt.deformation_mm);
  req.balance = opt.balance;
  if (opt.pressure_mpa_given) {
    if (!(opt.pressure_mpa >= 0)) {
      throw InputError("--pressure-MPa must be >= 0, got " + format_value(opt.pressure_mpa));
    }
    req.pressure_pa = units::mpa_to_pa(opt.pressure_mpa);
  }
  const PoseCalibration c = solve_pose_calibration(model, sc, req);
  const std::string out = opt.out.empty() ? "-" : opt.out;
  std::string header = "# pamsim calibrate --pose" + std::string(opt.balance ? " --balance" : "") +
                       " " + opt.scenario + ": the lines for its start pose; the residual " +
                       "torques [N m] on";
  for (std::size_t j = 0; j < c.joints.size(); ++j) {
    header += " " + c.joints[j] + " " + format_value(c.residual_nm[j]);
  }
  write_file_atomically(out, pose_calibration_toml(c, header + "\n"));
  std::ostream& said = is_stream_output(out) ? std::cerr : std::cout;
  if (opt.balance) said << "balanced in " << c.iterations << " Gauss-Newton iterations\n";
  said << "written to " << (out == "-" ? "standard output" : out) << "\n";
}

void calibrate(const CalibrateOptions& opt) {
  // the scenario's own model.calibration is what calibrate updates; another file is an output
  if (!opt.out.empty()) refuse_existing_file(opt.out, opt.force);
  if (opt.balance && !opt.pose) throw InputError("--balance goes with --pose");
  if (opt.pose) return calibrate_pose(opt);
  if (!std::isfinite(opt.angle_deg)) throw InputError("--angle-deg must be finite");
  if (!(opt.antagonist_deformation_mm > 0)) {
    throw InputError("--antagonist-deformation-mm must be > 0, got " +
                     format_value(opt.antagonist_deformation_mm));
  }
  const Scenario sc = load_scenario_for_calibration(opt.scenario, opt.overrides);
  const TrialModel model = load_trial_model(sc);
  if (model.pairs.empty()) throw InputError(sc.path + ": reflex.pairs: calibrate needs a pair");
  const ReflexPair pair = model.pairs.front();

  CalibrationRequest req;
  req.start_angle_rad = units::deg_to_rad(opt.angle_deg);
  req.pressure_agonist_pa = sc.muscles[model.muscles[pair.agonist].spec].command.at(0.0);
  req.pressure_antagonist_pa = sc.muscles[model.muscles[pair.antagonist].spec].command.at(0.0);
  req.antagonist_deformation_m = units::mm_to_m(opt.antagonist_deformation_mm);
  const ArmCalibration c = solve_calibration(model, sc, pair, req);

  const std::string out = opt.out.empty() ? sc.calibration_file : opt.out;
  if (out.empty()) throw InputError(sc.path + ": model.calibration is not set; give -o FILE");
  write_file_atomically(out, calibration_to_toml(c, "pamsim calibrate " + opt.scenario));
  // with -o - (or a pipe) the calibration itself is on standard output: the rest to stderr
  std::ostream& said = is_stream_output(out) ? std::cerr : std::cout;
  said << "gravity torque at " << opt.angle_deg << " deg: " << c.gravity_torque_nm << " N m\n";
  for (const CalibratedLine& line : c.lines) {
    said << line.actuator << " line: " << units::m_to_mm(line.line_length_m) << " mm\n";
  }
  said << "written to " << (out == "-" ? "standard output" : out) << "\n";
}

}  // namespace

void add_calibrate_command(CLI::App& app) {
  const auto [cmd, opt] = add_command<CalibrateOptions>(
      app, "calibrate", "Solve the arm's line lengths for its start angle at the goal pressures",
      calibrate);
  cmd->add_option("scenario", opt->scenario, "Scenario file (TOML)")->required();
  add_overrides_option(cmd, &opt->overrides, "Override a scenario key");
  cmd->add_option("--angle-deg", opt->angle_deg, "Start angle at rest [deg] (paper: -36)");
  cmd->add_option("--antagonist-deformation-mm", opt->antagonist_deformation_mm,
                  "Antagonist pre-deformation at the start [mm]");
  // --out: its name before 0.3 (-o/--output names a file everywhere now)
  cmd->add_option("-o,--output,--out", opt->out,
                  "Output file (default: update the scenario's model.calibration)");
  cmd->add_flag("--force", opt->force, "Replace an existing -o file");
  cmd->add_flag("--pose", opt->pose,
                "Every muscle's line for the scenario's start pose, as [muscles.<m>] line_mm "
                "(default output: standard output)");
  cmd->add_option("--deformation-mm", opt->deformation_mm,
                  "With --pose: each muscle this far past its free length [mm] (default 2)");
  cmd->add_option("--pressure-MPa", opt->pressure_mpa,
                  "With --pose: every muscle at this pressure [MPa] (default: its start command)")
      ->each([given = &opt->pressure_mpa_given](const std::string&) { *given = true; });
  cmd->add_flag("--balance", opt->balance,
                "With --pose: the deformations nearest --deformation-mm that hold the pose");
}

}  // namespace pamsim
