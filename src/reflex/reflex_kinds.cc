// reflex_kinds.cc: the reflex controllers as scenarios choose them (controller.kind):
// "stretch_reflex" (Ia), "tension_reflex" (Ib) and "stretch_tension_reflex" (both), their
// keys reflex.*, reflex.ib.* and controller.p_max_MPa (read, checked, documented), their
// summary fields and factory. The controller itself: stretch_reflex_controller.cc.
#include <algorithm>
#include <array>
#include <set>
#include <string>
#include <vector>

#include "base/config_reader.h"
#include "base/input_error.h"
#include "base/units.h"
#include "reflex/stretch_reflex_controller.h"

namespace pamsim {

namespace {

using NamePairs = std::vector<std::array<std::string, 2>>;

// reflex.* of the stretch reflex; reflex.lowpass_hz, the low-pass its velocity needs, into
// *lowpass_hz (the sensing applies it)
void read_stretch(ConfigReader& in, double* lowpass_hz, ReflexConfig* out) {
  ReflexConfig& r = *out;
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
  *lowpass_hz = in.get_double("reflex.lowpass_hz", *lowpass_hz);
  r.min_tension_n = in.get_double("reflex.min_tension_N", r.min_tension_n);
  r.reciprocal_trigger_inhibition =
      in.get_bool("reflex.reciprocal_trigger_inhibition", r.reciprocal_trigger_inhibition);
}

// reflex.ib.*: the threshold and the gain are required (no paper gives them for a PAM)
TensionReflexParams read_tension(ConfigReader& in) {
  TensionReflexParams p;
  p.f_thr_N = in.require_double("reflex.ib.f_thr_N");
  p.k_MPa_per_N = in.require_double("reflex.ib.k_MPa_per_N");
  p.df_thr_N_s = in.get_double("reflex.ib.df_thr_N_s", p.df_thr_N_s);
  p.duration_s = in.get_double("reflex.ib.duration_s", p.duration_s);
  const std::string mode = in.get_string("reflex.ib.mode", to_string(p.mode));
  p.mode = in_file(in, [&] { return parse_reflex_mode(mode, "reflex.ib.mode"); });
  p.refractory_s = in.get_double("reflex.ib.refractory_s", p.refractory_s);
  p.arm_after_s = in.get_double("reflex.ib.arm_after_s", p.arm_after_s);
  p.rate_lowpass_hz = in.get_double("reflex.ib.rate_lowpass_hz", p.rate_lowpass_hz);
  p.excite_antagonist = in.get_bool("reflex.ib.excite_antagonist", p.excite_antagonist);
  return p;
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

// a kind with the stretch reflexes, the tension reflexes or both
std::shared_ptr<const ControllerConfig> read_reflexes(ConfigReader& in,
                                                      const ControllerScenario& sc,
                                                      bool stretch, bool tension) {
  auto config = std::make_shared<StretchReflexScenarioConfig>();
  config->stretch = stretch;
  config->tension = tension;
  config->reflex.enabled = in.get_bool("reflex.enabled", config->reflex.enabled);
  if (stretch) read_stretch(in, &config->velocity_lowpass_hz, &config->reflex);
  if (tension) config->ib = read_tension(in);
  config->p_max_pa = read_p_max(in, sc);
  config->pairs = read_pairs(in, sc);
  // the values at the scenario's control rate (the pairs are checked by name above)
  in_file(in, [&] {
    validate(config->bound({static_cast<int>(sc.muscles.size()), sc.control_hz, {}}));
    return 0;
  });
  return config;
}

// the keys of a kind, in the order `pamsim keys` lists them
std::vector<ControllerKeyDoc> reflex_docs(bool stretch, bool tension) {
  const ReflexConfig d;
  const ReflexConfig fiber = table_ii_reflex_config(ReflexSensor::kFiber);
  const TensionReflexParams ib;
  const auto quoted = [](const char* name) { return "\"" + std::string(name) + "\""; };
  const auto boolean = [](bool b) { return std::string(b ? "true" : "false"); };
  std::vector<ControllerKeyDoc> docs = {
      {"controller.p_max_MPa", "MPa", "(valve.command_max_MPa)", "(0, valve.command_max_MPa]", "the highest pressure the reflex commands"},
      {"reflex.enabled", "", boolean(d.enabled), "true | false", "the reflex may trigger (false: the passive arm, same sensing)"}};
  const std::vector<ControllerKeyDoc> ia = {
      {"reflex.sensor", "", quoted(to_string(d.sensor)), "\"model\" | \"fiber\"", "the stretch velocity from the spring model (Eq. (9)-(11)) or a fiber sensor"},
      {"reflex.v_thr_mm_s", "mm/s", "(Table II: " + format_number(d.v_thr_mm_s) + " model, " + format_number(fiber.v_thr_mm_s) + " fiber)", "> 0", "the trigger threshold V_thr, Eq. (12)"},
      {"reflex.k_MPa_s_per_mm", "MPa s/mm", "(Table II: 1/800 model, 1/300 fiber)", ">= 0", "the reflex gain k, Eq. (13)-(14)"},
      {"reflex.duration_s", "s", format_number(d.duration_s), ">= one control period", "the reflex window"},
      {"reflex.mode", "", quoted(to_string(d.mode)), "\"follow\" | \"latch\"", "the command follows the velocity, or holds its trigger value"},
      {"reflex.refractory_s", "s", format_number(d.refractory_s), ">= 0 (0: off)", "no retrigger this long after a window ends"},
      {"reflex.arm_after_s", "s", format_number(d.arm_after_s), ">= 0 (0: off)", "no trigger before this time"},
      {"reflex.lowpass_hz", "Hz", format_number(SensingConfig{}.velocity_lowpass_hz), "0 (off) or (0, sim.control_hz / 2]", "low-pass on the estimated velocity"},
      {"reflex.min_tension_N", "N", format_number(d.min_tension_n), ">= 0", "trigger only while the gauge reads at least this tension"},
      {"reflex.reciprocal_trigger_inhibition", "", boolean(d.reciprocal_trigger_inhibition), "true | false", "a triggered muscle inhibits its antagonist's trigger"}};
  const std::vector<ControllerKeyDoc> ibs = {
      {"reflex.ib.f_thr_N", "N", "(required)", "> 0", "the tension (Ib) reflex's threshold on the gauge's tension"},
      {"reflex.ib.k_MPa_per_N", "MPa/N", "(required)", ">= 0", "its gain: dp = k f, off its own muscle's command"},
      {"reflex.ib.df_thr_N_s", "N/s", format_number(ib.df_thr_N_s), ">= 0 (0: off)", "it also triggers when the tension's rate exceeds this"},
      {"reflex.ib.duration_s", "s", format_number(ib.duration_s), ">= one control period", "its window"},
      {"reflex.ib.mode", "", quoted(to_string(ib.mode)), "\"follow\" | \"latch\"", "the output follows the tension, or holds its trigger value"},
      {"reflex.ib.refractory_s", "s", format_number(ib.refractory_s), ">= 0 (0: off)", "no retrigger this long after a window ends"},
      {"reflex.ib.arm_after_s", "s", format_number(ib.arm_after_s), ">= 0 (0: off)", "no trigger before this time"},
      {"reflex.ib.rate_lowpass_hz", "Hz", format_number(ib.rate_lowpass_hz), "0 (off) or (0, sim.control_hz / 2]", "low-pass on the tension's rate"},
      {"reflex.ib.excite_antagonist", "", boolean(ib.excite_antagonist), "true | false", "the output also raises the pair partner's command"}};
  if (stretch) docs.insert(docs.end(), ia.begin(), ia.end());
  docs.push_back({"reflex.pairs", "", "([[\"agonist\", \"antagonist\"]] when both exist)", "[[agonist, antagonist], ...]", "the reflex pairs by actuator name"});
  if (tension) docs.insert(docs.end(), ibs.begin(), ibs.end());
  return docs;
}

}  // namespace

StretchReflexControllerConfig StretchReflexScenarioConfig::bound(
    const ControllerSetup& setup) const {
  StretchReflexControllerConfig config;
  config.reflex = reflex;
  config.stretch = stretch;
  config.tension = tension;
  config.ib = ib;
  config.p_max_pa = p_max_pa;
  config.control_hz = setup.control_hz;
  config.muscle_count = setup.muscle_count;
  config.pairs = setup.pairs;
  return config;
}

std::vector<SummaryField> StretchReflexScenarioConfig::summary_fields() const {
  std::vector<SummaryField> fields = {{"reflex_enabled", reflex.enabled}};
  if (stretch) {
    fields.push_back({"reflex_sensor", std::string(to_string(reflex.sensor))});
    fields.push_back({"v_thr_mm_s", reflex.v_thr_mm_s});
    fields.push_back({"k_MPa_s_per_mm", reflex.k_MPa_s_per_mm});
  }
  if (tension) {
    fields.push_back({"ib_f_thr_N", ib.f_thr_N});
    fields.push_back({"ib_df_thr_N_s", ib.df_thr_N_s});
    fields.push_back({"ib_k_MPa_per_N", ib.k_MPa_per_N});
    fields.push_back({"ib_excite_antagonist", ib.excite_antagonist});
  }
  return fields;
}

std::unique_ptr<Controller> StretchReflexScenarioConfig::make_controller(
    const ControllerSetup& setup) const {
  return std::make_unique<StretchReflexController>(bound(setup));
}

ControllerKind stretch_reflex_controller_kind() {
  const auto read = [](ConfigReader& in, const ControllerScenario& sc) {
    return read_reflexes(in, sc, true, false);
  };
  return {"stretch_reflex", {"reflex"}, read, reflex_docs(true, false)};
}

ControllerKind tension_reflex_controller_kind() {
  const auto read = [](ConfigReader& in, const ControllerScenario& sc) {
    return read_reflexes(in, sc, false, true);
  };
  return {"tension_reflex", {"reflex"}, read, reflex_docs(false, true)};
}

ControllerKind stretch_tension_reflex_controller_kind() {
  const auto read = [](ConfigReader& in, const ControllerScenario& sc) {
    return read_reflexes(in, sc, true, true);
  };
  return {"stretch_tension_reflex", {"reflex"}, read, reflex_docs(true, true)};
}

}  // namespace pamsim
