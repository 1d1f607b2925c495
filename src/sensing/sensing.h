// sensing.h: every muscle's sensors and its model-based length estimate, sampled once per
// control tick: what a controller sees of the plant (reflex/controller.h), and all it sees.
// The order of a tick, which fixes the noise stream by the seed alone: SensorSuite.
#pragma once

#include <cstdint>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include "pam_actuator/pam_params.h"
#include "pam_actuator/spring_model.h"
#include "embedded/pamctl.h"
#include "sensing/length_estimator.h"
#include "sensing/muscle_reading.h"
#include "sensing/lowpass_filter.h"
#include "sensing/sensors.h"

namespace pamsim {

// One muscle as the sensing sees it: the law its estimator inverts and its gauge's Eq. (8)
// constants. `key` names the muscle in messages (e.g. "muscles.agonist").
struct MuscleSensorSpec {
  std::string key;
  SpringModel estimator;
  StrainGaugeParams gauge;
  // this muscle's gauge contact (muscles.<m>.gauge.contact.*), in place of the shared
  // sensors.gauge.contact; none: the shared one
  std::optional<GaugeContactParams> contact{};
};

struct SensingConfig {
  SensorConfig sensors;  // sensors.*
  // reflex.lowpass_hz (the controller's, ControllerConfig::velocity_lowpass_hz, handed over
  // by the scenario; its default is this one):
  // first-order low-pass on Eq. (11)'s v and the fiber rate, 0 (off) or (0, control_hz / 2].
  // Default off: a prototype of the falling-mass arm measured that 10 Hz delays the trigger
  // by ~30 ms and halves the gain and 5 Hz never triggers. On the physical plant
  // (docs/findings.md, sensor noise) 10 Hz costs the model reflex 0.9 deg of drop at the
  // default noise and moves the onset of noise mistrips from 2x to 6x the default noise
  // (sensors.noise_scale). A low-pass on the pressure (sensors.pressure_lowpass_hz) is no
  // substitute (see its caveat in sensors.h).
  double velocity_lowpass_hz = 0.0;
  double control_hz = 100.0;    // sim.control_hz
  double physics_dt_s = 0.001;  // sim.timestep_s: a ringing gauge board's step
};

// Throw InputError "<key> must be ..., got <value>" naming the scenario key:
// sim.control_hz, sensors.*, reflex.lowpass_hz; and for a muscle
// <key>.strain_gauge.q_V_per_N (> 0), .V_base_V and .spring.* (finite, h > 0), by the
// parameter file's own rows (validate_pam_params).
void validate(const SensingConfig& config);
void validate(const MuscleSensorSpec& muscle);

// Per tick, muscle by muscle in the model's actuator order (so the noise stream, and
// therefore a trial, is fixed by the seed alone):
//   1. sample the PSE540 pressure sensor, the strain gauge and the fiber sensor (sensors.h),
//      in that order, each drawing one normal from the suite's std::mt19937_64 (sensors built
//      as hardware draw their own errors from generators of their own, sensor_noise.h);
//   2. estimate length and velocity from pressure and force, Eq. (9)-(11), with the muscle's
//      estimator law, and low-pass the fiber rate at reflex.lowpass_hz (the velocity a fiber
//      reflex uses): the embedded controller's estimator (pamctl_estimate_muscle,
//      src/embedded/pamctl.h), fed the readings a board would read.
// All sensors are sampled whatever the controller uses, so a model-based and a fiber-based
// trial with the same seed see the same noise.
class SensorSuite {
 public:
  // Validates (throws InputError) and seeds the generator with `seed`.
  SensorSuite(const SensingConfig& config, const std::vector<MuscleSensorSpec>& muscles,
              std::uint64_t seed);

  int muscle_count() const { return static_cast<int>(channels_.size()); }
  // One tick: truth[j] -> (*readings)[j]; both sized muscle_count().
  void sample(const std::vector<MuscleTruth>& truth, std::vector<MuscleReading>* readings);
  // Whether an instrument follows the line's pull between ticks (a ringing gauge board,
  // gauge_hardware.h); if so, observe() at every physics step with each muscle's pull [N].
  bool observes_forces() const { return observes_forces_; }
  void observe(const std::vector<double>& force_n);
  // The estimator as the embedded controller holds it: the control period, the low-passes'
  // factors and each muscle's law, gauge calibration (the calibrated one where the gauge is
  // hardware), pressure line and sensor ranges. The controller's part is left for the
  // controller (ControllerConfig::embedded).
  pamctl_config embedded_config() const;

 private:
  struct Channel {
    PressureSensor pressure;
    StrainGauge gauge;
    FiberSensor fiber;
    pamctl_muscle_config estimator;
    pamctl_muscle_state state;
  };
  double dt_s_ = 0.0;
  double pressure_alpha_ = 1.0;
  double velocity_alpha_ = 1.0;
  std::mt19937_64 rng_;
  std::vector<Channel> channels_;
  bool observes_forces_ = false;
};

}  // namespace pamsim
