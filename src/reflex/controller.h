// controller.h: the interface between the co-simulation loop (src/sim) and a controller.
// At every control tick (sim.control_hz, 100 Hz as in the paper) the loop hands the
// controller the plant's true state; the controller samples its own sensors (with noise),
// estimates, decides, and returns valve commands plus what it measured, for the log.
#pragma once

#include <array>
#include <limits>

namespace pamsim {

enum Muscle : int { kAgonist = 0, kAntagonist = 1 };
inline constexpr int kMuscleCount = 2;

// Ground truth of one muscle at a control tick (what ideal sensors would read).
struct MuscleTruth {
  double pressure_pa = 0.0;   // chamber gauge pressure
  double force_n = 0.0;       // line tension, >= 0 (0 when slack)
  double length_m = 0.0;      // PAM length (the linear encoder's reading)
};

struct PlantSample {
  double time_s = 0.0;
  std::array<MuscleTruth, kMuscleCount> muscle{};
};

// What the controller measured and estimated for one muscle; NaN where not applicable.
struct MuscleTelemetry {
  static constexpr double kNone = std::numeric_limits<double>::quiet_NaN();
  double pressure_sensor_v = kNone;   // raw pressure sensor output [V]
  double gauge_v = kNone;             // raw strain gauge output [V], Eq. (8)
  double fiber_rate = kNone;          // raw fiber sensor: rate of length change [m/s]
  double pressure_meas_pa = kNone;    // pressure as the controller believes it
  double force_meas_n = kNone;        // f = dV / q, Eq. (9)
  double length_est_m = kNone;        // Eq. (1) with d from inverting Eq. (3)/(10)
  double velocity_est_m_s = kNone;    // Eq. (11), filtered if configured
  bool reflex_active = false;
  double fiber_length_m = kNone;      // fiber rate integrated from the encoder at t = 0
};

struct ControlOutput {
  std::array<double, kMuscleCount> p_cmd_pa{};   // valve commands, gauge [Pa]
  std::array<MuscleTelemetry, kMuscleCount> telemetry{};
};

class Controller {
 public:
  virtual ~Controller() = default;
  // Called once per control tick, in time order, starting at t = 0.
  virtual ControlOutput update(const PlantSample& sample) = 0;
};

// The top controller of the paper (Eq. (12)-(13)'s p_tp): holds goal pressures.
class TopController final : public Controller {
 public:
  TopController(double p_goal_agonist_pa, double p_goal_antagonist_pa)
      : goal_{p_goal_agonist_pa, p_goal_antagonist_pa} {}
  ControlOutput update(const PlantSample&) override {
    ControlOutput out;
    out.p_cmd_pa = goal_;
    return out;
  }
  const std::array<double, kMuscleCount>& goal_pa() const { return goal_; }

 private:
  std::array<double, kMuscleCount> goal_;
};

}  // namespace pamsim
