// stretch_reflex_controller.h: the reflex controllers. Controller "stretch_reflex" is the
// paper's controller for the falling-mass experiment (Sec. III-D): the scheduled goal
// pressures (the top controller's p_tp) plus one stretch (Ia) reflex per muscle of each
// antagonistic pair declared in the scenario (Eq. (12)-(14)), driven by the model-based
// velocity estimate (Eq. (9)-(11)) or by the fiber sensor's rate. "tension_reflex" has the
// tension (Ib) reflex of tension_reflex.h instead, driven by the strain gauge's tension
// (Eq. (8)-(9)); "stretch_tension_reflex" has both, the paper's next step (Sec. V). Muscles
// in no pair get their scheduled command. All of it is the embedded controller's code
// (pamctl_control, src/embedded/pamctl.h), which the robot runs.
#pragma once

#include <string>
#include <vector>

#include "reflex/controller.h"
#include "reflex/controller_kind.h"
#include "reflex/stretch_reflex.h"
#include "reflex/tension_reflex.h"

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

// What a reflex kind's keys set (reflex.*, reflex.ib.*, controller.p_max_MPa), in SI: the one
// type its rows fill, which the scenario's configuration holds and its controller runs with.
struct StretchReflexSettings {
  ReflexConfig reflex;
  bool stretch = true;   // the Ia reflexes run
  bool tension = false;  // the Ib reflexes run (reflex.ib.*)
  TensionReflexParams ib;
  // valve range [Pa]: the commands are clamped to [0, p_max]     controller.p_max_MPa
  double p_max_pa = 0.8e6;
};

// The settings bound to a trial: its control rate, muscles and pairs.
struct StretchReflexControllerConfig : StretchReflexSettings {
  double control_hz = 100.0;  // sim.control_hz
  int muscle_count = 2;
  std::vector<ReflexPair> pairs{ReflexPair{}};  // reflex.pairs
};

// The controller's part of the embedded controller's configuration (kind, reflexes, pairs,
// valve range, control period); the estimator's part is the sensing's
// (SensorSuite::embedded_config).
void embed_controller(const StretchReflexControllerConfig& config, pamctl_config* embedded);

// Checks every field once, throwing InputError "<key> must be ..., got <value>" naming the
// scenario key: reflex.* and, with the tension reflex, reflex.ib.* as documented on the
// structs, sim.control_hz, controller.p_max_MPa, and reflex.pairs (indices in range, no
// muscle in two pairs or paired with itself).
// (reflex.lowpass_hz is the sensing's velocity low-pass: SensingConfig, checked there.)
void validate(const StretchReflexControllerConfig& config);

// Eq. (12)-(13) with the Ib reflexes (pamsim's rule; the paper gives none): every reflex's
// output reaches its muscle's command and its partner's as inputs converge on a motor
// neuron, summed:
//   p_ago  = p_tp_ago  + dp_ia_ago  - dp_ia_anta - dp_ib_ago  + e dp_ib_anta
//   p_anta = p_tp_anta + dp_ia_anta - dp_ia_ago  - dp_ib_anta + e dp_ib_ago
// with e = 1 if reflex.ib.excite_antagonist, else 0; each clamped to [0, p_max_pa]. So a
// tension reflex can cancel its own muscle's stretch reflex, as autogenic inhibition does.
PairValues reflex_commands(const PairValues& p_tp_pa, const PairValues& dp_ia_pa,
                           const PairValues& dp_ib_pa, bool excite_antagonist, double p_max_pa);

// A reflex kind as a scenario configures it (controller_kind.h): the keys reflex.*,
// reflex.ib.* and controller.p_max_MPa, read by the kinds' readers.
class StretchReflexScenarioConfig final : public ControllerConfig, public StretchReflexSettings {
 public:
  // The controller's configuration for a trial's muscles, pairs and control rate.
  StretchReflexControllerConfig bound(const ControllerSetup& setup) const;
  // the windows: reflex_<m> (Ia; every reflex kind logs it), tension_reflex_<m> (Ib, with
  // the tension reflexes); the triggers: stretch_trigger, and tension_trigger likewise
  std::vector<ControllerChannel> channels() const override;
  std::vector<ControllerEvent> events() const override;
  // reflex_enabled; with Ia reflex_sensor, v_thr_mm_s, k_MPa_s_per_mm; with Ib
  // ib_f_thr_N, ib_df_thr_N_s, ib_k_MPa_per_N
  std::vector<SummaryField> summary_fields() const override;
  std::unique_ptr<Controller> make_controller(const ControllerSetup& setup) const override;
  std::string embedded(const ControllerSetup& setup, pamctl_config* config) const override;
  void retune(Controller& controller, const ControllerSetup& setup) const override;
};

// The kind "stretch_reflex" (listed in controller_registry.cc): its reader checks the keys
// above, reflex.pairs by name (default: agonist and antagonist when both exist) and each
// muscle's schedule against controller.p_max_MPa, and sets the sensing's velocity low-pass
// from reflex.lowpass_hz.
ControllerKind stretch_reflex_controller_kind();
// The kinds "tension_reflex" (Ib alone: reflex.enabled, reflex.pairs and reflex.ib.*) and
// "stretch_tension_reflex" (both: every key above), listed in controller_registry.cc.
ControllerKind tension_reflex_controller_kind();
ControllerKind stretch_tension_reflex_controller_kind();

// Per control tick, muscle by muscle in model order:
//   1. take v from the reading: the estimate (reflex.sensor = "model") or the fiber rate
//      ("fiber"), both low-passed at reflex.lowpass_hz by the sensing (sensing.h,
//      SensingConfig::velocity_lowpass_hz, from this kind's ControllerConfig);
//   2. run the muscle's stretch reflex (stretch_reflex.h) if reflex.enabled and the
//      controller is on, behind two gates (ReflexConfig); and its tension reflex on the
//      measured tension, with no gate of its own (its windows are not the log's reflex_<m>
//      flag, which is the stretch reflex's; the metric set "tension" counts its triggers);
// then command each pair, clamped to [0, p_max]: by Eq. (12)-(13) with the Ia reflexes
// alone, and with the Ib reflexes by the rule of reflex_commands (above).
class StretchReflexController final : public Controller {
 public:
  // Validates the configuration (throws InputError).
  explicit StretchReflexController(const StretchReflexControllerConfig& config);

  // the channels and events of reflex_channels() and reflex_events() for config.tension
  static constexpr int kStretchWindow = 0;   // ControlOutput::channels: reflex_<m>
  static constexpr int kTensionWindow = 1;   // tension_reflex_<m>, with the Ib reflexes
  static constexpr int kStretchTrigger = 0;  // event_times_s()
  static constexpr int kTensionTrigger = 1;

  void update(const ControlInput& in, ControlOutput* out) override;
  // These settings from the next tick, the state kept (ControllerConfig::retune). Throws
  // InputError as the constructor, and std::logic_error for another kind's reflexes (the
  // Ia or Ib reflexes added or taken away) or other muscles.
  void retune(const StretchReflexControllerConfig& config);
  const std::vector<std::vector<std::vector<double>>>& event_times_s() const override {
    return event_times_s_;
  }
  // The stretch (Ia) reflexes' trigger times per muscle, and the tension (Ib) reflexes'
  // (nullptr without them).
  const std::vector<std::vector<double>>* trigger_times_s() const {
    return &event_times_s_[kStretchTrigger];
  }
  const std::vector<std::vector<double>>* tension_trigger_times_s() const {
    return config_.tension ? &event_times_s_[kTensionTrigger] : nullptr;
  }

  const StretchReflexControllerConfig& config() const { return config_; }
  int trigger_count(int muscle) const;
  // Earliest trigger of any muscle [s]; NaN if none.
  double first_trigger_time_s() const;

 private:
  StretchReflexControllerConfig config_;
  pamctl_config embedded_{};  // its settings as the embedded controller holds them
  pamctl_state state_{};
  pamctl_output out_{};
  std::vector<std::vector<std::vector<double>>> event_times_s_;  // [event][muscle][k]
};

// What a reflex controller logs: its windows (reflex_<m>, and tension_reflex_<m> with
// `tension`) and its triggers (stretch_trigger, tension_trigger), in the order of the
// StretchReflexController's constants.
std::vector<ControllerChannel> reflex_channels(bool tension);
std::vector<ControllerEvent> reflex_events(bool tension);

}  // namespace pamsim
