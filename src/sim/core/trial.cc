// trial.cc: see trial.h.
#include "sim/core/trial.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <limits>
#include <memory>
#include <stdexcept>

#include "pam_actuator/pneumatics.h"
#include "pam_actuator/units.h"
#include "sim/core/pam_callback.h"

namespace pamsim {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInfinity = std::numeric_limits<double>::infinity();
constexpr double kRecoveryBandDeg = 2.0;

enum Col : std::size_t {
  kTime, kAngle, kOmega, kBallZ,
  kPCmdAgo, kPAgo, kPCmdAnta, kPAnta,
  kForceAgo, kForceAnta, kLengthAgo, kLengthAnta,
  kLengthEstAgo, kLengthEstAnta, kVelEstAgo, kVelEstAnta,
  kReflexAgo, kReflexAnta,
  kPSensorAgo, kPSensorAnta, kGaugeAgo, kGaugeAnta, kFiberAgo, kFiberAnta,
  kPMeasAgo, kPMeasAnta, kForceMeasAgo, kForceMeasAnta,
  kColumnCount
};

std::unique_ptr<Controller> make_controller(const ArmModel& arm, const Scenario& sc,
                                            std::uint64_t seed) {
  ReflexControllerConfig config = sc.reflex;
  config.seed = seed;
  set_muscles(&config, arm.pam[kAgonist], arm.pam[kAntagonist]);
  return std::make_unique<ReflexController>(config);
}

// Why the step went unstable, or nullptr (no allocation: called at every physics step).
const char* diverged_reason(const mjData* d) {
  if (d->warning[mjWARN_BADQACC].number > 0) return "MuJoCo: bad acceleration (unstable)";
  if (d->warning[mjWARN_BADQVEL].number > 0) return "MuJoCo: bad velocity (unstable)";
  if (d->warning[mjWARN_BADQPOS].number > 0) return "MuJoCo: bad position (unstable)";
  return nullptr;
}

void compute_metrics(const Trajectory& tr, const ReflexController* reflex, TrialSummary* s) {
  const std::size_t n = tr.rows();
  if (n == 0) return;
  s->final_angle_deg = tr.at(n - 1, kAngle);

  // recovery: from impact until the angle stays within the band of its final value
  s->recovery_time_s = kNaN;
  if (std::isfinite(s->impact_time_s)) {
    double last_outside = s->impact_time_s;
    for (std::size_t r = 0; r < n; ++r) {
      const double t = tr.at(r, kTime);
      if (t >= s->impact_time_s &&
          std::fabs(tr.at(r, kAngle) - s->final_angle_deg) > kRecoveryBandDeg) {
        last_outside = t;
      }
    }
    s->recovery_time_s = last_outside - s->impact_time_s;
  }

  // length estimate vs the encoder (the paper's Table V metric), both muscles, all ticks
  double sum_sq = 0.0;
  double max_err = 0.0;
  long count = 0;
  for (std::size_t r = 0; r < n; ++r) {
    for (auto [est, truth] : {std::pair{kLengthEstAgo, kLengthAgo}, {kLengthEstAnta, kLengthAnta}}) {
      const double e = tr.at(r, est) - tr.at(r, truth);
      if (!std::isfinite(e)) continue;
      sum_sq += e * e;
      max_err = std::max(max_err, std::fabs(e));
      ++count;
    }
  }
  s->length_est_rmse_mm = count ? std::sqrt(sum_sq / count) : kNaN;
  s->length_est_max_error_mm = count ? max_err : kNaN;

  // reflex triggers; a mistrip is any trigger before the impact (or without one)
  s->first_trigger_time_s = kNaN;
  s->mistrips = 0;
  if (reflex) {
    s->reflex_triggers_ago = reflex->trigger_count(kAgonist);
    s->reflex_triggers_anta = reflex->trigger_count(kAntagonist);
    s->first_trigger_time_s = reflex->first_trigger_time_s();
    for (Muscle muscle : {kAgonist, kAntagonist}) {
      for (double t : reflex->trigger_times_s(muscle)) {
        if (!(t >= s->impact_time_s)) ++s->mistrips;
      }
    }
  }
}

}  // namespace

const std::vector<std::string>& trajectory_columns() {
  static const std::vector<std::string> columns = {
      "time_s", "angle_deg", "omega_deg_s", "ball_z_m",
      "p_cmd_ago_MPa", "p_ago_MPa", "p_cmd_anta_MPa", "p_anta_MPa",
      "force_ago_N", "force_anta_N", "length_ago_mm", "length_anta_mm",
      "length_est_ago_mm", "length_est_anta_mm", "velocity_est_ago_mm_s", "velocity_est_anta_mm_s",
      "reflex_ago", "reflex_anta",
      "pressure_sensor_ago_V", "pressure_sensor_anta_V", "gauge_ago_V", "gauge_anta_V",
      "fiber_rate_ago_mm_s", "fiber_rate_anta_mm_s",
      "p_meas_ago_MPa", "p_meas_anta_MPa", "force_meas_ago_N", "force_meas_anta_N"};
  return columns;
}

std::size_t Trajectory::column(const std::string& name) const {
  const auto it = std::find(columns.begin(), columns.end(), name);
  if (it == columns.end()) throw std::out_of_range("no trajectory column " + name);
  return static_cast<std::size_t>(it - columns.begin());
}

TrialResult run_trial(const ArmModel& arm, const Scenario& sc, std::uint64_t seed,
                      const TrialOptions& options) {
  const mjModel* m = arm.model.get();
  if (m->opt.timestep != sc.timestep_s) {
    throw std::logic_error("run_trial: the model's timestep differs from sim.timestep_s "
                           "(load the arm with load_arm_for)");
  }
  MjDataPtr data = make_data(m);
  mjData* d = data.get();
  TrialResult result;
  TrialSummary& s = result.summary;
  s.seed = seed;
  s.impact_time_s = kNaN;
  result.trajectory.columns = trajectory_columns();
  static_assert(kColumnCount == 28, "keep Col and trajectory_columns() in step");

  // start at rest at the calibrated angle; the ball waits drop.height_m above the floor
  d->qpos[arm.shoulder_qpos] = arm.calibration.start_angle_rad;
  mj_forward(m, d);
  const double* floor = d->site_xpos + 3 * arm.basket_floor_site;
  const double hold_pos[3] = {floor[0], floor[1], floor[2] + sc.drop_height_m + arm.ball_radius_m};
  hold_ball(arm, d, hold_pos);

  // pneumatics start at the goal pressures, in equilibrium
  std::vector<BraidGeometry> braid(arm.braid.begin(), arm.braid.end());
  const std::vector<double> p0 = {sc.p_goal_agonist_pa, sc.p_goal_antagonist_pa};
  PneumaticSystem pneumatics(sc.pneumatics, sc.valve_model, braid, p0, 0.0);
  for (int i = 0; i < kMuscleCount; ++i) {
    pneumatics.set_command(i, p0[i]);
    d->userdata[pam_userdata_index(m, arm.actuator[i])] = pneumatics.pressure_pa(i);
  }
  std::unique_ptr<Controller> controller = make_controller(arm, sc, seed);
  const auto* reflex = dynamic_cast<const ReflexController*>(controller.get());

  const long n_steps = std::lround(sc.duration_s / sc.timestep_s);
  const long control_every = std::lround(1.0 / (sc.control_hz * sc.timestep_s));
  result.trajectory.values.reserve((n_steps / control_every + 1) * kColumnCount);
  bool released = false;
  s.start_angle_deg = kNaN;
  double min_angle = std::numeric_limits<double>::infinity();

  // the observer is shown the state when it asks; without one a step costs one compare
  TrialObserver* const observer = options.observer;
  double next_observation_s = kInfinity;
  std::array<bool, kMuscleCount> reflex_active{};
  std::chrono::steady_clock::duration observer_wall{};
  auto show_observer = [&] {
    const auto start = std::chrono::steady_clock::now();
    TrialSnapshot snapshot;
    snapshot.model = m;
    snapshot.data = d;
    snapshot.time_s = d->time;
    snapshot.angle_deg = units::rad_to_deg(shoulder_angle(arm, d));
    for (int i = 0; i < kMuscleCount; ++i) {
      snapshot.pressure_pa[i] = pneumatics.pressure_pa(i);
      snapshot.command_pa[i] = pneumatics.command_pa(i);
    }
    snapshot.reflex_active = reflex_active;
    observer->observe(snapshot);
    next_observation_s = observer->next_observation_time_s() - kObservationToleranceS;
    observer_wall += std::chrono::steady_clock::now() - start;
  };

  const auto wall_start = std::chrono::steady_clock::now();
  if (observer) {
    next_observation_s = observer->next_observation_time_s() - kObservationToleranceS;
    if (d->time >= next_observation_s) show_observer();
  }
  long step = 0;
  for (; step < n_steps; ++step) {
    const double t = step * sc.timestep_s;

    // the drop: hold until drop.time_s, then let go
    if (!released) {
      if (sc.drop_enabled && t >= sc.drop_time_s - 1e-12) {
        released = true;
        s.start_angle_deg = units::rad_to_deg(shoulder_angle(arm, d));
      } else {
        hold_ball(arm, d, hold_pos);
      }
    }
    mj_step1(m, d);

    // control tick: sample the plant, new valve commands, one log row
    if (step % control_every == 0) {
      PlantSample sample;
      sample.time_s = t;
      for (int i = 0; i < kMuscleCount; ++i) {
        MuscleTruth& mt = sample.muscle[i];
        mt.pressure_pa = pneumatics.pressure_pa(i);
        mt.force_n = -pam_actuator_force(m, d, arm.actuator[i]);
        mt.length_m = pam_length(m, d, arm.actuator[i]);
      }
      ControlOutput out;
      try {   // an absurd gain can drive the command out of range (e.g. to infinity)
        out = controller->update(sample);
        for (int i = 0; i < kMuscleCount; ++i) pneumatics.set_command(i, out.p_cmd_pa[i]);
      } catch (const std::exception& e) {
        s.status = "diverged";
        s.message = std::string("controller: ") + e.what() + " at t = " + std::to_string(t) + " s";
        break;
      }

      {
        double row[kColumnCount];
        row[kTime] = t;
        row[kAngle] = units::rad_to_deg(shoulder_angle(arm, d));
        row[kOmega] = units::rad_to_deg(d->qvel[arm.shoulder_dof]);
        row[kBallZ] = d->qpos[arm.ball_qpos + 2];
        const std::size_t p_cmd[2] = {kPCmdAgo, kPCmdAnta}, p_col[2] = {kPAgo, kPAnta};
        const std::size_t f_col[2] = {kForceAgo, kForceAnta}, l_col[2] = {kLengthAgo, kLengthAnta};
        const std::size_t le[2] = {kLengthEstAgo, kLengthEstAnta}, ve[2] = {kVelEstAgo, kVelEstAnta};
        const std::size_t rf[2] = {kReflexAgo, kReflexAnta}, ps[2] = {kPSensorAgo, kPSensorAnta};
        const std::size_t gv[2] = {kGaugeAgo, kGaugeAnta}, fb[2] = {kFiberAgo, kFiberAnta};
        const std::size_t pm[2] = {kPMeasAgo, kPMeasAnta}, fm[2] = {kForceMeasAgo, kForceMeasAnta};
        for (int i = 0; i < kMuscleCount; ++i) {
          const MuscleTelemetry& tel = out.telemetry[i];
          row[p_cmd[i]] = units::pa_to_mpa(pneumatics.command_pa(i));
          row[p_col[i]] = units::pa_to_mpa(sample.muscle[i].pressure_pa);
          row[f_col[i]] = sample.muscle[i].force_n;
          row[l_col[i]] = units::m_to_mm(sample.muscle[i].length_m);
          row[le[i]] = units::m_to_mm(tel.length_est_m);
          row[ve[i]] = units::m_to_mm(tel.velocity_est_m_s);
          row[rf[i]] = tel.reflex_active ? 1.0 : 0.0;
          row[ps[i]] = tel.pressure_sensor_v;
          row[gv[i]] = tel.gauge_v;
          row[fb[i]] = units::m_to_mm(tel.fiber_rate);
          row[pm[i]] = units::pa_to_mpa(tel.pressure_meas_pa);
          row[fm[i]] = tel.force_meas_n;
          reflex_active[i] = tel.reflex_active;
        }
        result.trajectory.values.insert(result.trajectory.values.end(), row, row + kColumnCount);
      }
    }

    // physics: forces with the pressures at t, then integrate to t + dt
    mj_step2(m, d);
    const char* unstable = diverged_reason(d);
    if (!unstable && !std::isfinite(d->qpos[arm.shoulder_qpos])) unstable = "non-finite angle";
    std::string reason = unstable ? unstable : "";

    // pneumatics over [t, t + dt] with this step's PAM length and velocity
    if (!unstable) {
      try {
        for (int i = 0; i < kMuscleCount; ++i) {
          pneumatics.set_kinematics(i, pam_length(m, d, arm.actuator[i]),
                                    d->actuator_velocity[arm.actuator[i]]);
        }
        pneumatics.advance(t + sc.timestep_s);
      } catch (const std::exception& e) {
        reason = std::string("pneumatics: ") + e.what();
      }
    }
    if (!reason.empty()) {
      s.status = "diverged";
      s.message = reason + " at t = " + std::to_string(t) + " s";
      ++step;
      break;
    }
    for (int i = 0; i < kMuscleCount; ++i) {
      d->userdata[pam_userdata_index(m, arm.actuator[i])] = pneumatics.pressure_pa(i);
    }

    // events: impact of the ball in the basket, lowest angle after the drop
    if (released) {
      if (!std::isfinite(s.impact_time_s) && ball_touches_basket(arm, m, d)) {
        s.impact_time_s = d->time;
      }
      const double a = shoulder_angle(arm, d);
      if (a < min_angle) {
        min_angle = a;
        s.min_angle_time_s = d->time;
      }
    }

    if (d->time >= next_observation_s) show_observer();
  }
  const auto wall_end = std::chrono::steady_clock::now();

  s.steps = step;
  s.sim_time_s = step * sc.timestep_s;
  s.wall_time_s = std::chrono::duration<double>(wall_end - wall_start - observer_wall).count();
  s.realtime_factor = s.wall_time_s > 0 ? s.sim_time_s / s.wall_time_s : kNaN;
  s.cvode_steps = pneumatics.steps();
  s.cvode_rhs_evals = pneumatics.rhs_evals();
  if (released && std::isfinite(min_angle)) {
    s.min_angle_deg = units::rad_to_deg(min_angle);
    s.peak_drop_deg = s.start_angle_deg - s.min_angle_deg;
  } else {
    s.min_angle_deg = s.peak_drop_deg = s.min_angle_time_s = kNaN;
  }
  compute_metrics(result.trajectory, reflex, &s);
  if (!options.keep_trajectory) result.trajectory.values.clear();
  return result;
}

}  // namespace pamsim
