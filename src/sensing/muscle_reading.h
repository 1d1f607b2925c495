// muscle_reading.h: one muscle at a control tick, as it is (MuscleTruth: what ideal sensors
// would read) and as its sensors and the model-based estimator report it (MuscleReading):
// what the sensing (sensing.h) produces and a controller (reflex/controller.h) is handed.
#pragma once

#include <limits>

namespace pamsim {

// Ground truth of one muscle at a control tick (what ideal sensors would read).
struct MuscleTruth {
  double pressure_pa = 0.0;  // chamber gauge pressure
  double force_n = 0.0;      // line tension, >= 0 (0 when slack)
  double length_m = 0.0;     // PAM length (the linear encoder's reading)
};

// What one muscle's sensors read at a tick and what the model-based estimator makes of them
// (sensing.h); NaN where not applicable.
struct MuscleReading {
  static constexpr double kNone = std::numeric_limits<double>::quiet_NaN();
  double pressure_sensor_v = kNone;   // raw pressure sensor output [V]
  double gauge_v = kNone;             // raw strain gauge output [V], Eq. (8)
  double fiber_rate_m_s = kNone;      // raw fiber sensor: rate of length change [m/s]
  double fiber_length_m = kNone;      // fiber rate integrated from the encoder at t = 0
  double fiber_velocity_m_s = kNone;  // fiber rate, low-passed at reflex.lowpass_hz
  double pressure_meas_pa = kNone;    // pressure as the controller believes it
  double force_meas_n = kNone;        // f = dV / q, Eq. (9)
  double length_est_m = kNone;        // Eq. (1) with d from inverting Eq. (3)/(10)
  double velocity_est_m_s = kNone;    // Eq. (11), low-passed at reflex.lowpass_hz
};

}  // namespace pamsim
