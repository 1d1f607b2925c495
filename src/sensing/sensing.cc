// sensing.cc: configuration checks and the per-tick sensor -> estimate pipeline.
#include "sensing/sensing.h"

#include <array>
#include <cmath>
#include <optional>
#include <utility>

#include "base/input_error.h"
#include "pam_actuator/pam_params.h"
#include "sensing/checks.h"
#include "sensing/instrument_kinds.h"
#include "sensing/sensor_keys.h"

namespace pamsim {
namespace {

using namespace checks;

// a muscle's estimator as the embedded controller holds it: its law, its gauge's Eq. (8)
// (calibrated), the PSE540's line, and the ADCs' ranges as the sensors' output ranges
pamctl_muscle_config embedded_estimator(const MuscleSensorSpec& muscle,
                                        const StrainGaugeParams& gauge, const SensorConfig& s) {
  pamctl_muscle_config estimator = embedded_muscle(muscle.estimator, gauge);
  estimator.pressure_zero_v = kPse540ZeroV;
  estimator.pressure_v_per_mpa = kPse540VoltPerMPa;
  estimator.pressure_min_v = s.pressure_adc_min_v;
  estimator.pressure_max_v = s.pressure_adc_max_v;
  estimator.gauge_min_v = s.gauge_adc_min_v;
  estimator.gauge_max_v = s.gauge_adc_max_v;
  return estimator;
}

// the generators' tags (sensor_noise.h): one per source, never reused
enum Stream : std::uint32_t { kPressureInstrument = 1, kPressureTrial = 2 };

// muscle `index`'s pressure sensor as hardware, if on: its offset and gain drawn from
// sensors.instrument_seed, its drift from the trial's seed
std::optional<PressureHardware> pressure_hardware(const SensorConfig& s, std::uint64_t seed,
                                                  std::uint32_t index, double dt_s) {
  if (!s.pressure_hardware.enabled) return std::nullopt;
  std::mt19937_64 instrument =
      derived_generator(s.gauge_hardware.instrument_seed, kPressureInstrument, index);
  return PressureHardware(s.pressure_hardware, instrument,
                          derived_generator(seed, kPressureTrial, index), dt_s);
}

std::optional<FiberHardware> fiber_hardware(const SensorConfig& s, double dt_s) {
  if (!s.fiber_hardware.enabled) return std::nullopt;
  return FiberHardware(s.fiber_hardware, dt_s);
}

}  // namespace

void validate(const SensingConfig& config) {
  // control rate first: the cutoffs are checked against it
  require_positive("sim.control_hz", config.control_hz);
  const SensorConfig& s = config.sensors;
  SensorConfig fields = s;  // each key's own range (sensor_keys.h), then what joins keys
  check_key_rows(sensor_key_table(&fields));
  require_adc("sensors.pressure_adc", s.pressure_adc_bits, s.pressure_adc_min_v,
              s.pressure_adc_max_v);
  require_cutoff("sensors.pressure_lowpass_hz", s.pressure_lowpass_hz, config.control_hz);
  require_adc("sensors.gauge_adc", s.gauge_adc_bits, s.gauge_adc_min_v, s.gauge_adc_max_v);
  require_cutoff("reflex.lowpass_hz", config.velocity_lowpass_hz, config.control_hz);
  for (const InstrumentKind& kind : instrument_kinds()) kind.validate(s);
  validate_calibration_length(s.gauge_hardware, config.control_hz);
}

void validate(const MuscleSensorSpec& muscle) {
  // the gauge's slope and offset and a finite estimator law: the parameter file's own rows
  validate_pam_params(muscle.estimator, muscle.gauge, muscle.key);
}

SensorSuite::SensorSuite(const SensingConfig& config, const std::vector<MuscleSensorSpec>& muscles,
                         std::uint64_t seed)
    : rng_(seed) {
  validate(config);
  const double dt_s = 1.0 / config.control_hz;
  dt_s_ = dt_s;
  pressure_alpha_ = lowpass_alpha(config.sensors.pressure_lowpass_hz, dt_s);
  velocity_alpha_ = lowpass_alpha(config.velocity_lowpass_hz, dt_s);
  const GaugeHardwareConfig& hardware = config.sensors.gauge_hardware;
  // the built instruments: the same for every trial of a scenario, whatever its seed
  std::mt19937_64 instruments(hardware.instrument_seed);
  channels_.reserve(muscles.size());
  for (const MuscleSensorSpec& muscle : muscles) {
    validate(muscle);
    const auto index = static_cast<std::uint32_t>(channels_.size());
    // the estimator's Eq. (8): the published constants, or this gauge's calibration
    std::optional<GaugeHardware> gauge;
    StrainGaugeParams calibrated = muscle.gauge;
    if (hardware.enabled) {
      GaugeHardwareConfig own = hardware;  // with this muscle's contact, where it has one
      if (muscle.contact) own.contact = *muscle.contact;
      gauge.emplace(own, muscle.gauge, instruments, dt_s);
      calibrated = calibrate_gauge(*gauge, own, dt_s, muscle.key);
      gauge->reseat();  // the line re-laid after the calibration, as the lab's may be
    }
    channels_.push_back(Channel{
        PressureSensor(config.sensors, pressure_hardware(config.sensors, seed, index, dt_s)),
        StrainGauge(muscle.gauge, config.sensors, std::move(gauge)),
        FiberSensor(config.sensors, dt_s, fiber_hardware(config.sensors, dt_s)),
        embedded_estimator(muscle, calibrated, config.sensors), pamctl_muscle_state{}});
    pamctl_muscle_init(&channels_.back().state, pressure_alpha_, velocity_alpha_);
    channels_.back().gauge.enable_vibration(config.physics_dt_s);
    observes_forces_ = observes_forces_ || channels_.back().gauge.vibrates();
  }
}

pamctl_config SensorSuite::embedded_config() const {
  if (channels_.size() > PAMCTL_MAX_MUSCLES) {
    throw InputError("the embedded controller holds at most " + std::to_string(PAMCTL_MAX_MUSCLES) +
                     " muscles, the model has " + std::to_string(channels_.size()));
  }
  pamctl_config config{};
  config.muscle_count = static_cast<std::int32_t>(channels_.size());
  config.control_period_s = dt_s_;
  config.pressure_alpha = pressure_alpha_;
  config.velocity_alpha = velocity_alpha_;
  for (std::size_t j = 0; j < channels_.size(); ++j) {
    config.muscles[j] = channels_[j].estimator;
    config.partner[j] = -1;
  }
  return config;
}

void SensorSuite::observe(const std::vector<double>& force_n) {
  for (std::size_t j = 0; j < channels_.size(); ++j) channels_[j].gauge.observe(force_n[j]);
}

void SensorSuite::sample(const std::vector<MuscleTruth>& truth,
                         std::vector<MuscleReading>* readings) {
  for (std::size_t j = 0; j < channels_.size(); ++j) {
    Channel& ch = channels_[j];
    MuscleReading& r = (*readings)[j];

    // sensors, in a fixed order: pressure, gauge, fiber
    const PressureReading pressure = ch.pressure.sample(truth[j].pressure_pa, rng_);
    ch.gauge.follow(truth[j].length_m, truth[j].force_n);
    r.gauge_v = ch.gauge.sample(truth[j].force_n, rng_);
    r.fiber_rate_m_s = ch.fiber.sample(truth[j].length_m, rng_);
    r.pressure_sensor_v = pressure.voltage_v;
    r.fiber_length_m = ch.fiber.length_m();

    // the embedded controller's estimate from the raw readings, Eq. (9)-(11), and the
    // fiber's low-passed rate
    pamctl_estimate est{};
    pamctl_estimate_muscle(&ch.estimator, dt_s_, &ch.state, r.pressure_sensor_v, r.gauge_v,
                           r.fiber_rate_m_s, &est);
    r.pressure_meas_pa = est.pressure_pa;
    r.force_meas_n = est.force_n;
    r.length_est_m = est.length_m;
    r.velocity_est_m_s = est.velocity_m_s;
    r.fiber_velocity_m_s = est.fiber_velocity_m_s;
  }
}

}  // namespace pamsim
