// scenario_bad_values_test.cc: a bad value of every scenario key, given by --set, is one
// line naming its key: the simulation, drop, pressures, valve and reflex keys, then the
// instruments', the time step's limits, the model files and misspelt keys.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "sim/scenario_errors.h"

namespace {

struct BadOverride {
  std::string assignment;
  std::string key;
};

// the simulation, the drop, the pressures, the valve, the reflex and the plain sensors
std::vector<BadOverride> bad_core_overrides() {
  return {
      {"seed=-1", "seed"},
      {"seed=1.5", "seed"},
      {"sim.timestep_s=0", "sim.timestep_s"},
      {"sim.timestep_s=-0.001", "sim.timestep_s"},
      {"sim.timestep_s=nan", "sim.timestep_s"},
      {"sim.timestep_s=0.5", "sim.timestep_s"},
      {"sim.duration_s=0", "sim.duration_s"},
      {"sim.duration_s=inf", "sim.duration_s"},
      {"sim.control_hz=0", "sim.control_hz"},
      {"sim.control_hz=300", "sim.control_hz"},
      {"sim.control_hz=5000", "sim.control_hz"},
      {"drop.mass_kg=0", "drop.mass_kg"},
      {"drop.mass_kg=-0.2", "drop.mass_kg"},
      {"drop.height_m=-0.1", "drop.height_m"},
      {"drop.height_m=5", "drop.height_m"},
      {"drop.time_s=-1", "drop.time_s"},
      {"drop.time_s=10", "drop.time_s"},
      {"drop.enabled=3", "drop.enabled"},
      {"pressure.agonist_MPa=-0.1", "pressure.agonist_MPa"},
      {"pressure.agonist_MPa=2", "pressure.agonist_MPa"},
      {"pressure.antagonist_MPa=nan", "pressure.antagonist_MPa"},
      {"pressure.antagonist_MPa=\"high\"", "pressure.antagonist_MPa"},
      {"valve.model=\"bang_bang\"", "valve.model"},
      {"valve.model=3", "valve.model"},
      {"model.joint=3", "model.joint"},
      {"reflex.enabled=\"yes\"", "reflex.enabled"},
      {"reflex.sensor=\"laser\"", "reflex.sensor"},
      {"reflex.v_thr_mm_s=0", "reflex.v_thr_mm_s"},
      {"reflex.v_thr_mm_s=-70", "reflex.v_thr_mm_s"},
      {"reflex.k_MPa_s_per_mm=-0.001", "reflex.k_MPa_s_per_mm"},
      {"reflex.k_MPa_s_per_mm=nan", "reflex.k_MPa_s_per_mm"},
      {"reflex.duration_s=0", "reflex.duration_s"},
      {"reflex.duration_s=0.001", "reflex.duration_s"},
      {"reflex.lowpass_hz=-5", "reflex.lowpass_hz"},
      {"reflex.lowpass_hz=80", "reflex.lowpass_hz"},
      {"reflex.mode=\"sticky\"", "reflex.mode"},
      {"reflex.refractory_s=-1", "reflex.refractory_s"},
      {"reflex.arm_after_s=-1", "reflex.arm_after_s"},
      {"reflex.min_tension_N=-1", "reflex.min_tension_N"},
      {"reflex.reciprocal_trigger_inhibition=1", "reflex.reciprocal_trigger_inhibition"},
      {"sensors.pressure_noise_MPa=-0.001", "sensors.pressure_noise_MPa"},
      {"sensors.pressure_bias_MPa=2", "sensors.pressure_bias_MPa"},
      {"sensors.pressure_adc_bits=2", "sensors.pressure_adc"},
      {"sensors.pressure_adc_max_V=-1", "sensors.pressure_adc"},
      {"sensors.pressure_lowpass_hz=-1", "sensors.pressure_lowpass_hz"},
      {"sensors.gauge_noise_V=-1", "sensors.gauge_noise_V"},
      {"sensors.gauge_adc_bits=40", "sensors.gauge_adc"},
      {"sensors.fiber_noise_mm_s=-2", "sensors.fiber_noise_mm_s"},
      {"sensors.noise_scale=-1", "sensors.noise_scale"},
  };
}

// the instruments as hardware
std::vector<BadOverride> bad_instrument_overrides() {
  return {
      // the gauge as hardware: one key each
      {"sensors.gauge.model=\"strain\"",
       "sensors.gauge.model is \"strain\", allowed \"linear\" | \"bridge\""},
      {"sensors.gauge.tolerance_pct=101", "sensors.gauge.tolerance_pct must be"},
      {"sensors.gauge.excitation_V=0", "sensors.gauge.excitation_V must be"},
      {"sensors.gauge.gauge_factor=nan", "sensors.gauge.gauge_factor must be"},
      {"sensors.gauge.nominal_Ohm=-120", "sensors.gauge.nominal_Ohm must be"},
      {"sensors.gauge.board.youngs_modulus_MPa=0", "sensors.gauge.board.youngs_modulus_MPa"},
      {"sensors.gauge.board.width_mm=-1", "sensors.gauge.board.width_mm must be"},
      {"sensors.gauge.board.thickness_mm=0", "sensors.gauge.board.thickness_mm must be"},
      {"sensors.gauge.board.thickness_mm=0.1", "strains the board at most 3 %"},
      {"sensors.gauge.board.gauge_position_mm=-1", "sensors.gauge.board.gauge_position_mm"},
      {"sensors.gauge.board.contact_position_mm=5", "sensors.gauge.board.contact_position_mm"},
      {"sensors.gauge.board.creep_weights=[-0.1]",
       "sensors.gauge.board.creep_weights[0] must be in [0, inf)"},
      {"sensors.gauge.board.creep_weights=[0.1]", "sensors.gauge.board.creep_times_s must list"},
      {"sensors.gauge.calibration.max_N=0", "sensors.gauge.calibration.max_N must be"},
      {"sensors.gauge.calibration.steps=0", "sensors.gauge.calibration.steps must be"},
      {"sensors.gauge.calibration.hold_s=-2", "sensors.gauge.calibration.hold_s must be"},
      // the pressure sensor, fiber sensor and encoder as hardware
      {"sensors.pressure.model=\"pse530\"",
       "sensors.pressure.model is \"pse530\", allowed \"ideal\" | \"pse540\""},
      {"sensors.pressure.bias_mean_MPa=nan", "sensors.pressure.bias_mean_MPa must be"},
      {"sensors.pressure.bias_stddev_MPa=-0.001", "sensors.pressure.bias_stddev_MPa must be"},
      {"sensors.pressure.gain_error_stddev_pct=-1",
       "sensors.pressure.gain_error_stddev_pct must be"},
      {"sensors.pressure.dynamic_bias_stddev_MPa=-0.001",
       "sensors.pressure.dynamic_bias_stddev_MPa must be"},
      {"sensors.pressure.dynamic_bias_correlation_time_s=0",
       "sensors.pressure.dynamic_bias_correlation_time_s must be"},
      {"sensors.pressure.dynamic_bias_correlation_time_s=nan",
       "sensors.pressure.dynamic_bias_correlation_time_s must be"},
      {"sensors.pressure.hysteresis_MPa=-0.002", "sensors.pressure.hysteresis_MPa must be"},
      {"sensors.pressure.response_time_ms=-1", "sensors.pressure.response_time_ms must be"},
      {"sensors.pressure.precision_MPa=-0.001", "sensors.pressure.precision_MPa must be"},
      {"sensors.fiber.model=\"knit\"",
       "sensors.fiber.model is \"knit\", allowed \"ideal\" | \"fabric\""},
      {"sensors.fiber.nonlinearity_pct=nan", "sensors.fiber.nonlinearity_pct must be"},
      {"sensors.fiber.span_mm=0", "sensors.fiber.span_mm must be"},
      {"sensors.fiber.creep_weights=[-0.1]", "sensors.fiber.creep_weights[0] must be in [0, inf)"},
      {"sensors.fiber.creep_times_s=[0]", "sensors.fiber.creep_times_s[0] must be in (0, inf) s"},
      {"sensors.fiber.creep_times_s=[1, 2]", "sensors.fiber.creep_times_s must list"},
      {"sensors.encoder.model=\"optical\"",
       "sensors.encoder.model is \"optical\", allowed \"ideal\" | \"counts\""},
      {"sensors.encoder.resolution_mm=0", "sensors.encoder.resolution_mm must be in (0, inf)"},
      {"sensors.instrument_seed=-1", "sensors.instrument_seed must be"},
  };
}

// the time step's limits, the plant, the model files, misspelt keys
std::vector<BadOverride> bad_file_overrides() {
  return {
      // a time step that makes an uncountable or endless trial
      {"sim.timestep_s=1e-308", "sim.timestep_s of 1e-308 s makes"},
      {"sim.timestep_s=1e-9", "more than sim.max_steps = 10000000"},
      {"sim.max_steps=0", "sim.max_steps"},
      {"sim.max_steps=1e11", "sim.max_steps"},
      // a plant that is not the muscle its estimator describes (216 mm against 180 mm)
      {"muscles.agonist.plant=\"../models/pams/plant_pam_a.toml\"",
       "muscles.agonist.plant has a length of 216 mm, but its estimator's file"},
      // and how to change both, for the braid angle
      {"muscles.agonist.plant.geometry.braid_angle_deg=30", "describes 25 deg: change both"},
      {"muscles.agonist.plant=\"../models/pams/missing.toml\"", "missing.toml"},
      {"valve.tube_critical_pressure_ratio=0.9995",
       "tube critical pressure ratio must be in [0, laminar ratio)"},
      {"sensors.noise_scale=1e4", "sensors.noise_scale"},
      {"controller.p_max_MPa=0", "controller.p_max_MPa"},
      {"controller.p_max_MPa=0.8", "controller.p_max_MPa"},  // above the 0.7 MPa regulator
      {"model.file=\"missing.xml\"", "missing.xml"},
      {"model.agonist_params=\"missing.toml\"", "missing.toml"},
      {"model.calibration=\"missing.toml\"", "missing.toml"},
      {"model.pneumatics=\"missing.toml\"", "missing.toml"},
      {"sim.timestepp_s=0.001", "sim.timestepp_s"},
      {"reflex.threshold=70", "reflex.threshold"},
  };
}

TEST(ScenarioTest, EveryBadValueNamesItsKey) {
  std::vector<BadOverride> cases = bad_core_overrides();
  for (const auto& more : {bad_instrument_overrides(), bad_file_overrides()}) {
    cases.insert(cases.end(), more.begin(), more.end());
  }
  for (const auto& c : cases) {
    const std::string message = pamsim_test::error_of("drop_mass.toml", {c.assignment});
    EXPECT_NE(message.find(c.key), std::string::npos) << c.assignment << " -> " << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << "one line: " << message;
  }
}

}  // namespace
