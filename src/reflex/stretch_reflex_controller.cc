// stretch_reflex_controller.cc: the reflex controllers' configuration checks and per-tick
// pipeline reading -> reflexes (Ia, Ib) -> Eq. (12)-(13); their kinds' keys are in
// reflex_kinds.cc.
#include "reflex/stretch_reflex_controller.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <cstdint>
#include <limits>
#include <set>
#include <stdexcept>

#include "base/enum_names.h"
#include "base/input_error.h"
#include "base/units.h"
#include "reflex/reflex_keys.h"
#include "sensing/checks.h"

namespace pamsim {
namespace {

using namespace checks;

constexpr EnumName<ReflexSensor> kSensorNames[] = {{ReflexSensor::kModel, "model"},
                                                   {ReflexSensor::kFiber, "fiber"}};

const StretchReflexControllerConfig& validated(const StretchReflexControllerConfig& config) {
  validate(config);
  return config;
}

}  // namespace

const char* to_string(ReflexSensor sensor) { return name_of(kSensorNames, sensor); }

ReflexSensor parse_reflex_sensor(const std::string& name) {
  return parse_name(kSensorNames, name, "reflex.sensor");
}

ReflexConfig table_ii_reflex_config(ReflexSensor sensor) {
  ReflexConfig reflex;  // the model-based reflex's values are StretchReflexParams' defaults
  reflex.sensor = sensor;
  if (sensor == ReflexSensor::kFiber) {
    reflex.v_thr_m_s = 0.025;
    reflex.k_pa_s_per_m = 1e9 / 300.0;  // 1/300 MPa per mm/s
  }
  return reflex;
}

void validate(const StretchReflexControllerConfig& config) {
  // control rate first: the window is checked against it
  require_positive("sim.control_hz", config.control_hz);
  const double dt = 1.0 / config.control_hz;

  // reflex.*
  const ReflexConfig& reflex = config.reflex;
  ReflexConfig fields = reflex;  // the rows' ranges and choices (the low-pass is the sensing's)
  double lowpass_hz = 0.0;
  check_key_rows(stretch_reflex_key_table(&fields, &lowpass_hz));
  require_window("reflex", reflex.duration_s, reflex.refractory_s, reflex.arm_after_s, dt);
  if (config.tension) validate(config.ib, config.control_hz);

  // the valve range, in MPa as in the scenario file
  require_positive("controller.p_max_MPa", units::pa_to_mpa(config.p_max_pa));

  // pairs: two distinct muscles in range, each muscle in one pair at most
  if (config.muscle_count < 0 || config.muscle_count > PAMCTL_MAX_MUSCLES) {
    fail("the muscle count",
         "in [0, " + std::to_string(PAMCTL_MAX_MUSCLES) + "] (the embedded controller's most)",
         config.muscle_count);
  }
  std::vector<char> paired(config.muscle_count, 0);
  for (std::size_t k = 0; k < config.pairs.size(); ++k) {
    const std::string key = "reflex.pairs[" + std::to_string(k) + "]";
    if (config.pairs[k].agonist == config.pairs[k].antagonist) {
      fail(key, "two different muscles, not one paired with itself (muscle index)",
           config.pairs[k].agonist);
    }
    for (int j : {config.pairs[k].agonist, config.pairs[k].antagonist}) {
      if (j < 0 || j >= config.muscle_count) {
        fail(key, "a muscle index in [0, " + std::to_string(config.muscle_count) + ")", j);
      }
      if (paired[j]) fail(key, "muscles not already in a pair (muscle index)", j);
      paired[j] = 1;
    }
  }
}

void embed_controller(const StretchReflexControllerConfig& config, pamctl_config* embedded) {
  const double dt = 1.0 / config.control_hz;
  embedded->muscle_count = config.muscle_count;
  embedded->kind = PAMCTL_KIND_REFLEX;
  embedded->control_period_s = dt;
  embedded->p_max_pa = config.p_max_pa;
  pamctl_reflex_config& rc = embedded->reflex;
  rc.enabled = config.reflex.enabled;
  rc.stretch = config.stretch;
  rc.tension = config.tension;
  rc.sensor =
      config.reflex.sensor == ReflexSensor::kFiber ? PAMCTL_SENSOR_FIBER : PAMCTL_SENSOR_MODEL;
  rc.min_tension_n = config.reflex.min_tension_n;
  rc.reciprocal_trigger_inhibition = config.reflex.reciprocal_trigger_inhibition;
  rc.excite_antagonist = config.ib.excite_antagonist;
  rc.ia = embedded_stretch(config.reflex, dt);
  rc.ib = embedded_tension(config.ib, dt);
  for (int j = 0; j < PAMCTL_MAX_MUSCLES; ++j) embedded->partner[j] = -1;
  for (const ReflexPair& pair : config.pairs) {
    embedded->partner[pair.agonist] = pair.antagonist;
    embedded->partner[pair.antagonist] = pair.agonist;
  }
}

std::vector<ControllerChannel> reflex_channels(bool tension) {
  std::vector<ControllerChannel> channels = {
      {"reflex_", "", "1 while the muscle's stretch (Ia) reflex window is open", true, ""}};
  if (tension) {
    channels.push_back({"tension_reflex_", "",
                        "1 while the muscle's tension (Ib) reflex window is open", true, " Ib"});
  }
  return channels;
}

std::vector<ControllerEvent> reflex_events(bool tension) {
  std::vector<ControllerEvent> events = {{"stretch_trigger", "a stretch (Ia) window opens"}};
  if (tension) events.push_back({"tension_trigger", "a tension (Ib) window opens"});
  return events;
}

StretchReflexController::StretchReflexController(const StretchReflexControllerConfig& config)
    : config_(validated(config)),
      event_times_s_(reflex_events(config.tension).size(),
                     std::vector<std::vector<double>>(config.muscle_count)) {
  embed_controller(config_, &embedded_);
  pamctl_reset(&embedded_, &state_);
}

void StretchReflexController::retune(const StretchReflexControllerConfig& config) {
  validate(config);
  if (config.stretch != config_.stretch || config.tension != config_.tension ||
      config.muscle_count != config_.muscle_count) {
    throw std::logic_error("retune: a reflex controller keeps its kind and muscles");
  }
  config_ = config;
  embed_controller(config_, &embedded_);
}

void StretchReflexController::update(const ControlInput& in, ControlOutput* out) {
  const std::size_t n = event_times_s_[kStretchTrigger].size();
  assert(in.readings && in.p_tp_pa && in.readings->size() == n && in.p_tp_pa->size() == n &&
         out->p_cmd_pa.size() == n && out->channels.size() == event_times_s_.size());
  // the estimates the sensing made (the embedded estimator's), then the embedded controller
  for (std::size_t j = 0; j < n; ++j) {
    const MuscleReading& r = (*in.readings)[j];
    pamctl_estimate& est = out_.estimates[j];
    est.force_n = r.force_meas_n;
    est.velocity_m_s = r.velocity_est_m_s;
    est.fiber_velocity_m_s = r.fiber_velocity_m_s;
    est.flags = 0;
  }
  pamctl_control(&embedded_, &state_, in.time_s, in.enabled, in.p_tp_pa->data(), &out_);
  for (std::size_t j = 0; j < n; ++j) {
    out->p_cmd_pa[j] = out_.p_cmd_pa[j];
    out->velocity_m_s[j] = out_.velocity_m_s[j];
    out->channels[kStretchWindow][j] = out_.ia_active[j] ? 1.0 : 0.0;
    if (out_.ia_triggered[j]) event_times_s_[kStretchTrigger][j].push_back(in.time_s);
    if (!config_.tension) continue;
    out->channels[kTensionWindow][j] = out_.ib_active[j] ? 1.0 : 0.0;
    if (out_.ib_triggered[j]) event_times_s_[kTensionTrigger][j].push_back(in.time_s);
  }
}

PairValues reflex_commands(const PairValues& p_tp_pa, const PairValues& dp_ia_pa,
                           const PairValues& dp_ib_pa, bool excite_antagonist, double p_max_pa) {
  // the embedded controller's rule (pamctl_pair_command), clamped to the valve's range
  pamctl_reflex_config rc{};
  rc.tension = true;
  rc.excite_antagonist = excite_antagonist;
  PairValues p;
  std::uint32_t flags = 0;
  for (int j : {kAgonist, kAntagonist}) {
    const double pj =
        pamctl_pair_command(&rc, p_tp_pa.data(), dp_ia_pa.data(), dp_ib_pa.data(), j, 1 - j);
    p[j] = pamctl_valve_command(pj, p_max_pa, &flags);
  }
  return p;
}

int StretchReflexController::trigger_count(int muscle) const {
  return static_cast<int>(event_times_s_[kStretchTrigger][muscle].size());
}

double StretchReflexController::first_trigger_time_s() const {
  double first = std::numeric_limits<double>::quiet_NaN();
  for (const std::vector<double>& times : event_times_s_[kStretchTrigger]) {
    if (!times.empty() && !(times.front() >= first)) first = times.front();
  }
  return first;
}

}  // namespace pamsim
