// reflex_kinds.cc: the reflex controllers as scenarios choose them (controller.kind):
// "stretch_reflex" (Ia), "tension_reflex" (Ib) and "stretch_tension_reflex" (both): their
// keys (read and documented by their rows, reflex_keys.h; controller.p_max_MPa and
// reflex.pairs, which depend on the rest of the scenario, here), summary fields and factory.
// The controller itself: stretch_reflex_controller.cc.
#include <algorithm>
#include <array>
#include <set>
#include <string>
#include <vector>

#include "base/config_reader.h"
#include "base/input_error.h"
#include "base/units.h"
#include "reflex/reflex_keys.h"
#include "reflex/stretch_reflex_controller.h"

namespace pamsim {

namespace {

using NamePairs = std::vector<std::array<std::string, 2>>;

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
  for (const ControllerScenario::Muscle& m : sc.muscles) {  // they would be clamped silently
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
                                                      const ControllerScenario& sc, bool stretch,
                                                      bool tension) {
  auto config = std::make_shared<StretchReflexScenarioConfig>();
  config->stretch = stretch;
  config->tension = tension;
  read_key_rows(in,
                stretch_reflex_key_table(&config->reflex, &config->velocity_lowpass_hz, stretch));
  if (tension) read_key_rows(in, tension_reflex_key_table(&config->ib));
  config->p_max_pa = read_p_max(in, sc);
  config->pairs = read_pairs(in, sc);
  // the values at the scenario's control rate (the pairs are checked by name above)
  in_file(in, [&] {
    validate(config->bound({static_cast<int>(sc.muscles.size()), sc.control_hz, {}}));
    return 0;
  });
  return config;
}

// the keys of a kind, in the order `pamsim keys` lists them: its rows, and the two keys
// whose values depend on the rest of the scenario
std::vector<ControllerKeyDoc> reflex_docs(bool stretch, bool tension) {
  ReflexConfig reflex;
  double lowpass_hz = SensingConfig{}.velocity_lowpass_hz;
  TensionReflexParams ib;
  std::vector<KeyTable> tables = {stretch_reflex_key_table(&reflex, &lowpass_hz, stretch)};
  if (tension) tables.push_back(tension_reflex_key_table(&ib));
  std::vector<ControllerKeyDoc> docs = {
      {"controller.p_max_MPa", "MPa", "(valve.command_max_MPa)", "(0, valve.command_max_MPa]",
       "the highest pressure the reflex commands", true},
      // (the pairs are bound to the model's muscles when it is loaded)
      {"reflex.pairs", "", "([[\"agonist\", \"antagonist\"]] when both exist)",
       "[[agonist, antagonist], ...]", "the reflex pairs by actuator name", false}};
  for (const KeyDoc& doc : key_table_docs(tables)) docs.push_back(doc);
  return docs;
}

// what may change during a trial: the thresholds, gains and trigger gate (the sensor, pairs,
// filters and windows shape the sensing and the log and hold); the sliders span Table II's
// values several times over
std::vector<LiveSetting> live_settings(bool stretch, bool tension) {
  std::vector<LiveSetting> live;
  if (stretch) {
    live.push_back({"reflex.v_thr_mm_s", 5.0, 300.0});
    live.push_back({"reflex.k_MPa_s_per_mm", 0.0, 0.005});
    live.push_back({"reflex.min_tension_N", 0.0, 10.0});
  }
  if (tension) {
    live.push_back({"reflex.ib.f_thr_N", 1.0, 300.0});
    live.push_back({"reflex.ib.k_MPa_per_N", 0.0, 0.02});
  }
  return live;
}

}  // namespace

StretchReflexControllerConfig StretchReflexScenarioConfig::bound(
    const ControllerSetup& setup) const {
  StretchReflexControllerConfig config;
  static_cast<StretchReflexSettings&>(config) = *this;
  config.control_hz = setup.control_hz;
  config.muscle_count = setup.muscle_count;
  config.pairs = setup.pairs;
  return config;
}

std::vector<SummaryField> StretchReflexScenarioConfig::summary_fields() const {
  std::vector<SummaryField> fields = {{"reflex_enabled", reflex.enabled}};
  if (stretch) {
    fields.push_back({"reflex_sensor", std::string(to_string(reflex.sensor))});
    ReflexConfig fields_of = reflex;  // the values in the file's units, by their rows
    double lowpass_hz = velocity_lowpass_hz;
    const KeyTable rows = stretch_reflex_key_table(&fields_of, &lowpass_hz);
    fields.push_back({"v_thr_mm_s", file_value(rows, "v_thr_mm_s")});
    fields.push_back({"k_MPa_s_per_mm", file_value(rows, "k_MPa_s_per_mm")});
  }
  if (tension) {
    fields.push_back({"ib_f_thr_N", ib.f_thr_N});
    fields.push_back({"ib_df_thr_N_s", ib.df_thr_N_s});
    TensionReflexParams ib_of = ib;
    const KeyTable ib_rows = tension_reflex_key_table(&ib_of);
    fields.push_back({"ib_k_MPa_per_N", file_value(ib_rows, "k_MPa_per_N")});
    fields.push_back({"ib_excite_antagonist", ib.excite_antagonist});
  }
  return fields;
}

std::unique_ptr<Controller> StretchReflexScenarioConfig::make_controller(
    const ControllerSetup& setup) const {
  return std::make_unique<StretchReflexController>(bound(setup));
}

std::vector<ControllerChannel> StretchReflexScenarioConfig::channels() const {
  return reflex_channels(tension);
}

std::vector<ControllerEvent> StretchReflexScenarioConfig::events() const {
  return reflex_events(tension);
}

std::string StretchReflexScenarioConfig::embedded(const ControllerSetup& setup,
                                                  pamctl_config* config) const {
  const StretchReflexControllerConfig bound_config = bound(setup);
  validate(bound_config);
  embed_controller(bound_config, config);
  return "";
}

void StretchReflexScenarioConfig::retune(Controller& controller,
                                         const ControllerSetup& setup) const {
  dynamic_cast<StretchReflexController&>(controller).retune(bound(setup));
}

ControllerKind stretch_reflex_controller_kind() {
  const auto read = [](ConfigReader& in, const ControllerScenario& sc) {
    return read_reflexes(in, sc, true, false);
  };
  return {"stretch_reflex", {"reflex"}, read, reflex_docs(true, false), live_settings(true, false)};
}

ControllerKind tension_reflex_controller_kind() {
  const auto read = [](ConfigReader& in, const ControllerScenario& sc) {
    return read_reflexes(in, sc, false, true);
  };
  return {"tension_reflex", {"reflex"}, read, reflex_docs(false, true), live_settings(false, true)};
}

ControllerKind stretch_tension_reflex_controller_kind() {
  const auto read = [](ConfigReader& in, const ControllerScenario& sc) {
    return read_reflexes(in, sc, true, true);
  };
  return {"stretch_tension_reflex",
          {"reflex"},
          read,
          reflex_docs(true, true),
          live_settings(true, true)};
}

}  // namespace pamsim
