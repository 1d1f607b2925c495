// reflex_controller.h: the paper's controller for the falling-mass experiment (Sec. III-D):
// the top controller's goal pressures plus one stretch reflex per muscle (Eq. (12)-(14)),
// driven either by the model-based length estimate (Eq. (9)-(11)) or by the fiber sensor.
//
// Per control tick, for the agonist then the antagonist, in this fixed order (so the noise
// stream, and therefore a trial, is fixed by the seed alone):
//   1. sample the PSE540 pressure sensor, the strain gauge and the fiber sensor (sensors.h);
//   2. estimate length and velocity from pressure and force (length_estimator.h);
//   3. take v from the estimate (reflex.sensor = "model") or from the fiber rate, low-passed
//      at reflex.lowpass_hz ("fiber");
//   4. run the muscle's stretch reflex (stretch_reflex.h) if reflex.enabled;
// then command p = Eq. (12)-(13), clamped to [0, p_max]. All sensors are sampled whatever
// reflex.sensor says, so the model and fiber variants of a trial see the same noise.
// The random generator is a std::mt19937_64 owned by the controller, seeded with `seed`.
#pragma once

#include <array>
#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include "pam_actuator/pam_params.h"
#include "pam_actuator/spring_model.h"
#include "reflex/controller.h"
#include "reflex/length_estimator.h"
#include "reflex/lowpass_filter.h"
#include "reflex/sensors.h"
#include "reflex/stretch_reflex.h"

namespace pamsim {

enum class ReflexSensor { kModel, kFiber };

// "model" | "fiber"
const char* to_string(ReflexSensor sensor);
// Throws InputError naming the key reflex.sensor on anything else.
ReflexSensor parse_reflex_sensor(const std::string& name);

// Scenario keys reflex.*; the stretch-reflex law's keys are in StretchReflexParams.
struct ReflexConfig : StretchReflexParams {
  bool enabled = true;                         // reflex.enabled
  ReflexSensor sensor = ReflexSensor::kModel;  // reflex.sensor
  // reflex.lowpass_hz: first-order low-pass on the velocity fed to the reflex, 0 (off) or
  // (0, control_hz / 2]. Default off: DESIGN.md measured that 10 Hz delays the trigger by
  // ~30 ms and halves the gain and 5 Hz never triggers; at higher noise a low-pass on the
  // pressure (sensors.pressure_lowpass_hz) removes mistrips instead (see its caveat).
  double lowpass_hz = 0.0;
  // Trigger gates (pamsim's additions; the paper reports the problems they address, Sec. V-C:
  // "mistripping the reflex or making the reflex to continue triggering itself").
  // reflex.min_tension_N >= 0: a muscle's reflex triggers only while its strain gauge reads
  // at least this tension. A slack line cannot be stretched by the load; its model estimate
  // is l_n(p) (d = 0, Fig. 7), which moves with pressure alone: when reciprocal inhibition
  // lowers the antagonist's pressure, its natural length grows at ~70 mm per MPa (Table IV m)
  // and reads as a stretch of 100-250 mm/s. This is the spindle unloading the paper cites
  // (Sec. V-B). 1 N is 4-9 sigma of the default gauge noise. 0 disables the gate.
  double min_tension_n = 1.0;
  // reflex.reciprocal_trigger_inhibition: while one muscle's reflex window is open, the
  // other's reflex may not trigger (the Ia inhibitory interneuron silences the antagonist's
  // motor neurons, the trigger-level counterpart of Eq. (12)-(13)'s pressure inhibition).
  // Without it the antagonist, softened by inhibition, is stretched on the rebound, fires,
  // inhibits the agonist and throws the arm down again. Default on.
  bool reciprocal_trigger_inhibition = true;
};

// Table II's thresholds and gains for a sensor: model 70 mm/s and 1/800 MPa/(mm/s),
// fiber 25 mm/s and 1/300. The other fields keep their defaults.
ReflexConfig table_ii_reflex_config(ReflexSensor sensor);

struct ReflexControllerConfig {
  // top controller (Eq. (12)-(13) p_tp), gauge [Pa]: 0.4 MPa each as in the experiment
  std::array<double, kMuscleCount> p_tp_pa{0.4e6, 0.4e6};   // controller.p_tp_{ago,anta}_MPa
  // valve range [Pa]: 0.8 MPa, the highest pressure the paper applied to its PAMs (Sec. II)
  double p_max_pa = 0.8e6;                                  // controller.p_max_MPa
  // per muscle, from its parameter file (set_muscles() below)
  std::array<SpringModel, kMuscleCount> spring{};            // pams.<muscle>.spring
  std::array<StrainGaugeParams, kMuscleCount> gauge{};       // pams.<muscle>.strain_gauge
  SensorConfig sensors;
  ReflexConfig reflex;
  double control_hz = 100.0;                                 // sim.control_hz
  std::uint64_t seed = 0;                                    // the trial seed
};

// Fills spring and gauge from the two parameter files. Throws InputError naming the file's
// muscle if it has no [strain_gauge] table (the reflex needs Eq. (8)).
void set_muscles(ReflexControllerConfig* config, const PamParams& agonist,
                 const PamParams& antagonist);

// The Table IV arm (agonist and antagonist spring laws and q, V_base = 0) with all other
// fields at their defaults: the configuration of the paper's falling-mass experiment.
ReflexControllerConfig table_iv_reflex_controller_config();

// Checks every field once, throwing InputError "<key> must be ..., got <value>" naming the
// scenario key: reflex.* and sensors.* as documented on the structs, sim.control_hz,
// controller.p_max_MPa, controller.p_tp_ago_MPa, controller.p_tp_anta_MPa,
// pams.{agonist,antagonist}.strain_gauge.{q_V_per_N,V_base_V}, pams.{...}.spring.
void validate(const ReflexControllerConfig& config);

class ReflexController final : public Controller {
 public:
  // Validates the configuration (throws InputError) and seeds the generator.
  explicit ReflexController(const ReflexControllerConfig& config);

  ControlOutput update(const PlantSample& sample) override;

  const ReflexControllerConfig& config() const { return config_; }
  // Reflex triggers of a muscle so far (summary.json: reflex_triggers_ago/_anta).
  int trigger_count(Muscle muscle) const;
  const std::vector<double>& trigger_times_s(Muscle muscle) const;
  // Earliest trigger of either muscle [s]; NaN if none (summary.json: first_trigger_time_s).
  double first_trigger_time_s() const;

 private:
  ReflexControllerConfig config_;
  double dt_s_;
  std::mt19937_64 rng_;
  PressureSensor pressure_sensor_;
  std::array<StrainGauge, kMuscleCount> gauges_;
  std::array<FiberSensor, kMuscleCount> fibers_;
  std::array<LengthEstimator, kMuscleCount> estimators_;
  std::array<LowpassFilter, kMuscleCount> fiber_velocity_filters_;
  std::array<StretchReflex, kMuscleCount> reflexes_;
};

}  // namespace pamsim
