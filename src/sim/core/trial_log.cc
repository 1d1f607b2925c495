// trial_log.cc: see trial_log.h.
#include "sim/core/trial_log.h"

#include <algorithm>
#include <stdexcept>

namespace pamsim {

std::size_t Trajectory::column(const std::string& name) const {
  const auto it = std::find(columns.begin(), columns.end(), name);
  if (it == columns.end()) throw std::out_of_range("no trajectory column " + name);
  return static_cast<std::size_t>(it - columns.begin());
}

bool Trajectory::has_column(const std::string& name) const {
  return std::find(columns.begin(), columns.end(), name) != columns.end();
}

LogLayout make_log_layout(bool hinge, const std::vector<std::string>& bodies,
                          const std::vector<std::string>& labels,
                          const std::vector<ControllerChannel>& channels) {
  LogLayout layout;
  std::vector<std::string>& c = layout.columns;
  auto add = [&c](const std::string& name) {
    c.push_back(name);
    return c.size() - 1;
  };

  // time, the joint, the held bodies
  layout.time = add("time_s");
  layout.joint_position = add(hinge ? "angle_deg" : "position_mm");
  layout.joint_velocity = add(hinge ? "omega_deg_s" : "velocity_mm_s");
  for (const std::string& body : bodies) layout.body_z.push_back(add(body + "_z_m"));

  // pressures muscle by muscle, then every other quantity for all muscles in turn
  layout.muscle.resize(labels.size());
  for (std::size_t j = 0; j < labels.size(); ++j) {
    layout.muscle[j].p_cmd = add("p_cmd_" + labels[j] + "_MPa");
    layout.muscle[j].p = add("p_" + labels[j] + "_MPa");
  }
  auto per_muscle = [&](std::size_t MuscleColumns::*field, const std::string& prefix,
                        const std::string& suffix) {
    for (std::size_t j = 0; j < labels.size(); ++j) {
      layout.muscle[j].*field = add(prefix + labels[j] + suffix);
    }
  };
  per_muscle(&MuscleColumns::force, "force_", "_N");
  per_muscle(&MuscleColumns::length, "length_", "_mm");
  per_muscle(&MuscleColumns::length_est, "length_est_", "_mm");
  per_muscle(&MuscleColumns::velocity_est, "velocity_est_", "_mm_s");
  for (const ControllerChannel& channel : channels) {
    for (std::size_t j = 0; j < labels.size(); ++j) {
      layout.muscle[j].channels.push_back(add(channel.prefix + labels[j] + channel.suffix));
    }
  }
  per_muscle(&MuscleColumns::pressure_sensor, "pressure_sensor_", "_V");
  per_muscle(&MuscleColumns::gauge, "gauge_", "_V");
  per_muscle(&MuscleColumns::fiber_rate, "fiber_rate_", "_mm_s");
  per_muscle(&MuscleColumns::p_meas, "p_meas_", "_MPa");
  per_muscle(&MuscleColumns::force_meas, "force_meas_", "_N");
  return layout;
}

}  // namespace pamsim
