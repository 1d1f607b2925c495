// trial_log.h: a trial's log, one row per control tick, and its columns, built from what the
// trial contains (units in the names; per-muscle columns carry the muscle's label):
//   time_s
//   angle_deg, omega_deg_s          the scenario's joint (model.joint) if a hinge, or
//   position_mm, velocity_mm_s      if a slide
//   <body>_z_m                      the height of each held body (e.g. ball_z_m)
//   p_cmd_<m>_MPa, p_<m>_MPa        valve command and chamber pressure, muscle by muscle
// then, for every muscle in turn, one column per quantity:
//   force_<m>_N, length_<m>_mm      true line tension and PAM length (the encoder)
//   length_est_<m>_mm               model-based estimate, Eq. (9)-(10)
//   velocity_est_<m>_mm_s           the velocity the controller acted on, Eq. (11) or fiber
//   <prefix><m><suffix>             each channel the controller's kind declares (a reflex
//                                   kind: reflex_<m>, 1 while its stretch (Ia) window is
//                                   open; with Ib, tension_reflex_<m>; ControllerChannel)
//   pressure_sensor_<m>_V, gauge_<m>_V, fiber_rate_<m>_mm_s   raw sensor readings
//   p_meas_<m>_MPa, force_meas_<m>_N                          what the controller believes
// The falling-mass scenarios' columns (the Ia reflex's) are exactly those of pamsim 0.1 (a
// pinned test); the Ib kinds add their tension_reflex_<m> columns.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "reflex/controller.h"

namespace pamsim {

// The log, row-major; columns named by its layout.
struct Trajectory {
  std::vector<std::string> columns;
  std::vector<double> values;  // row-major
  std::size_t rows() const { return columns.empty() ? 0 : values.size() / columns.size(); }
  double at(std::size_t row, std::size_t col) const { return values[row * columns.size() + col]; }
  std::size_t column(const std::string& name) const;  // throws std::out_of_range
  bool has_column(const std::string& name) const;
};

inline constexpr std::size_t kNoColumn = static_cast<std::size_t>(-1);

struct MuscleColumns {
  std::size_t p_cmd, p, force, length, length_est, velocity_est;
  std::vector<std::size_t> channels;  // per declared controller channel
  std::size_t pressure_sensor, gauge, fiber_rate, p_meas, force_meas;
};

struct LogLayout {
  std::vector<std::string> columns;
  std::size_t time = 0, joint_position = 1, joint_velocity = 2;
  std::vector<std::size_t> body_z;    // per hold
  std::vector<MuscleColumns> muscle;  // per muscle, model order
};

// `hinge`: the joint's kind; `bodies`: the held bodies' names; `labels`: the muscles';
// `channels`: what the controller's kind logs per muscle.
LogLayout make_log_layout(bool hinge, const std::vector<std::string>& bodies,
                          const std::vector<std::string>& labels,
                          const std::vector<ControllerChannel>& channels = {});

}  // namespace pamsim
