// reflex_controller_test.cc: the ReflexController end to end on synthetic plant samples
// (a stretch ramp triggers the agonist reflex; quiet noisy samples at the default noise do
// not), determinism per seed, telemetry, and a bad-value test for every validated key.
#include "reflex/reflex_controller.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "pam_actuator/input_error.h"
#include "pam_actuator/spring_model.h"

namespace pamsim {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// the falling-mass operating point (DESIGN.md): both at 0.4 MPa, agonist d = 6.66 mm,
// antagonist d = 1.0 mm
struct Plant {
  ReflexControllerConfig config = table_iv_reflex_controller_config();
  double d_m[kMuscleCount] = {6.66e-3, 1.0e-3};
  double p_pa[kMuscleCount] = {0.4e6, 0.4e6};

  PlantSample sample(double t) const {
    PlantSample s;
    s.time_s = t;
    for (int j = 0; j < kMuscleCount; ++j) {
      s.muscle[j].pressure_pa = p_pa[j];
      s.muscle[j].force_n = spring_force(config.spring[j], p_pa[j], d_m[j]);
      s.muscle[j].length_m = natural_length(config.spring[j], p_pa[j]) + d_m[j];
    }
    return s;
  }
};

// quiet for 1 s, then the agonist stretched (antagonist shortened) at 150 mm/s for 50 ms
void run_ramp(ReflexController* controller, Plant* plant, std::vector<ControlOutput>* outs) {
  for (int j = 0; j < 200; ++j) {
    const double t = j * 0.01;
    if (j > 100 && j <= 105) {
      plant->d_m[kAgonist] += 0.150 * 0.01;
      plant->d_m[kAntagonist] = std::max(plant->d_m[kAntagonist] - 0.150 * 0.01, -5e-3);
    }
    outs->push_back(controller->update(plant->sample(t)));
  }
}

TEST(ReflexController, StretchRampTriggersAgonistReflex) {
  for (ReflexSensor sensor : {ReflexSensor::kModel, ReflexSensor::kFiber}) {
    Plant plant;
    plant.config.reflex = table_ii_reflex_config(sensor);
    plant.config.seed = 7;
    ReflexController controller(plant.config);
    std::vector<ControlOutput> outs;
    run_ramp(&controller, &plant, &outs);
    SCOPED_TRACE(to_string(sensor));
    EXPECT_EQ(controller.trigger_count(kAgonist), 1);
    EXPECT_EQ(controller.trigger_count(kAntagonist), 0);
    // the first stretched tick (t = 1.01 s) exceeds the threshold
    EXPECT_NEAR(controller.first_trigger_time_s(), 1.01, 1e-9);
    const ControlOutput& during = outs[102];
    EXPECT_TRUE(during.telemetry[kAgonist].reflex_active);
    EXPECT_FALSE(during.telemetry[kAntagonist].reflex_active);
    // agonist up by k v, antagonist down by k v (v ~ 150 mm/s), within [0, p_max]
    // (the fiber gain 1/300 asks for 0.5 MPa: both commands hit the valve's range)
    const double k_v = std::min(plant.config.reflex.k_MPa_s_per_mm * 150.0 * 1e6, 0.4e6);
    EXPECT_NEAR(during.p_cmd_pa[kAgonist] - 0.4e6, k_v, 0.15 * k_v);
    EXPECT_NEAR(0.4e6 - during.p_cmd_pa[kAntagonist], k_v, 0.15 * k_v);
    // follow mode: back to the goal once the stretch stops, inside the window
    EXPECT_NEAR(outs[110].p_cmd_pa[kAgonist], 0.4e6, 0.02e6);
    EXPECT_TRUE(outs[110].telemetry[kAgonist].reflex_active);
    // the window is 20 ticks
    int active = 0;
    for (const ControlOutput& o : outs) active += o.telemetry[kAgonist].reflex_active;
    EXPECT_EQ(active, 20);
    // before and well after: the goal pressures
    EXPECT_EQ(outs[50].p_cmd_pa[kAgonist], 0.4e6);
    EXPECT_EQ(outs[150].p_cmd_pa[kAntagonist], 0.4e6);
  }
}

TEST(ReflexController, QuietNoisySamplesNeverTripAtDefaults) {
  // 10 s at 100 Hz, static arm, default noise and filters, several seeds, both sensors
  for (ReflexSensor sensor : {ReflexSensor::kModel, ReflexSensor::kFiber}) {
    double max_v = 0.0;
    for (std::uint64_t seed = 1; seed <= 5; ++seed) {
      Plant plant;
      plant.config.reflex = table_ii_reflex_config(sensor);
      plant.config.seed = seed;
      ReflexController controller(plant.config);
      for (int j = 0; j < 1000; ++j) {
        const ControlOutput out = controller.update(plant.sample(j * 0.01));
        for (int m = 0; m < kMuscleCount; ++m) {
          max_v = std::max(max_v, out.telemetry[m].velocity_est_m_s);
        }
      }
      EXPECT_EQ(controller.trigger_count(kAgonist), 0) << to_string(sensor) << " " << seed;
      EXPECT_EQ(controller.trigger_count(kAntagonist), 0) << to_string(sensor) << " " << seed;
      EXPECT_TRUE(std::isnan(controller.first_trigger_time_s()));
    }
    // a margin, not just luck: the largest stretch velocity stays well under threshold
    const double v_thr = table_ii_reflex_config(sensor).v_thr_mm_s * 1e-3;
    EXPECT_LT(max_v, 0.6 * v_thr) << to_string(sensor) << " max v " << max_v;
  }
}

TEST(ReflexController, PressureLowpassRemovesMistripsAtHighNoise) {
  // DESIGN.md: at 0.003 MPa / 0.5 N the unfiltered model-based velocity mistrips the 70 mm/s
  // threshold most quiet seconds; a 5 Hz low-pass on the measured pressure removes it
  auto trips = [](double pressure_lowpass_hz) {
    int count = 0;
    for (std::uint64_t seed = 1; seed <= 3; ++seed) {
      Plant plant;
      plant.config.sensors.pressure_noise_mpa = 0.003;
      plant.config.sensors.gauge_noise_v = 0.5 * plant.config.gauge[kAgonist].q_v_per_n;
      plant.config.sensors.pressure_lowpass_hz = pressure_lowpass_hz;
      plant.config.reflex.refractory_s = 0.0;
      plant.config.seed = seed;
      ReflexController controller(plant.config);
      for (int j = 0; j < 1000; ++j) controller.update(plant.sample(j * 0.01));
      count += controller.trigger_count(kAgonist) + controller.trigger_count(kAntagonist);
    }
    return count;
  };
  EXPECT_GT(trips(0.0), 10);
  EXPECT_EQ(trips(5.0), 0);
}

TEST(ReflexController, DeterministicPerSeed) {
  auto trace = [](std::uint64_t seed) {
    Plant plant;
    plant.config.seed = seed;
    ReflexController controller(plant.config);
    std::vector<double> out;
    for (int j = 0; j < 200; ++j) {
      const ControlOutput o = controller.update(plant.sample(j * 0.01));
      for (const MuscleTelemetry& t : o.telemetry) {
        out.push_back(t.pressure_sensor_v);
        out.push_back(t.gauge_v);
        out.push_back(t.fiber_rate);
        out.push_back(t.velocity_est_m_s);
      }
    }
    return out;
  };
  EXPECT_EQ(trace(99), trace(99));
  EXPECT_NE(trace(99), trace(100));
}

TEST(ReflexController, FillsEveryTelemetryField) {
  Plant plant;
  ReflexController controller(plant.config);
  controller.update(plant.sample(0.0));
  const ControlOutput out = controller.update(plant.sample(0.01));
  for (int j = 0; j < kMuscleCount; ++j) {
    const MuscleTelemetry& t = out.telemetry[j];
    EXPECT_TRUE(std::isfinite(t.pressure_sensor_v));
    EXPECT_TRUE(std::isfinite(t.gauge_v));
    EXPECT_TRUE(std::isfinite(t.fiber_rate));
    EXPECT_TRUE(std::isfinite(t.fiber_length_m));
    EXPECT_TRUE(std::isfinite(t.velocity_est_m_s));
    EXPECT_NEAR(t.pressure_sensor_v, 2.6, 0.02);
    EXPECT_NEAR(t.pressure_meas_pa, 0.4e6, 5e3);
    EXPECT_NEAR(t.force_meas_n, plant.sample(0.0).muscle[j].force_n, 1.0);
    EXPECT_NEAR(t.length_est_m, plant.sample(0.0).muscle[j].length_m, 0.5e-3);
    EXPECT_NEAR(t.fiber_length_m, plant.sample(0.0).muscle[j].length_m, 0.1e-3);
    EXPECT_FALSE(t.reflex_active);
  }
}

TEST(ReflexController, DisabledReflexHoldsGoalPressures) {
  Plant plant;
  plant.config.reflex.enabled = false;
  plant.config.p_tp_pa = {0.45e6, 0.35e6};
  ReflexController controller(plant.config);
  std::vector<ControlOutput> outs;
  run_ramp(&controller, &plant, &outs);
  EXPECT_EQ(controller.trigger_count(kAgonist), 0);
  for (const ControlOutput& o : outs) {
    EXPECT_EQ(o.p_cmd_pa[kAgonist], 0.45e6);
    EXPECT_EQ(o.p_cmd_pa[kAntagonist], 0.35e6);
  }
}

TEST(ReflexController, LatchModeHoldsTheTriggerCommand) {
  Plant plant;
  plant.config.reflex.mode = ReflexMode::kLatch;
  plant.config.sensors.pressure_noise_mpa = 0.0;
  plant.config.sensors.gauge_noise_v = 0.0;
  ReflexController controller(plant.config);
  std::vector<ControlOutput> outs;
  run_ramp(&controller, &plant, &outs);
  // the ramp stops at tick 105; latched, the command stays up until tick 120
  EXPECT_NEAR(outs[101].p_cmd_pa[kAgonist], outs[119].p_cmd_pa[kAgonist], 1e-6);
  EXPECT_GT(outs[119].p_cmd_pa[kAgonist], 0.5e6);
  EXPECT_EQ(outs[121].p_cmd_pa[kAgonist], 0.4e6);
}

// --- bad values: every validated key, the message names it ---

struct BadValue {
  std::string key;
  std::function<void(ReflexControllerConfig&)> set;
};

std::vector<BadValue> bad_values() {
  using C = ReflexControllerConfig&;
  return {
      {"sim.control_hz", [](C c) { c.control_hz = 0.0; }},
      {"sim.control_hz", [](C c) { c.control_hz = kNaN; }},
      {"reflex.sensor", [](C c) { c.reflex.sensor = static_cast<ReflexSensor>(7); }},
      {"reflex.mode", [](C c) { c.reflex.mode = static_cast<ReflexMode>(7); }},
      {"reflex.v_thr_mm_s", [](C c) { c.reflex.v_thr_mm_s = -5.0; }},
      {"reflex.v_thr_mm_s", [](C c) { c.reflex.v_thr_mm_s = 0.0; }},
      {"reflex.v_thr_mm_s", [](C c) { c.reflex.v_thr_mm_s = kNaN; }},
      {"reflex.k_MPa_s_per_mm", [](C c) { c.reflex.k_MPa_s_per_mm = -0.001; }},
      {"reflex.k_MPa_s_per_mm", [](C c) { c.reflex.k_MPa_s_per_mm = kNaN; }},
      {"reflex.duration_s", [](C c) { c.reflex.duration_s = -0.2; }},
      {"reflex.duration_s", [](C c) { c.reflex.duration_s = 0.001; }},
      {"reflex.duration_s", [](C c) { c.reflex.duration_s = kNaN; }},
      {"reflex.lowpass_hz", [](C c) { c.reflex.lowpass_hz = -1.0; }},
      {"reflex.lowpass_hz", [](C c) { c.reflex.lowpass_hz = 60.0; }},
      {"reflex.lowpass_hz", [](C c) { c.reflex.lowpass_hz = kNaN; }},
      {"reflex.refractory_s", [](C c) { c.reflex.refractory_s = -0.1; }},
      {"reflex.refractory_s", [](C c) { c.reflex.refractory_s = kNaN; }},
      {"reflex.arm_after_s", [](C c) { c.reflex.arm_after_s = -1.0; }},
      {"reflex.arm_after_s", [](C c) { c.reflex.arm_after_s = kNaN; }},
      {"sensors.pressure_noise_MPa", [](C c) { c.sensors.pressure_noise_mpa = -0.001; }},
      {"sensors.pressure_noise_MPa", [](C c) { c.sensors.pressure_noise_mpa = kNaN; }},
      {"sensors.pressure_bias_MPa", [](C c) { c.sensors.pressure_bias_mpa = 1.5; }},
      {"sensors.pressure_bias_MPa", [](C c) { c.sensors.pressure_bias_mpa = kNaN; }},
      {"sensors.pressure_adc_bits", [](C c) { c.sensors.pressure_adc_bits = -1; }},
      {"sensors.pressure_adc_bits", [](C c) { c.sensors.pressure_adc_bits = 2; }},
      {"sensors.pressure_adc_bits", [](C c) { c.sensors.pressure_adc_bits = 32; }},
      {"sensors.pressure_adc_min_V", [](C c) { c.sensors.pressure_adc_min_v = kNaN; }},
      {"sensors.pressure_adc_max_V", [](C c) { c.sensors.pressure_adc_max_v = -1.0; }},
      {"sensors.pressure_adc_max_V", [](C c) { c.sensors.pressure_adc_max_v = kNaN; }},
      {"sensors.pressure_lowpass_hz", [](C c) { c.sensors.pressure_lowpass_hz = -5.0; }},
      {"sensors.pressure_lowpass_hz", [](C c) { c.sensors.pressure_lowpass_hz = 51.0; }},
      {"sensors.pressure_lowpass_hz", [](C c) { c.sensors.pressure_lowpass_hz = kNaN; }},
      {"sensors.gauge_noise_V", [](C c) { c.sensors.gauge_noise_v = -1e-3; }},
      {"sensors.gauge_noise_V", [](C c) { c.sensors.gauge_noise_v = kNaN; }},
      {"sensors.gauge_adc_bits", [](C c) { c.sensors.gauge_adc_bits = 3; }},
      {"sensors.gauge_adc_bits", [](C c) { c.sensors.gauge_adc_bits = 25; }},
      {"sensors.gauge_adc_min_V", [](C c) { c.sensors.gauge_adc_min_v = kNaN; }},
      {"sensors.gauge_adc_max_V", [](C c) { c.sensors.gauge_adc_max_v = -5.0; }},
      {"sensors.gauge_adc_max_V", [](C c) { c.sensors.gauge_adc_max_v = kNaN; }},
      {"sensors.fiber_noise_mm_s", [](C c) { c.sensors.fiber_noise_mm_s = -2.0; }},
      {"sensors.fiber_noise_mm_s", [](C c) { c.sensors.fiber_noise_mm_s = kNaN; }},
      {"controller.p_max_MPa", [](C c) { c.p_max_pa = 0.0; }},
      {"controller.p_max_MPa", [](C c) { c.p_max_pa = kNaN; }},
      {"controller.p_tp_ago_MPa", [](C c) { c.p_tp_pa[kAgonist] = -0.1e6; }},
      {"controller.p_tp_ago_MPa", [](C c) { c.p_tp_pa[kAgonist] = 0.9e6; }},
      {"controller.p_tp_ago_MPa", [](C c) { c.p_tp_pa[kAgonist] = kNaN; }},
      {"controller.p_tp_anta_MPa", [](C c) { c.p_tp_pa[kAntagonist] = 1.0e6; }},
      {"controller.p_tp_anta_MPa", [](C c) { c.p_tp_pa[kAntagonist] = kNaN; }},
      {"pams.agonist.strain_gauge.q_V_per_N", [](C c) { c.gauge[kAgonist].q_v_per_n = 0.0; }},
      {"pams.agonist.strain_gauge.q_V_per_N", [](C c) { c.gauge[kAgonist].q_v_per_n = kNaN; }},
      {"pams.antagonist.strain_gauge.q_V_per_N",
       [](C c) { c.gauge[kAntagonist].q_v_per_n = -4.33e-3; }},
      {"pams.agonist.strain_gauge.V_base_V", [](C c) { c.gauge[kAgonist].v_base_v = kNaN; }},
      {"pams.antagonist.strain_gauge.V_base_V",
       [](C c) { c.gauge[kAntagonist].v_base_v = INFINITY; }},
      {"pams.agonist.spring.m", [](C c) { c.spring[kAgonist].m_m_per_pa = kNaN; }},
      {"pams.antagonist.spring.h", [](C c) { c.spring[kAntagonist].h_m = -0.1; }},
      {"pams.agonist.spring.a3", [](C c) { c.spring[kAgonist].coef[3] = kNaN; }},
  };
}

TEST(ReflexControllerConfig, DefaultsAreValid) {
  EXPECT_NO_THROW(validate(table_iv_reflex_controller_config()));
  ReflexControllerConfig fiber = table_iv_reflex_controller_config();
  fiber.reflex = table_ii_reflex_config(ReflexSensor::kFiber);
  EXPECT_NO_THROW(validate(fiber));
}

TEST(ReflexControllerConfig, EveryBadValueThrowsNamingTheKey) {
  for (const BadValue& bad : bad_values()) {
    ReflexControllerConfig config = table_iv_reflex_controller_config();
    bad.set(config);
    try {
      validate(config);
      ADD_FAILURE() << "no throw for " << bad.key;
    } catch (const InputError& e) {
      const std::string what = e.what();
      EXPECT_EQ(what.rfind(bad.key + " must be ", 0), 0u) << bad.key << ": " << what;
      EXPECT_NE(what.find(", got "), std::string::npos) << what;
    }
    // the constructor validates too
    EXPECT_THROW(ReflexController{config}, InputError) << bad.key;
  }
}

TEST(ReflexControllerConfig, MessageQuotesTheValue) {
  ReflexControllerConfig config = table_iv_reflex_controller_config();
  config.reflex.v_thr_mm_s = -5.0;
  try {
    validate(config);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(), "reflex.v_thr_mm_s must be > 0, got -5");
  }
}

TEST(ReflexControllerConfig, UnsetMusclesAreRejected) {
  ReflexControllerConfig config;   // no set_muscles()
  EXPECT_THROW(validate(config), InputError);
}

TEST(ReflexControllerConfig, SetMusclesNeedsAStrainGauge) {
  ReflexControllerConfig config;
  PamParams ago;
  ago.name = "agonist";
  ago.spring = table_iv_reflex_controller_config().spring[kAgonist];
  ago.strain_gauge = StrainGaugeParams{2.25e-3, 0.0};
  PamParams anta = ago;
  anta.name = "antagonist";
  anta.strain_gauge.reset();
  try {
    set_muscles(&config, ago, anta);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("pams.antagonist"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("strain_gauge"), std::string::npos) << e.what();
  }
  anta.strain_gauge = StrainGaugeParams{4.33e-3, 0.1};
  set_muscles(&config, ago, anta);
  EXPECT_DOUBLE_EQ(config.gauge[kAntagonist].v_base_v, 0.1);
}

TEST(ReflexSensor, ParsesAndRejectsNamingTheKey) {
  EXPECT_EQ(parse_reflex_sensor("model"), ReflexSensor::kModel);
  EXPECT_EQ(parse_reflex_sensor("fiber"), ReflexSensor::kFiber);
  for (const char* bad : {"fibre", "", "Model"}) {
    try {
      parse_reflex_sensor(bad);
      ADD_FAILURE() << "no throw for " << bad;
    } catch (const InputError& e) {
      EXPECT_EQ(std::string(e.what()).rfind("reflex.sensor must be ", 0), 0u) << e.what();
    }
  }
  EXPECT_THROW(parse_reflex_mode("Follow"), InputError);
}

}  // namespace
}  // namespace pamsim
