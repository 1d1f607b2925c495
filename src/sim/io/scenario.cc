// scenario.cc: see scenario.h.
#include "sim/io/scenario.h"

#include <cmath>
#include <iterator>

#include "pam_actuator/input_error.h"
#include "pam_actuator/units.h"
#include "sim/io/config_reader.h"

namespace pamsim {
namespace {

// Runs `parse`, prefixing any InputError with the scenario's name.
template <typename F>
auto in_file(const ConfigReader& in, F&& parse) -> decltype(parse()) {
  try {
    return parse();
  } catch (const InputError& e) {
    throw InputError(in.name() + ": " + e.what());
  }
}

void read_reflex(ConfigReader& in, ReflexControllerConfig* c) {
  ReflexConfig& r = c->reflex;
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
  r.lowpass_hz = in.get_double("reflex.lowpass_hz", r.lowpass_hz);
  r.min_tension_n = in.get_double("reflex.min_tension_N", r.min_tension_n);
  r.reciprocal_trigger_inhibition =
      in.get_bool("reflex.reciprocal_trigger_inhibition", r.reciprocal_trigger_inhibition);

  SensorConfig& s = c->sensors;
  s.pressure_noise_mpa = in.get_double("sensors.pressure_noise_MPa", s.pressure_noise_mpa);
  s.pressure_bias_mpa = in.get_double("sensors.pressure_bias_MPa", s.pressure_bias_mpa);
  s.pressure_adc_bits = static_cast<int>(in.get_int("sensors.pressure_adc_bits", s.pressure_adc_bits));
  s.pressure_adc_min_v = in.get_double("sensors.pressure_adc_min_V", s.pressure_adc_min_v);
  s.pressure_adc_max_v = in.get_double("sensors.pressure_adc_max_V", s.pressure_adc_max_v);
  s.pressure_lowpass_hz = in.get_double("sensors.pressure_lowpass_hz", s.pressure_lowpass_hz);
  s.gauge_noise_v = in.get_double("sensors.gauge_noise_V", s.gauge_noise_v);
  s.gauge_adc_bits = static_cast<int>(in.get_int("sensors.gauge_adc_bits", s.gauge_adc_bits));
  s.gauge_adc_min_v = in.get_double("sensors.gauge_adc_min_V", s.gauge_adc_min_v);
  s.gauge_adc_max_v = in.get_double("sensors.gauge_adc_max_V", s.gauge_adc_max_v);
  s.fiber_noise_mm_s = in.get_double("sensors.fiber_noise_mm_s", s.fiber_noise_mm_s);

  c->p_max_pa = units::mpa_to_pa(in.get_double("controller.p_max_MPa", units::pa_to_mpa(c->p_max_pa)));
}

}  // namespace

namespace {
Scenario read_scenario(ConfigReader& in, const std::vector<std::string>& overrides);
}  // namespace

const std::vector<std::string>& scenario_path_keys() {
  static const std::vector<std::string> keys = {"model.file", "model.agonist_params",
                                                "model.antagonist_params", "model.calibration",
                                                "model.pneumatics"};
  return keys;
}

Scenario load_scenario(const std::string& path, const std::vector<std::string>& overrides) {
  ConfigReader in(path);
  return read_scenario(in, overrides);
}

Scenario load_scenario_text(const std::string& text, const std::string& path,
                            const std::vector<std::string>& overrides) {
  ConfigReader in(text, path);
  return read_scenario(in, overrides);
}

namespace {

Scenario read_scenario(ConfigReader& in, const std::vector<std::string>& overrides) {
  for (const auto& o : overrides) in.apply_override(o);
  Scenario sc;
  sc.path = in.name();

  // the trial
  const std::int64_t seed = in.get_int("seed", 1);
  in.check(seed >= 0, "seed", "must be >= 0, got " + std::to_string(seed));
  sc.seed = static_cast<std::uint64_t>(seed);

  // files
  std::string* const files[] = {&sc.model_file, &sc.agonist_params, &sc.antagonist_params,
                                &sc.calibration_file, &sc.pneumatics_file};
  static_assert(std::size(files) == 5, "one target per scenario_path_keys() entry");
  for (std::size_t i = 0; i < std::size(files); ++i) {
    const std::string& key = scenario_path_keys()[i];
    *files[i] = in.get_path(key, "");
    in.check(!files[i]->empty(), key, "is required");
  }

  // time
  sc.timestep_s = in.get_double("sim.timestep_s", sc.timestep_s);
  in.check(sc.timestep_s > 0 && sc.timestep_s <= 0.01, "sim.timestep_s",
           "must be in (0, 0.01] s, got " + format_value(sc.timestep_s));
  sc.duration_s = in.get_double("sim.duration_s", sc.duration_s);
  in.check(sc.duration_s > 0 && sc.duration_s <= 3600, "sim.duration_s",
           "must be in (0, 3600] s, got " + format_value(sc.duration_s));
  sc.control_hz = in.get_double("sim.control_hz", sc.control_hz);
  in.check(sc.control_hz > 0, "sim.control_hz", "must be > 0, got " + format_value(sc.control_hz));
  const double ratio = 1.0 / (sc.control_hz * sc.timestep_s);
  in.check(ratio >= 1.0 - 1e-9 && std::fabs(ratio - std::round(ratio)) < 1e-6, "sim.control_hz",
           "must divide the physics rate 1/sim.timestep_s into whole steps, got " +
               format_value(sc.control_hz) + " Hz at " + format_value(sc.timestep_s) + " s");

  // the drop
  sc.drop_enabled = in.get_bool("drop.enabled", sc.drop_enabled);
  sc.drop_mass_kg = in.get_double("drop.mass_kg", sc.drop_mass_kg);
  in.check(sc.drop_mass_kg > 0 && sc.drop_mass_kg <= 10, "drop.mass_kg",
           "must be in (0, 10] kg, got " + format_value(sc.drop_mass_kg));
  sc.drop_height_m = in.get_double("drop.height_m", sc.drop_height_m);
  in.check(sc.drop_height_m >= 0 && sc.drop_height_m <= 1, "drop.height_m",
           "must be in [0, 1] m, got " + format_value(sc.drop_height_m));
  sc.drop_time_s = in.get_double("drop.time_s", sc.drop_time_s);
  in.check(sc.drop_time_s >= 0 && sc.drop_time_s < sc.duration_s, "drop.time_s",
           "must be in [0, sim.duration_s), got " + format_value(sc.drop_time_s));

  // valve and pneumatics
  sc.pneumatics = load_pneumatic_params(sc.pneumatics_file);
  const std::string valve = in.get_string("valve.model", valve_model_name(sc.valve_model));
  sc.valve_model = parse_valve_model(valve, in.name() + ": valve.model");

  // goal pressures (the top controller)
  const double supply_mpa = units::pa_to_mpa(sc.pneumatics.supply_gauge_pa);
  for (auto [key, target] : {std::pair{"pressure.agonist_MPa", &sc.p_goal_agonist_pa},
                             {"pressure.antagonist_MPa", &sc.p_goal_antagonist_pa}}) {
    const double p = in.get_double(key, units::pa_to_mpa(*target));
    in.check(p >= 0 && p <= supply_mpa, key,
             "must be in [0, " + format_value(supply_mpa) + "] MPa (the supply), got " +
                 format_value(p));
    *target = units::mpa_to_pa(p);
  }

  // reflex and sensors
  sc.reflex.p_tp_pa = {sc.p_goal_agonist_pa, sc.p_goal_antagonist_pa};
  sc.reflex.control_hz = sc.control_hz;
  sc.reflex.p_max_pa = sc.pneumatics.command_max_gauge_pa;
  read_reflex(in, &sc.reflex);
  in.reject_unknown();
  in_file(in, [&] {
    sc.pam[kAgonist] = load_pam_params(sc.agonist_params);
    sc.pam[kAntagonist] = load_pam_params(sc.antagonist_params);
    set_muscles(&sc.reflex, sc.pam[kAgonist], sc.pam[kAntagonist]);
    validate(sc.reflex);
    return 0;
  });
  return sc;
}

}  // namespace

}  // namespace pamsim
