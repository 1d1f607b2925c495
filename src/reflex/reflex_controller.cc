// reflex_controller.cc: configuration checks and the per-tick pipeline
// sensors -> estimate -> reflex -> Eq. (12)-(13).
#include "reflex/reflex_controller.h"

#include <cmath>
#include <limits>
#include <sstream>

#include "pam_actuator/input_error.h"
#include "pam_actuator/units.h"

namespace pamsim {

namespace {

constexpr const char* kMuscleKey[kMuscleCount] = {"agonist", "antagonist"};

std::string format_value(double value) {
  std::ostringstream os;
  os.precision(10);
  os << value;
  return os.str();
}

[[noreturn]] void fail(const std::string& key, const std::string& allowed, double value) {
  throw InputError(key + " must be " + allowed + ", got " + format_value(value));
}

void require_finite(const std::string& key, double value) {
  if (!std::isfinite(value)) fail(key, "finite", value);
}

void require_positive(const std::string& key, double value) {
  if (!(std::isfinite(value) && value > 0.0)) fail(key, "> 0", value);
}

void require_non_negative(const std::string& key, double value) {
  if (!(std::isfinite(value) && value >= 0.0)) fail(key, ">= 0", value);
}

// a low-pass cutoff: 0 (off) or up to the Nyquist frequency of the control rate
void require_cutoff(const std::string& key, double value, double control_hz) {
  const double nyquist = 0.5 * control_hz;
  if (!(std::isfinite(value) && value >= 0.0 && value <= nyquist)) {
    fail(key, "0 (off) or in (0, " + format_value(nyquist) + "] Hz (sim.control_hz / 2)",
         value);
  }
}

void require_adc(const std::string& prefix, int bits, double v_min, double v_max) {
  if (!(bits == 0 || (bits >= 4 && bits <= 24))) {
    fail(prefix + "_bits", "0 (ideal) or in [4, 24]", bits);
  }
  require_finite(prefix + "_min_V", v_min);
  require_finite(prefix + "_max_V", v_max);
  if (!(v_max > v_min)) fail(prefix + "_max_V", "> " + prefix + "_min_V = " +
                                 format_value(v_min), v_max);
}

const ReflexControllerConfig& validated(const ReflexControllerConfig& config) {
  validate(config);
  return config;
}

LengthEstimatorParams estimator_params(const ReflexControllerConfig& config) {
  LengthEstimatorParams params;
  params.pressure_lowpass_hz = config.sensors.pressure_lowpass_hz;
  params.velocity_lowpass_hz = config.reflex.lowpass_hz;
  return params;
}

}  // namespace

const char* to_string(ReflexSensor sensor) {
  switch (sensor) {
    case ReflexSensor::kModel:
      return "model";
    case ReflexSensor::kFiber:
      return "fiber";
  }
  return "?";
}

ReflexSensor parse_reflex_sensor(const std::string& name) {
  if (name == "model") return ReflexSensor::kModel;
  if (name == "fiber") return ReflexSensor::kFiber;
  throw InputError("reflex.sensor must be \"model\" or \"fiber\", got \"" + name + "\"");
}

ReflexConfig table_ii_reflex_config(ReflexSensor sensor) {
  ReflexConfig reflex;
  reflex.sensor = sensor;
  if (sensor == ReflexSensor::kFiber) {
    reflex.v_thr_mm_s = 25.0;
    reflex.k_MPa_s_per_mm = 1.0 / 300.0;
  } else {
    reflex.v_thr_mm_s = 70.0;
    reflex.k_MPa_s_per_mm = 1.0 / 800.0;
  }
  return reflex;
}

void set_muscles(ReflexControllerConfig* config, const PamParams& agonist,
                 const PamParams& antagonist) {
  const PamParams* pams[kMuscleCount] = {&agonist, &antagonist};
  for (int j = 0; j < kMuscleCount; ++j) {
    if (!pams[j]->strain_gauge) {
      throw InputError(std::string("pams.") + kMuscleKey[j] + " (" + pams[j]->name +
                       "): strain_gauge.q_V_per_N must be given for the reflex controller " +
                       "(Eq. (8)), got no [strain_gauge] table");
    }
    config->spring[j] = pams[j]->spring;
    config->gauge[j] = *pams[j]->strain_gauge;
  }
}

ReflexControllerConfig table_iv_reflex_controller_config() {
  // Table IV of seeds/000: m [mm/MPa], h [mm], a0..a3 (f [N], p [MPa], d [mm]), q [V/N]
  ReflexControllerConfig config;
  config.spring[kAgonist] = spring_model_from_paper_units(SpringLaw::kEq3, -60.1, 170.1,
                                                          {0.911, 0.256, 7.00, -0.201, 0, 0});
  config.spring[kAntagonist] = spring_model_from_paper_units(SpringLaw::kEq3, -70.3, 178.5,
                                                             {22.4, -0.129, 1.24, 0.871, 0, 0});
  config.gauge[kAgonist] = StrainGaugeParams{2.25e-3, 0.0};
  config.gauge[kAntagonist] = StrainGaugeParams{4.33e-3, 0.0};
  return config;
}

void validate(const ReflexControllerConfig& config) {
  // control rate first: the cutoffs and the window are checked against it
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
  require_cutoff("reflex.lowpass_hz", reflex.lowpass_hz, config.control_hz);
  require_non_negative("reflex.refractory_s", reflex.refractory_s);
  require_non_negative("reflex.arm_after_s", reflex.arm_after_s);
  require_non_negative("reflex.min_tension_N", reflex.min_tension_n);

  // sensors.*
  const SensorConfig& s = config.sensors;
  require_non_negative("sensors.pressure_noise_MPa", s.pressure_noise_mpa);
  if (!(std::isfinite(s.pressure_bias_mpa) && std::abs(s.pressure_bias_mpa) < 1.0)) {
    fail("sensors.pressure_bias_MPa", "finite and within (-1, 1) MPa (the sensor's span)",
         s.pressure_bias_mpa);
  }
  require_adc("sensors.pressure_adc", s.pressure_adc_bits, s.pressure_adc_min_v,
              s.pressure_adc_max_v);
  require_cutoff("sensors.pressure_lowpass_hz", s.pressure_lowpass_hz, config.control_hz);
  require_non_negative("sensors.gauge_noise_V", s.gauge_noise_v);
  require_adc("sensors.gauge_adc", s.gauge_adc_bits, s.gauge_adc_min_v, s.gauge_adc_max_v);
  require_non_negative("sensors.fiber_noise_mm_s", s.fiber_noise_mm_s);

  // top controller and valve range, in MPa as in the scenario file
  const double p_max_mpa = units::pa_to_mpa(config.p_max_pa);
  require_positive("controller.p_max_MPa", p_max_mpa);
  const char* p_tp_key[kMuscleCount] = {"controller.p_tp_ago_MPa", "controller.p_tp_anta_MPa"};
  for (int j = 0; j < kMuscleCount; ++j) {
    const double p_tp_mpa = units::pa_to_mpa(config.p_tp_pa[j]);
    if (!(std::isfinite(p_tp_mpa) && p_tp_mpa >= 0.0 && p_tp_mpa <= p_max_mpa)) {
      fail(p_tp_key[j], "in [0, controller.p_max_MPa = " + format_value(p_max_mpa) + "]",
           p_tp_mpa);
    }
  }

  // the muscles: gauge slope and offset, finite spring coefficients
  for (int j = 0; j < kMuscleCount; ++j) {
    const std::string pam = std::string("pams.") + kMuscleKey[j];
    require_positive(pam + ".strain_gauge.q_V_per_N", config.gauge[j].q_v_per_n);
    require_finite(pam + ".strain_gauge.V_base_V", config.gauge[j].v_base_v);
    double m_mm_per_mpa = 0.0;
    double h_mm = 0.0;
    std::array<double, 6> coef{};
    spring_model_to_paper_units(config.spring[j], &m_mm_per_mpa, &h_mm, &coef);
    require_finite(pam + ".spring.m", m_mm_per_mpa);
    require_positive(pam + ".spring.h", h_mm);
    for (int k = 0; k < coefficient_count(config.spring[j].law); ++k) {
      require_finite(pam + ".spring." + coefficient_name(config.spring[j].law, k), coef[k]);
    }
  }
}

ReflexController::ReflexController(const ReflexControllerConfig& config)
    : config_(validated(config)),
      dt_s_(1.0 / config.control_hz),
      rng_(config.seed),
      pressure_sensor_(config.sensors),
      gauges_{StrainGauge(config.gauge[kAgonist], config.sensors),
              StrainGauge(config.gauge[kAntagonist], config.sensors)},
      fibers_{FiberSensor(config.sensors, dt_s_), FiberSensor(config.sensors, dt_s_)},
      estimators_{LengthEstimator(config.spring[kAgonist], config.gauge[kAgonist],
                                  estimator_params(config), dt_s_),
                  LengthEstimator(config.spring[kAntagonist], config.gauge[kAntagonist],
                                  estimator_params(config), dt_s_)},
      fiber_velocity_filters_{LowpassFilter(config.reflex.lowpass_hz, dt_s_),
                              LowpassFilter(config.reflex.lowpass_hz, dt_s_)},
      reflexes_{StretchReflex(config.reflex, dt_s_), StretchReflex(config.reflex, dt_s_)} {}

ControlOutput ReflexController::update(const PlantSample& sample) {
  ControlOutput out;
  std::array<double, kMuscleCount> dp_pa{};
  // whose window was open at the previous tick (the same for both muscles' gates)
  const std::array<bool, kMuscleCount> was_active = {reflexes_[kAgonist].active(),
                                                     reflexes_[kAntagonist].active()};
  for (int j = 0; j < kMuscleCount; ++j) {
    const MuscleTruth& truth = sample.muscle[j];
    MuscleTelemetry& tel = out.telemetry[j];

    // sensors, in a fixed order: pressure, gauge, fiber
    const PressureReading pressure = pressure_sensor_.sample(truth.pressure_pa, rng_);
    tel.gauge_v = gauges_[j].sample(truth.force_n, rng_);
    tel.fiber_rate = fibers_[j].sample(truth.length_m, rng_);
    tel.pressure_sensor_v = pressure.voltage_v;
    tel.fiber_length_m = fibers_[j].length_m();

    // model-based estimate, Eq. (9)-(11)
    const LengthEstimate est = estimators_[j].update(pressure.pressure_pa, tel.gauge_v);
    tel.pressure_meas_pa = est.pressure_pa;
    tel.force_meas_n = est.force_n;
    tel.length_est_m = est.length_m;

    // the velocity the reflex sees
    const double fiber_v = fiber_velocity_filters_[j].step(tel.fiber_rate);
    tel.velocity_est_m_s =
        config_.reflex.sensor == ReflexSensor::kFiber ? fiber_v : est.velocity_m_s;

    // this muscle's reflex, Eq. (14)
    if (config_.reflex.enabled) {
      const bool loaded = est.force_n >= config_.reflex.min_tension_n;
      const bool other_quiet =
          !(config_.reflex.reciprocal_trigger_inhibition && was_active[1 - j]);
      dp_pa[j] = reflexes_[j].update(sample.time_s, tel.velocity_est_m_s, loaded && other_quiet);
      tel.reflex_active = reflexes_[j].active();
    }
  }

  // Eq. (12)-(13), clamped to the valve's range
  out.p_cmd_pa = reflex_commands(config_.p_tp_pa, dp_pa, config_.p_max_pa);
  return out;
}

int ReflexController::trigger_count(Muscle muscle) const {
  return reflexes_[muscle].trigger_count();
}

const std::vector<double>& ReflexController::trigger_times_s(Muscle muscle) const {
  return reflexes_[muscle].trigger_times_s();
}

double ReflexController::first_trigger_time_s() const {
  double first = std::numeric_limits<double>::quiet_NaN();
  for (const StretchReflex& reflex : reflexes_) {
    if (!reflex.trigger_times_s().empty()) {
      const double t = reflex.trigger_times_s().front();
      if (!(t >= first)) first = t;
    }
  }
  return first;
}

}  // namespace pamsim
