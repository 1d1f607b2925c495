// stretch_reflex_controller.h: controller "stretch_reflex", the paper's controller for the
// falling-mass experiment (Sec. III-D): the scheduled goal pressures (the top controller's
// p_tp) plus one stretch reflex per muscle of each antagonistic pair declared in the
// scenario (Eq. (12)-(14)), driven by the model-based velocity estimate (Eq. (9)-(11)) or by
// the fiber sensor's rate. Muscles in no pair get their scheduled command.
//
// Per control tick, muscle by muscle in model order:
//   1. take v from the reading: the estimate (reflex.sensor = "model") or the fiber rate
//      ("fiber"), both low-passed at reflex.lowpass_hz by the sensing (sensing.h,
//      SensingConfig::velocity_lowpass_hz, which this kind's reader sets);
//   2. run the muscle's stretch reflex (stretch_reflex.h) if reflex.enabled and the
//      controller is on, behind two gates (below);
// then command each pair by Eq. (12)-(13), clamped to [0, p_max].
#pragma once

#include <string>
#include <vector>

#include "reflex/controller.h"
#include "reflex/controller_kind.h"
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
  // Trigger gates (pamsim's additions; the paper reports the problems they address, Sec. V-C:
  // "mistripping the reflex or making the reflex to continue triggering itself").
  // reflex.min_tension_N >= 0: a muscle's reflex triggers only while its strain gauge reads
  // at least this tension. A slack line cannot be stretched by the load; its model estimate
  // is l_n(p) (d = 0, Fig. 7), which moves with pressure alone: when reciprocal inhibition
  // lowers the antagonist's pressure, its natural length grows at ~70 mm per MPa (Table IV m)
  // and reads as a stretch of 100-250 mm/s. This is the spindle unloading the paper cites
  // (Sec. V-B). 1 N is 4-9 sigma of the default gauge noise. 0 (or less) disables the gate.
  double min_tension_n = 1.0;
  // reflex.reciprocal_trigger_inhibition: while one muscle's reflex window is open, its
  // pair partner's reflex may not trigger (the Ia inhibitory interneuron silences the
  // antagonist's motor neurons, the trigger-level counterpart of Eq. (12)-(13)'s pressure
  // inhibition). Without it the antagonist, softened by inhibition, is stretched on the
  // rebound, fires, inhibits the agonist and throws the arm down again. Default on.
  bool reciprocal_trigger_inhibition = true;
};

// Table II's thresholds and gains for a sensor: model, StretchReflexParams' defaults (70 mm/s
// and 1/800 MPa/(mm/s)); fiber 25 mm/s and 1/300. The other fields keep their defaults.
ReflexConfig table_ii_reflex_config(ReflexSensor sensor);

struct StretchReflexControllerConfig {
  ReflexConfig reflex;
  // valve range [Pa]: the commands are clamped to [0, p_max]     controller.p_max_MPa
  double p_max_pa = 0.8e6;
  double control_hz = 100.0;                                   // sim.control_hz
  int muscle_count = 2;
  std::vector<ReflexPair> pairs{ReflexPair{}};                 // reflex.pairs
};

// Checks every field once, throwing InputError "<key> must be ..., got <value>" naming the
// scenario key: reflex.* as documented on the structs, sim.control_hz, controller.p_max_MPa,
// and reflex.pairs (indices in range, no muscle in two pairs or paired with itself).
// (reflex.lowpass_hz is the sensing's velocity low-pass: SensingConfig, checked there.)
void validate(const StretchReflexControllerConfig& config);

// The kind "stretch_reflex" as a scenario configures it (controller_kind.h): the keys
// reflex.* and controller.p_max_MPa, read by stretch_reflex_controller_kind()'s reader.
class StretchReflexScenarioConfig final : public ControllerConfig {
 public:
  ReflexConfig reflex;     // reflex.*
  double p_max_pa = 0.0;   // controller.p_max_MPa, or the regulator's command maximum

  // The controller's configuration for a trial's muscles, pairs and control rate.
  StretchReflexControllerConfig bound(const ControllerSetup& setup) const;
  bool has_reflexes() const override { return true; }
  // reflex_enabled, reflex_sensor, v_thr_mm_s, k_MPa_s_per_mm
  std::vector<SummaryField> summary_fields() const override;
  std::unique_ptr<Controller> make_controller(const ControllerSetup& setup) const override;
};

// The kind "stretch_reflex" (listed in controller_registry.cc): its reader checks the keys
// above, reflex.pairs by name (default: agonist and antagonist when both exist) and each
// muscle's schedule against controller.p_max_MPa, and sets the sensing's velocity low-pass
// from reflex.lowpass_hz.
ControllerKind stretch_reflex_controller_kind();

class StretchReflexController final : public Controller {
 public:
  // Validates the configuration (throws InputError).
  explicit StretchReflexController(const StretchReflexControllerConfig& config);

  void update(const ControlInput& in, ControlOutput* out) override;
  const std::vector<std::vector<double>>* trigger_times_s() const override {
    return &trigger_times_s_;
  }

  const StretchReflexControllerConfig& config() const { return config_; }
  int trigger_count(int muscle) const;
  // Earliest trigger of any muscle [s]; NaN if none.
  double first_trigger_time_s() const;

 private:
  StretchReflexControllerConfig config_;
  std::vector<int> partner_;            // pair partner of each muscle, -1 if unpaired
  std::vector<StretchReflex> reflexes_;
  std::vector<double> dp_pa_;           // this tick's reflex outputs
  std::vector<char> was_active_;        // whose window was open at the previous tick
  std::vector<std::vector<double>> trigger_times_s_;
};

}  // namespace pamsim
