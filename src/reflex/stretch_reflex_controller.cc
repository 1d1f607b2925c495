// stretch_reflex_controller.cc: the reflex controllers' configuration checks and per-tick
// pipeline reading -> reflexes (Ia, Ib) -> Eq. (12)-(13); their kinds' keys are in
// reflex_kinds.cc.
#include "reflex/stretch_reflex_controller.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>
#include <set>

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
  ReflexConfig reflex;   // the model-based reflex's values are StretchReflexParams' defaults
  reflex.sensor = sensor;
  if (sensor == ReflexSensor::kFiber) {
    reflex.v_thr_m_s = 0.025;
    reflex.k_pa_s_per_m = 1e9 / 300.0;   // 1/300 MPa per mm/s
  }
  return reflex;
}

void validate(const StretchReflexControllerConfig& config) {
  // control rate first: the window is checked against it
  require_positive("sim.control_hz", config.control_hz);
  const double dt = 1.0 / config.control_hz;

  // reflex.*
  const ReflexConfig& reflex = config.reflex;
  ReflexConfig fields = reflex;   // the rows' ranges and choices (the low-pass is the sensing's)
  double lowpass_hz = 0.0;
  check_key_rows(stretch_reflex_key_table(&fields, &lowpass_hz));
  require_window("reflex", reflex.duration_s, reflex.refractory_s, reflex.arm_after_s, dt);
  if (config.tension) validate(config.ib, config.control_hz);

  // the valve range, in MPa as in the scenario file
  require_positive("controller.p_max_MPa", units::pa_to_mpa(config.p_max_pa));

  // pairs: two distinct muscles in range, each muscle in one pair at most
  if (config.muscle_count < 0) fail("the muscle count", ">= 0", config.muscle_count);
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

StretchReflexController::StretchReflexController(const StretchReflexControllerConfig& config)
    : config_(validated(config)),
      partner_(config.muscle_count, -1),
      reflexes_(config.muscle_count, StretchReflex(config.reflex, 1.0 / config.control_hz)),
      tension_reflexes_(config.muscle_count, TensionReflex(config.ib, 1.0 / config.control_hz)),
      dp_pa_(config.muscle_count, 0.0),
      dp_ib_pa_(config.muscle_count, 0.0),
      was_active_(config.muscle_count, 0),
      trigger_times_s_(config.muscle_count),
      tension_trigger_times_s_(config.muscle_count) {
  for (const ReflexPair& pair : config.pairs) {
    partner_[pair.agonist] = pair.antagonist;
    partner_[pair.antagonist] = pair.agonist;
  }
}

void StretchReflexController::update(const ControlInput& in, ControlOutput* out) {
  assert(in.readings && in.p_tp_pa && in.readings->size() == reflexes_.size() &&
         in.p_tp_pa->size() == reflexes_.size() && out->p_cmd_pa.size() == reflexes_.size());
  const std::vector<MuscleReading>& readings = *in.readings;
  const std::vector<double>& p_tp = *in.p_tp_pa;
  const ReflexConfig& rc = config_.reflex;
  for (std::size_t j = 0; j < reflexes_.size(); ++j) was_active_[j] = reflexes_[j].active();

  for (std::size_t j = 0; j < reflexes_.size(); ++j) {
    // the velocity the reflex sees
    const MuscleReading& r = readings[j];
    const double v = rc.sensor == ReflexSensor::kFiber ? r.fiber_velocity_m_s : r.velocity_est_m_s;
    out->velocity_m_s[j] = v;
    dp_pa_[j] = 0.0;
    dp_ib_pa_[j] = 0.0;
    out->reflex_active[j] = 0;
    out->tension_reflex_active[j] = 0;
    // while the controller is switched off its windows and refractory times run out
    // without acting
    if (!rc.enabled || partner_[j] < 0) continue;
    if (config_.stretch) run_stretch_reflex(j, in, v, out);
    if (config_.tension) run_tension_reflex(j, in, out);
  }

  // Eq. (12)-(13) per pair, clamped to the valve's range; unpaired muscles get p_tp
  for (std::size_t j = 0; j < reflexes_.size(); ++j) {
    if (partner_[j] < 0) out->p_cmd_pa[j] = std::clamp(p_tp[j], 0.0, config_.p_max_pa);
  }
  for (const ReflexPair& pair : config_.pairs) {
    const PairValues p_tp_pair = {p_tp[pair.agonist], p_tp[pair.antagonist]};
    const PairValues dp = {dp_pa_[pair.agonist], dp_pa_[pair.antagonist]};
    const PairValues p =
        config_.tension
            ? reflex_commands(p_tp_pair, dp, {dp_ib_pa_[pair.agonist], dp_ib_pa_[pair.antagonist]},
                              config_.ib.excite_antagonist, config_.p_max_pa)
            : reflex_commands(p_tp_pair, dp, config_.p_max_pa);
    out->p_cmd_pa[pair.agonist] = p[kAgonist];
    out->p_cmd_pa[pair.antagonist] = p[kAntagonist];
  }
}

void StretchReflexController::run_stretch_reflex(std::size_t j, const ControlInput& in, double v,
                                                 ControlOutput* out) {
  // this muscle's reflex, Eq. (14), behind the tension and reciprocal gates
  const ReflexConfig& rc = config_.reflex;
  const bool loaded = rc.min_tension_n <= 0.0 || (*in.readings)[j].force_meas_n >= rc.min_tension_n;
  const bool other_quiet = !(rc.reciprocal_trigger_inhibition && was_active_[partner_[j]]);
  const double dp = reflexes_[j].update(in.time_s, v, in.enabled && loaded && other_quiet);
  if (!in.enabled) return;
  dp_pa_[j] = dp;
  out->reflex_active[j] = reflexes_[j].active() ? 1 : 0;
  if (reflexes_[j].triggered()) trigger_times_s_[j].push_back(in.time_s);
}

void StretchReflexController::run_tension_reflex(std::size_t j, const ControlInput& in,
                                                 ControlOutput* out) {
  // the muscle's tension reflex on its gauge's tension, Eq. (8)-(9)
  const double dp = tension_reflexes_[j].update(in.time_s, (*in.readings)[j].force_meas_n,
                                                in.enabled);
  if (!in.enabled) return;
  dp_ib_pa_[j] = dp;
  out->tension_reflex_active[j] = tension_reflexes_[j].active() ? 1 : 0;
  if (tension_reflexes_[j].triggered()) tension_trigger_times_s_[j].push_back(in.time_s);
}

PairValues reflex_commands(const PairValues& p_tp_pa, const PairValues& dp_ia_pa,
                           const PairValues& dp_ib_pa, bool excite_antagonist,
                           double p_max_pa) {
  const double e = excite_antagonist ? 1.0 : 0.0;
  PairValues p;
  p[kAgonist] = p_tp_pa[kAgonist] + dp_ia_pa[kAgonist] - dp_ia_pa[kAntagonist] -
                dp_ib_pa[kAgonist] + e * dp_ib_pa[kAntagonist];
  p[kAntagonist] = p_tp_pa[kAntagonist] + dp_ia_pa[kAntagonist] - dp_ia_pa[kAgonist] -
                   dp_ib_pa[kAntagonist] + e * dp_ib_pa[kAgonist];
  for (double& pj : p) pj = std::clamp(pj, 0.0, p_max_pa);
  return p;
}

int StretchReflexController::trigger_count(int muscle) const {
  return static_cast<int>(trigger_times_s_[muscle].size());
}

double StretchReflexController::first_trigger_time_s() const {
  double first = std::numeric_limits<double>::quiet_NaN();
  for (const std::vector<double>& times : trigger_times_s_) {
    if (!times.empty() && !(times.front() >= first)) first = times.front();
  }
  return first;
}

}  // namespace pamsim
