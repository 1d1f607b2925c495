// trial_channels.cc: the table of the trial's output channels (trial_channels.h).
#include "sim/core/trial_channels.h"

#include <algorithm>
#include <stdexcept>
#include <utility>

#include "base/units.h"

namespace pamsim {
namespace trial_channels {

constexpr double kMpa = units::kPaPerMPa;  // a column in MPa: SI / 1e6
constexpr double kMm = units::kMPerMm;     // in mm: SI / 1e-3

using Field = double MuscleReading::*;
// A reading's field, per muscle.
std::function<double(const TrialObservation&, std::size_t)> reading(Field field) {
  return [field](const TrialObservation& o, std::size_t i) { return o.readings[i].*field; };
}
// A per-muscle vector of the observation.
std::function<double(const TrialObservation&, std::size_t)> per_muscle(
    std::vector<double> TrialObservation::*field) {
  return [field](const TrialObservation& o, std::size_t i) { return (o.*field)[i]; };
}

ChannelRow joint_row(std::string name, std::string unit, double to_si, double divisor,
                     std::string meaning, double TrialObservation::*field, ChannelJoint joint) {
  ChannelRow r{std::move(name),
               std::move(unit),
               to_si,
               divisor,
               std::move(meaning),
               "the simulation (model.joint)",
               [field](const TrialObservation& o, std::size_t) { return o.*field; }};
  r.joint = joint;
  return r;
}

// A row of what a controller on the robot sees: an instrument's reading or an estimate.
ChannelRow measured(ChannelRow row) {
  row.measured = true;
  return row;
}

std::vector<ChannelRow> built_in_rows() {
  using O = TrialObservation;
  const double deg = units::kPi, per_deg = 180.0;  // SI = deg * pi / 180
  std::vector<ChannelRow> t;
  t.push_back({"time_s", "s", 1.0, 1.0, "the trial's time at the control tick", "the clock",
               [](const O& o, std::size_t) { return o.time_s; }});
  t.push_back(joint_row("angle_deg", "deg", deg, per_deg, "the joint's angle",
                        &O::joint_position_rad_or_m, ChannelJoint::kHinge));
  t.push_back(joint_row("omega_deg_s", "deg/s", deg, per_deg, "the joint's angular velocity",
                        &O::joint_velocity_rad_or_m_per_s, ChannelJoint::kHinge));
  t.push_back(joint_row("position_mm", "mm", kMm, 1.0, "the slide joint's position",
                        &O::joint_position_rad_or_m, ChannelJoint::kSlide));
  t.push_back(joint_row("velocity_mm_s", "mm/s", kMm, 1.0, "the slide joint's velocity",
                        &O::joint_velocity_rad_or_m_per_s, ChannelJoint::kSlide));
  t.push_back({"{body}_z_m", "m", 1.0, 1.0, "a held body's height (the scenario's holds)",
               "the simulation", [](const O& o, std::size_t i) { return o.body_z_m[i]; }});
  t.push_back({"p_cmd_{m}_MPa", "MPa", kMpa, 1.0, "the valve's command in force (gauge)",
               "the controller, or the caller's commands", per_muscle(&O::command_pa)});
  t.push_back({"p_{m}_MPa", "MPa", kMpa, 1.0, "the chamber's gauge pressure",
               "the pneumatics (truth)", per_muscle(&O::pressure_pa)});
  t[t.size() - 2].muscle_by_muscle = t.back().muscle_by_muscle = true;
  t.push_back({"force_{m}_N", "N", 1.0, 1.0, "the line's tension (0 when slack)",
               "the plant (truth)", per_muscle(&O::force_n)});
  t.push_back({"length_{m}_mm", "mm", kMm, 1.0, "the PAM's length (a linear encoder)",
               "the plant (truth)", per_muscle(&O::length_m)});
  t.push_back(
      measured({"length_est_{m}_mm", "mm", kMm, 1.0,
                "the length estimated from pressure and force, Eq. (1) with Eq. (3)/(10) inverted",
                "the estimator", per_muscle(&O::length_est_m)}));
  t.push_back(measured({"velocity_est_{m}_mm_s", "mm/s", kMm, 1.0,
                        "the stretch velocity the controller acted on, Eq. (11) or the fiber's",
                        "the estimator", per_muscle(&O::velocity_est_m_s)}));
  t.push_back({"{controller}", "", 1.0, 1.0,
               "each channel the scenario's controller kind declares, per muscle", "the controller",
               nullptr});
  t.back().controller_channels = true;
  t.push_back(measured({"pressure_sensor_{m}_V", "V", 1.0, 1.0, "the pressure sensor's output",
                        "the pressure sensor", reading(&MuscleReading::pressure_sensor_v)}));
  t.push_back(measured({"gauge_{m}_V", "V", 1.0, 1.0, "the strain gauge's bridge output, Eq. (8)",
                        "the strain gauge", reading(&MuscleReading::gauge_v)}));
  t.push_back(
      measured({"fiber_rate_{m}_mm_s", "mm/s", kMm, 1.0, "the fiber sensor's rate of length change",
                "the fiber sensor", reading(&MuscleReading::fiber_rate_m_s)}));
  t.push_back(
      measured({"p_meas_{m}_MPa", "MPa", kMpa, 1.0, "the pressure as the controller believes it",
                "the pressure sensor's calibration", reading(&MuscleReading::pressure_meas_pa)}));
  t.push_back(measured({"force_meas_{m}_N", "N", 1.0, 1.0,
                        "the tension from the gauge, f = dV / q, Eq. (9)",
                        "the strain gauge's calibration", reading(&MuscleReading::force_meas_n)}));
  return t;
}

std::vector<ChannelRow>& table() {
  static std::vector<ChannelRow> rows = built_in_rows();
  return rows;
}

}  // namespace trial_channels

std::string ChannelRow::column(const std::string& part) const {
  std::string out = name;
  for (const char* slot : {"{m}", "{body}"}) {
    const std::size_t at = out.find(slot);
    if (at != std::string::npos) out.replace(at, std::string(slot).size(), part);
  }
  return out;
}

std::string ChannelRow::quantity() const {
  for (const char* slot : {"{m}", "{body}"}) {
    const std::size_t at = name.find(slot);
    if (at != std::string::npos) {
      return quantity_name(name.substr(0, at), name.substr(at + std::string(slot).size()));
    }
  }
  return name;
}

std::string quantity_name(const std::string& prefix, const std::string& suffix) {
  if (suffix.empty())
    return prefix.empty() || prefix.back() != '_' ? prefix : prefix.substr(0, prefix.size() - 1);
  if (!prefix.empty() && prefix.back() == '_' && suffix.front() == '_') {
    return prefix + suffix.substr(1);
  }
  return prefix + suffix;
}

const std::vector<ChannelRow>& trial_channel_table() { return trial_channels::table(); }

void add_trial_channel(ChannelRow row) {
  std::vector<ChannelRow>& t = trial_channels::table();
  if (!row.si || !(row.to_si > 0.0) || !(row.divisor > 0.0)) {
    throw std::invalid_argument("add_trial_channel: " + row.name +
                                " needs a value and positive unit factors");
  }
  if (std::any_of(t.begin(), t.end(), [&](const ChannelRow& r) { return r.name == row.name; })) {
    throw std::invalid_argument("add_trial_channel: " + row.name + " is in the table already");
  }
  t.push_back(std::move(row));
}

}  // namespace pamsim
