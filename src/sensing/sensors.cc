// sensors.cc: pressure sensor, strain gauge, fiber sensor and ADC models.
#include "sensing/sensors.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <utility>

#include "base/units.h"

namespace pamsim {

double encoder_read_m(const EncoderConfig& encoder, double length_m) {
  return encoder.enabled ? quantise(length_m, encoder.resolution_m) : length_m;
}

double adc_step_v(const AdcParams& adc) {
  if (adc.bits == 0) return 0.0;
  const double levels = std::ldexp(1.0, adc.bits) - 1.0;
  return (adc.v_max_v - adc.v_min_v) / levels;
}

double adc_read(const AdcParams& adc, double v) {
  assert(adc.v_max_v > adc.v_min_v);
  // saturate at the input range (NaN reads as the bottom of the range)
  if (!(v > adc.v_min_v)) return adc.v_min_v;
  if (v >= adc.v_max_v) return adc.v_max_v;
  if (adc.bits == 0) return v;
  // round to the nearest code
  return std::min(adc.v_min_v + quantise(v - adc.v_min_v, adc_step_v(adc)), adc.v_max_v);
}

double pse540_voltage(double p_pa) {
  return kPse540ZeroV + kPse540VoltPerMPa * units::pa_to_mpa(p_pa);
}

double pse540_pressure_pa(double v) {
  return units::mpa_to_pa((v - kPse540ZeroV) / kPse540VoltPerMPa);
}

PressureSensor::PressureSensor(const SensorConfig& config, std::optional<PressureHardware> hardware)
    : noise_pa_(config.noise_scale * config.pressure_noise_pa),
      bias_pa_(config.pressure_bias_pa),
      adc_{config.pressure_adc_bits, config.pressure_adc_min_v, config.pressure_adc_max_v},
      hardware_(std::move(hardware)) {}

PressureReading PressureSensor::sample(double p_true_pa, std::mt19937_64& rng) {
  // sensed pressure: truth (or what the hardware makes of it) + bias + random noise
  const double p_in = hardware_ ? hardware_->sensed_pa(p_true_pa) : p_true_pa;
  double p_sensed = p_in + bias_pa_ + noise_pa_ * standard_normal(rng);
  if (hardware_) p_sensed = hardware_->rounded_pa(p_sensed);
  // analog output, then the ADC (saturating at its range)
  PressureReading reading;
  reading.voltage_v = adc_read(adc_, pse540_voltage(p_sensed));
  reading.pressure_pa = pse540_pressure_pa(reading.voltage_v);
  return reading;
}

StrainGauge::StrainGauge(const StrainGaugeParams& gauge, const SensorConfig& config,
                         std::optional<GaugeHardware> hardware)
    : gauge_(gauge),
      noise_v_(config.noise_scale * config.gauge_noise_v),
      adc_{config.gauge_adc_bits, config.gauge_adc_min_v, config.gauge_adc_max_v},
      hardware_(std::move(hardware)) {}

double StrainGauge::sample(double f_true_n, std::mt19937_64& rng) {
  // the gauge sees tension only; a slack line reads V_base, Eq. (8)
  const double f = std::max(f_true_n, 0.0);
  const double clean = hardware_ ? hardware_->voltage(f) : gauge_.q_v_per_n * f + gauge_.v_base_v;
  return adc_read(adc_, clean + noise_v_ * standard_normal(rng));
}

void StrainGauge::enable_vibration(double physics_dt_s) {
  if (hardware_) hardware_->enable_vibration(physics_dt_s);
}

void StrainGauge::observe(double f_true_n) {
  if (hardware_) hardware_->observe(std::max(f_true_n, 0.0));
}

void StrainGauge::follow(double length_m, double f_true_n) {
  if (hardware_) hardware_->follow(length_m, f_true_n);
}

FiberSensor::FiberSensor(const SensorConfig& config, double sample_period_s,
                         std::optional<FiberHardware> hardware)
    : noise_m_s_(config.noise_scale * config.fiber_noise_m_s),
      dt_s_(sample_period_s),
      encoder_(config.encoder),
      hardware_(std::move(hardware)) {
  assert(sample_period_s > 0.0);
}

double FiberSensor::sample(double encoder_length_m, std::mt19937_64& rng) {
  const double noise = noise_m_s_ * standard_normal(rng);
  if (!started_) start_m_ = encoder_length_m;
  // the length the fabric reads: the truth, or its reading of the displacement since start
  const double read_m =
      hardware_ ? start_m_ + hardware_->reading_m(encoder_length_m - start_m_) : encoder_length_m;
  // first sample: calibrate the absolute length to the encoder
  if (!started_) {
    started_ = true;
    last_read_m_ = read_m;
    length_m_ = encoder_read_m(encoder_, encoder_length_m);
    return noise;
  }
  // mean rate of the reading over the last period, plus noise, integrated to a length
  const double rate = (read_m - last_read_m_) / dt_s_ + noise;
  last_read_m_ = read_m;
  length_m_ += rate * dt_s_;
  return rate;
}

}  // namespace pamsim
