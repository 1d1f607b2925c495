// stretch_reflex_controller.cc: the kind "stretch_reflex" whole: its scenario keys (read,
// checked, documented), configuration checks, and the per-tick pipeline
// reading -> reflex -> Eq. (12)-(13).
#include "reflex/stretch_reflex_controller.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>
#include <set>

#include "base/config_reader.h"
#include "base/enum_names.h"
#include "base/input_error.h"
#include "base/units.h"
#include "reflex/checks.h"

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
    reflex.v_thr_mm_s = 25.0;
    reflex.k_MPa_s_per_mm = 1.0 / 300.0;
  }
  return reflex;
}

void validate(const StretchReflexControllerConfig& config) {
  // control rate first: the window is checked against it
  require_positive("sim.control_hz", config.control_hz);
  const double dt = 1.0 / config.control_hz;

  // reflex.*
  const ReflexConfig& reflex = config.reflex;
  if (reflex.sensor != ReflexSensor::kModel && reflex.sensor != ReflexSensor::kFiber) {
    fail("reflex.sensor", "\"model\" or \"fiber\"", static_cast<int>(reflex.sensor));
  }
  if (reflex.mode != ReflexMode::kFollow && reflex.mode != ReflexMode::kLatch) {
    fail("reflex.mode", "\"follow\" or \"latch\"", static_cast<int>(reflex.mode));
  }
  require_positive("reflex.v_thr_mm_s", reflex.v_thr_mm_s);
  require_non_negative("reflex.k_MPa_s_per_mm", reflex.k_MPa_s_per_mm);
  if (!(std::isfinite(reflex.duration_s) && reflex.duration_s >= dt * (1.0 - 1e-9))) {
    fail("reflex.duration_s", ">= one control period (" + format_value(dt) + " s)",
         reflex.duration_s);
  }
  require_non_negative("reflex.refractory_s", reflex.refractory_s);
  // both are counted in int control ticks (stretch_reflex.cc): a bound far below INT_MAX
  const double max_ticks_s = 1e9 * dt;
  for (const auto& [key, value] : {std::pair{"reflex.duration_s", reflex.duration_s},
                                   std::pair{"reflex.refractory_s", reflex.refractory_s}}) {
    if (!(value <= max_ticks_s)) {
      fail(key, "at most " + format_value(max_ticks_s) + " s (1e9 control periods)", value);
    }
  }
  require_non_negative("reflex.arm_after_s", reflex.arm_after_s);
  require_non_negative("reflex.min_tension_N", reflex.min_tension_n);

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
      dp_pa_(config.muscle_count, 0.0),
      was_active_(config.muscle_count, 0),
      trigger_times_s_(config.muscle_count) {
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
    out->reflex_active[j] = 0;

    // this muscle's reflex, Eq. (14), behind the tension and reciprocal gates; while the
    // controller is switched off its windows and refractory time run out without acting
    const int partner = partner_[j];
    if (!rc.enabled || partner < 0) continue;
    const bool loaded = rc.min_tension_n <= 0.0 || r.force_meas_n >= rc.min_tension_n;
    const bool other_quiet = !(rc.reciprocal_trigger_inhibition && was_active_[partner]);
    const double dp = reflexes_[j].update(in.time_s, v, in.enabled && loaded && other_quiet);
    if (!in.enabled) continue;
    dp_pa_[j] = dp;
    out->reflex_active[j] = reflexes_[j].active() ? 1 : 0;
    if (reflexes_[j].triggered()) trigger_times_s_[j].push_back(in.time_s);
  }

  // Eq. (12)-(13) per pair, clamped to the valve's range; unpaired muscles get p_tp
  for (std::size_t j = 0; j < reflexes_.size(); ++j) {
    if (partner_[j] < 0) out->p_cmd_pa[j] = std::clamp(p_tp[j], 0.0, config_.p_max_pa);
  }
  for (const ReflexPair& pair : config_.pairs) {
    const PairValues p = reflex_commands({p_tp[pair.agonist], p_tp[pair.antagonist]},
                                         {dp_pa_[pair.agonist], dp_pa_[pair.antagonist]},
                                         config_.p_max_pa);
    out->p_cmd_pa[pair.agonist] = p[kAgonist];
    out->p_cmd_pa[pair.antagonist] = p[kAntagonist];
  }
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

// ---- the kind: scenario keys, summary fields, factory ----

namespace {

using NamePairs = std::vector<std::array<std::string, 2>>;

// reflex.*; reflex.lowpass_hz is the sensing's
ReflexConfig read_reflex(ConfigReader& in, SensingConfig* sensing) {
  ReflexConfig r;
  r.enabled = in.get_bool("reflex.enabled", r.enabled);
  const std::string sensor = in.get_string("reflex.sensor", to_string(r.sensor));
  r.sensor = in_file(in, [&] { return parse_reflex_sensor(sensor); });
  // Table II values are the defaults for the chosen sensor
  const ReflexConfig table = table_ii_reflex_config(r.sensor);
  r.v_thr_mm_s = in.get_double("reflex.v_thr_mm_s", table.v_thr_mm_s);
  r.k_MPa_s_per_mm = in.get_double("reflex.k_MPa_s_per_mm", table.k_MPa_s_per_mm);
  r.duration_s = in.get_double("reflex.duration_s", r.duration_s);
  const std::string mode = in.get_string("reflex.mode", to_string(r.mode));
  r.mode = in_file(in, [&] { return parse_reflex_mode(mode); });
  r.refractory_s = in.get_double("reflex.refractory_s", r.refractory_s);
  r.arm_after_s = in.get_double("reflex.arm_after_s", r.arm_after_s);
  sensing->velocity_lowpass_hz = in.get_double("reflex.lowpass_hz", sensing->velocity_lowpass_hz);
  r.min_tension_n = in.get_double("reflex.min_tension_N", r.min_tension_n);
  r.reciprocal_trigger_inhibition =
      in.get_bool("reflex.reciprocal_trigger_inhibition", r.reciprocal_trigger_inhibition);
  return r;
}

// controller.p_max_MPa [Pa]: within the regulator's range, above every schedule
double read_p_max(ConfigReader& in, const ControllerScenario& sc) {
  const double p_max_pa = in.has("controller.p_max_MPa")
                              ? units::mpa_to_pa(in.get_double("controller.p_max_MPa", 0.0))
                              : sc.command_max_pa;
  // one pressure limit everywhere: the reflex cannot ask beyond what the regulator gives
  in.check(!(p_max_pa > sc.command_max_pa), "controller.p_max_MPa",
           "must be <= the regulator's command maximum (" +
               format_value(units::pa_to_mpa(sc.command_max_pa)) + " MPa), got " +
               format_value(units::pa_to_mpa(p_max_pa)));
  for (const ControllerScenario::Muscle& m : sc.muscles) {   // they would be clamped silently
    in.check(!(m.command_max_pa > p_max_pa), m.key + ".command",
             "goes up to " + format_value(units::pa_to_mpa(m.command_max_pa)) +
                 " MPa, above controller.p_max_MPa = " + format_value(units::pa_to_mpa(p_max_pa)));
  }
  return p_max_pa;
}

// reflex.pairs by actuator name; agonist/antagonist by default
NamePairs read_pairs(ConfigReader& in, const ControllerScenario& sc) {
  const auto is_muscle = [&](const std::string& name) {
    return std::any_of(sc.muscles.begin(), sc.muscles.end(),
                       [&](const ControllerScenario::Muscle& m) { return m.actuator == name; });
  };
  NamePairs pairs;
  if (in.has("reflex.pairs")) {
    const toml::array* a = in.raw("reflex.pairs")->as_array();
    in.check(a != nullptr, "reflex.pairs", "must be a list of [agonist, antagonist] name pairs");
    for (const toml::node& item : *a) {
      const toml::array* pair = item.as_array();
      const bool ok = pair && pair->size() == 2 && (*pair)[0].is_string() && (*pair)[1].is_string();
      in.check(ok, "reflex.pairs", "must be a list of [agonist, antagonist] name pairs");
      pairs.push_back({*(*pair)[0].value<std::string>(), *(*pair)[1].value<std::string>()});
    }
  } else if (is_muscle("agonist") && is_muscle("antagonist")) {
    pairs.push_back({"agonist", "antagonist"});
  }
  in.check(!pairs.empty(), "reflex.pairs",
           "is required: the scenario has no muscles named agonist and antagonist");
  // each pair two different muscles of the scenario, each muscle in one pair at most
  std::set<std::string> paired;
  for (const auto& pair : pairs) {
    in.check(pair[0] != pair[1], "reflex.pairs", "pairs muscle '" + pair[0] + "' with itself");
    for (const std::string& name : pair) {
      in.check(is_muscle(name), "reflex.pairs",
               "names muscle '" + name + "', which is not a muscle of the scenario");
      in.check(paired.insert(name).second, "reflex.pairs",
               "puts muscle '" + name + "' in two pairs");
    }
  }
  return pairs;
}

std::shared_ptr<const ControllerConfig> read_stretch_reflex(ConfigReader& in,
                                                            const ControllerScenario& sc) {
  auto config = std::make_shared<StretchReflexScenarioConfig>();
  config->reflex = read_reflex(in, sc.sensing);
  config->p_max_pa = read_p_max(in, sc);
  config->pairs = read_pairs(in, sc);
  // the values at the scenario's control rate (the pairs are checked by name above)
  in_file(in, [&] {
    validate(config->bound({static_cast<int>(sc.muscles.size()), sc.control_hz, {}}));
    return 0;
  });
  return config;
}

std::vector<ControllerKeyDoc> stretch_reflex_docs() {
  const ReflexConfig d;
  const ReflexConfig fiber = table_ii_reflex_config(ReflexSensor::kFiber);
  const auto quoted = [](const char* name) { return "\"" + std::string(name) + "\""; };
  const auto boolean = [](bool b) { return std::string(b ? "true" : "false"); };
  return {
      {"controller.p_max_MPa", "MPa", "(valve.command_max_MPa)", "(0, valve.command_max_MPa]", "the highest pressure the reflex commands"},
      {"reflex.enabled", "", boolean(d.enabled), "true | false", "the reflex may trigger (false: the passive arm, same sensing)"},
      {"reflex.sensor", "", quoted(to_string(d.sensor)), "\"model\" | \"fiber\"", "the stretch velocity from the spring model (Eq. (9)-(11)) or a fiber sensor"},
      {"reflex.v_thr_mm_s", "mm/s", "(Table II: " + format_number(d.v_thr_mm_s) + " model, " + format_number(fiber.v_thr_mm_s) + " fiber)", "> 0", "the trigger threshold V_thr, Eq. (12)"},
      {"reflex.k_MPa_s_per_mm", "MPa s/mm", "(Table II: 1/800 model, 1/300 fiber)", ">= 0", "the reflex gain k, Eq. (13)-(14)"},
      {"reflex.duration_s", "s", format_number(d.duration_s), ">= one control period", "the reflex window"},
      {"reflex.mode", "", quoted(to_string(d.mode)), "\"follow\" | \"latch\"", "the command follows the velocity, or holds its trigger value"},
      {"reflex.refractory_s", "s", format_number(d.refractory_s), ">= 0 (0: off)", "no retrigger this long after a window ends"},
      {"reflex.arm_after_s", "s", format_number(d.arm_after_s), ">= 0 (0: off)", "no trigger before this time"},
      {"reflex.lowpass_hz", "Hz", format_number(SensingConfig{}.velocity_lowpass_hz), "0 (off) or (0, sim.control_hz / 2]", "low-pass on the estimated velocity"},
      {"reflex.min_tension_N", "N", format_number(d.min_tension_n), ">= 0", "trigger only while the gauge reads at least this tension"},
      {"reflex.reciprocal_trigger_inhibition", "", boolean(d.reciprocal_trigger_inhibition), "true | false", "a triggered muscle inhibits its antagonist's trigger"},
      {"reflex.pairs", "", "([[\"agonist\", \"antagonist\"]] when both exist)", "[[agonist, antagonist], ...]", "the reflex pairs by actuator name"},
  };
}

}  // namespace

StretchReflexControllerConfig StretchReflexScenarioConfig::bound(
    const ControllerSetup& setup) const {
  StretchReflexControllerConfig config;
  config.reflex = reflex;
  config.p_max_pa = p_max_pa;
  config.control_hz = setup.control_hz;
  config.muscle_count = setup.muscle_count;
  config.pairs = setup.pairs;
  return config;
}

std::vector<SummaryField> StretchReflexScenarioConfig::summary_fields() const {
  return {{"reflex_enabled", reflex.enabled},
          {"reflex_sensor", std::string(to_string(reflex.sensor))},
          {"v_thr_mm_s", reflex.v_thr_mm_s},
          {"k_MPa_s_per_mm", reflex.k_MPa_s_per_mm}};
}

std::unique_ptr<Controller> StretchReflexScenarioConfig::make_controller(
    const ControllerSetup& setup) const {
  return std::make_unique<StretchReflexController>(bound(setup));
}

ControllerKind stretch_reflex_controller_kind() {
  return {"stretch_reflex", {"reflex"}, read_stretch_reflex, stretch_reflex_docs()};
}

}  // namespace pamsim
