// trial_channels.h: the trial's output channels as rows, one row a quantity: its column name
// (the unit in it), unit, factor to SI, meaning, what produces it, and how its SI value is
// read from the trial's state. The log writer (trial_log.h), the Python module's observation,
// the Gymnasium environments' lists and the reference of trajectory.csv's columns (`pamsim
// keys --channels`) all read this one table; adding a channel is one row.
#pragma once

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include "sensing/muscle_reading.h"

namespace pamsim {

// The trial's state as a channel reads it, in SI; vectors per muscle (model order) or per held
// body. At a control tick (the log's row) the plant's quantities are the tick's; in
// SteppedTrial::observe they are the state after the last physics step, and the controller's
// (readings, estimates, channels) those of the last control tick.
struct TrialObservation {
  double time_s = 0.0;
  long steps = 0;                              // physics steps taken
  double joint_position_rad_or_m = 0.0;        // a hinge's [rad], a slide's [m]
  double joint_velocity_rad_or_m_per_s = 0.0;  // [rad/s] or [m/s]
  std::vector<double> body_z_m;                // each held body's height
  std::vector<double> pressure_pa;             // chamber pressures
  std::vector<double> command_pa;              // valve commands in force
  std::vector<double> force_n;                 // tension in each PAM's line
  std::vector<double> length_m;                // each PAM's length
  std::vector<double> length_est_m;            // the estimator's length
  // what the controller logs per muscle: its channels' names (the log's <prefix><m><suffix>
  // without the muscle, "reflex_") and values, [channel][muscle]
  std::vector<std::string> channel_names;
  std::vector<std::vector<double>> channels;
  // what the controller saw: the instruments' readings and estimates, and the velocity each
  // muscle's control acted on (the log's velocity_est_<m>_mm_s)
  std::vector<MuscleReading> readings;
  std::vector<double> velocity_est_m_s;
};

// Which joints a row applies to.
enum class ChannelJoint { kAny, kHinge, kSlide };

// One channel. Its name holds "{m}" for a per-muscle row (one column per muscle, the muscle's
// label in its place) or "{body}" for a per-held-body row; else it is one column. A column's
// value is the SI value times divisor / to_si, as a key row's SI value is the file's value times
// to_si / divisor (base/key_table.h): degrees are to_si = pi, divisor = 180.
struct ChannelRow {
  std::string name;  // "force_{m}_N"
  std::string unit;  // "N"; "" for a pure number
  double to_si = 1.0;
  double divisor = 1.0;
  std::string meaning;
  std::string source;  // what produces it: "the plant", "the pressure sensor", "the estimator"
  // the SI value of instance `i` (the muscle, or the held body; 0 for a single column)
  std::function<double(const TrialObservation&, std::size_t i)> si;
  ChannelJoint joint = ChannelJoint::kAny;
  bool measured = false;  // what a controller on the robot sees (the Gymnasium observation's)
  // The columns of this row and of the rows after it that also have it set are written muscle
  // by muscle (p_cmd_<a>, p_<a>, p_cmd_<b>, p_<b>), not each row for all muscles in turn.
  bool muscle_by_muscle = false;
  // Where the controller's declared channels go (ControllerChannel): no value of its own.
  bool controller_channels = false;

  bool per_muscle() const { return name.find("{m}") != std::string::npos; }
  bool per_body() const { return name.find("{body}") != std::string::npos; }
  double value(const TrialObservation& o, std::size_t i) const {
    return si(o, i) * divisor / to_si;
  }
  std::string column(const std::string& part) const;  // "{m}" or "{body}" replaced by `part`
  std::string quantity() const;                       // the name without its part: "force_N"
};

// The table, in the log's column order. add_trial_channel appends a row: call it before any
// trial or layout is made (at start-up, as a plug-in registers a controller kind). Throws
// std::invalid_argument for a name already in the table, or a row without a value or a unit
// factor.
const std::vector<ChannelRow>& trial_channel_table();
void add_trial_channel(ChannelRow row);

// A channel's name without its muscle, as the observation and the Gymnasium lists name it:
// ("p_meas_", "_MPa") -> "p_meas_MPa", ("reflex_", "") -> "reflex".
std::string quantity_name(const std::string& prefix, const std::string& suffix);

}  // namespace pamsim
