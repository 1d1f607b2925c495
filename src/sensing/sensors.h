// sensors.h: the arm's sensors as the controller samples them at the control rate
// (paper Sec. III-C/D): the SMC PSE540 pressure sensor, the strain gauge on a quarter
// bridge (Eq. (8)), the conductive-fiber sensor of Hitzmann et al. (rate of length change),
// and the linear encoder (ground truth: PlantSample's length, used only to calibrate the
// fiber sensor at the start and logged by the simulation).
// Each may be built as hardware, off by default (the errors of a real instrument, sized from
// its datasheet or the literature, each file says which): the gauge (gauge_hardware.h),
// the pressure sensor (pressure_hardware.h), the fiber sensor (fiber_hardware.h) and the
// encoder's resolution (EncoderConfig below). Their random draws come from generators of
// their own (sensor_noise.h), so the noise stream (PressureSensor) is the same with them on
// or off.
#pragma once

#include <optional>
#include <random>

#include "pam_actuator/pam_params.h"
#include "sensing/fiber_hardware.h"
#include "sensing/gauge_hardware.h"
#include "sensing/pressure_hardware.h"
#include "sensing/sensor_noise.h"

namespace pamsim {

// The linear encoder (Yoshida and Hosoda, Sec. III-A: a MUTOH DS-025) as counts of
// `resolution_m`: it reads round(l / resolution) resolution (sensor_noise.h's quantise). Keys
// sensors.encoder.model ("ideal" | "counts") and sensors.encoder.resolution_mm (> 0). The
// DS-025's resolution could not be retrieved: 0.01 mm is an ASSUMPTION, the usual count of
// digital-scale linear encoders of its class (docs/physics.md, departures). Where pamsim uses
// the encoder's reading: the fiber sensor's calibration at its first sample (FiberSensor);
// the logged length_<m>_mm stays the plant's true length.
struct EncoderConfig {
  bool enabled = false;
  double resolution_m = 1e-5;
};
double encoder_read_m(const EncoderConfig& encoder, double length_m);

// Defaults (SensorConfig) and why:
//  - sensors.pressure_noise_MPa = 0.001 (1 kPa, 0.1 % F.S.) random noise per sample. The PSE540's
//    +/-2 % F.S. accuracy is a slowly varying offset, not sample-to-sample noise: it is the
//    separate sensors.pressure_bias_MPa (default 0; a bias shifts the length estimate by about
//    66 mm/MPa at the operating point but cancels in the velocity, Eq. (11)), or, drawn per
//    instrument with its gain error, hysteresis, response and drift, sensors.pressure.*
//    (pressure_hardware.h). Its repeatability
//    is +/-0.2 % F.S., so random noise of half that is a realistic level.
//  - pressure ADC: 12 bit over 0-5 V (a microcontroller or DAQ input): 1.22 mV = 0.31 kPa
//    per step, well below the noise.
//  - gauge_noise_v = 0.5 mV: 0.22 N on the agonist (q = 2.25e-3 V/N) and 0.12 N on the
//    antagonist (q = 4.33e-3 V/N), the 0.2 N level of the prototype below.
//  - gauge ADC: 16 bit over -5..+5 V (a bridge amplifier into a bipolar DAQ input, so noise
//    around V_base is not clipped): 0.15 mV = 0.07 N per step on the agonist.
//  - sensors.fiber_noise_mm_s = 2 on the rate: the fiber reflex threshold of Table II (25 mm/s)
//    is 12 standard deviations away, and the integrated length drifts only ~0.6 mm over 10 s.
// With these defaults (no pressure low-pass), the velocity estimate at 100 Hz has a standard
// deviation of about 9 mm/s (drop_mass.toml's quiet second: 9.6 mm/s agonist, 8.4 mm/s
// antagonist, largest 32 mm/s), 7 sigma below the model reflex threshold (70 mm/s): no
// mistrip (a prototype of the falling-mass arm measured ~1.5 % mistrips per quiet second at
// 0.002 MPa / 0.2 N, whose velocity noise is ~19 mm/s).
//
// The sensors' parameters, SI; their scenario keys sensors.* (paper units, named) are rows
// of sensor_keys.h. Checked by validate() in sensing.h.
struct SensorConfig {
  double pressure_noise_pa = 1000.0;  // std dev >= 0 [Pa], sensors.pressure_noise_MPa = 0.001
  double pressure_bias_pa = 0.0;      // constant offset [Pa], sensors.pressure_bias_MPa in (-1, 1)
  int pressure_adc_bits = 12;         // sensors.pressure_adc_bits, 0 (ideal) or 4..24
  double pressure_adc_min_v = 0.0;    // sensors.pressure_adc_min_V
  double pressure_adc_max_v = 5.0;    // sensors.pressure_adc_max_V, > min
  // sensors.pressure_lowpass_hz, 0 (off) or (0, Nyquist]. Default off. A low-pass on the
  // measured pressure removes noise mistrips (a prototype: 5 Hz removed all of them at
  // 0.003 MPa / 0.5 N of noise without delaying the trigger) but, in the closed loop, its lag
  // turns the reflex's own pressure rise into estimated stretch: the real force rises with
  // the real pressure while the estimate still inverts Eq. (3) at the older, lower one, so d
  // is overestimated; on the ideal plant (drop_mass_ideal.toml) a 5 Hz filter made the
  // velocity estimate read ~250 mm/s for a true ~96 mm/s stretch and the reflex pumped the
  // arm's ~5 Hz mode until the mass was thrown out. At the default noise (0.001 MPa) the
  // unfiltered velocity noise is ~9 mm/s, 7 sigma below the 70 mm/s threshold: no mistrips
  // without the filter (on the physical plant they begin at twice the default noise,
  // sensors.noise_scale = 2; docs/findings.md, sensor noise).
  double pressure_lowpass_hz = 0.0;
  double gauge_noise_v = 0.5e-3;   // sensors.gauge_noise_V, std dev, >= 0
  int gauge_adc_bits = 16;         // sensors.gauge_adc_bits, 0 (ideal) or 4..24
  double gauge_adc_min_v = -5.0;   // sensors.gauge_adc_min_V
  double gauge_adc_max_v = 5.0;    // sensors.gauge_adc_max_V, > min
  double fiber_noise_m_s = 0.002;  // std dev >= 0 [m/s], sensors.fiber_noise_mm_s = 2
  // sensors.noise_scale, in [0, 1000]: multiplies the three noise standard deviations above
  // (not the bias), one knob for a sweep over sensor noise; 1 leaves them as given.
  double noise_scale = 1.0;
  // sensors.gauge.* and sensors.instrument_seed: the gauge as hardware (gauge_hardware.h);
  // off by default (Eq. (8) exact, the published q and V_base)
  GaugeHardwareConfig gauge_hardware;
  // sensors.pressure.*, sensors.fiber.*, sensors.encoder.*: the other sensors as hardware,
  // each off by default
  PressureHardwareConfig pressure_hardware;
  FiberHardwareConfig fiber_hardware;
  EncoderConfig encoder;
};

// An analog-to-digital converter: saturates at [v_min, v_max] and rounds to the nearest of
// 2^bits levels spaced (v_max - v_min) / (2^bits - 1) apart, both ends included.
// bits = 0 is an ideal converter: saturation only.
struct AdcParams {
  int bits = 12;
  double v_min_v = 0.0;
  double v_max_v = 5.0;
};
double adc_step_v(const AdcParams& adc);  // 0 for an ideal converter
double adc_read(const AdcParams& adc, double v);

// PSE540 transfer: 1 V at 0 MPa to 5 V at 1 MPa (gauge), linear: V = 1 + 4 p / (1 MPa).
inline constexpr double kPse540ZeroV = 1.0;
inline constexpr double kPse540VoltPerMPa = 4.0;
double pse540_voltage(double p_pa);
// Its inverse, as the controller converts a reading: p = (V - 1) / 4 MPa.
double pse540_pressure_pa(double v);

struct PressureReading {
  double voltage_v = 0.0;    // after noise and ADC
  double pressure_pa = 0.0;  // pse540_pressure_pa(voltage_v)
};

// The sensors' noise (here and below) is drawn from a std::mt19937_64 the caller owns (the
// SensorSuite seeds one per trial from the trial seed), so a trial is deterministic. Every
// sample() call draws exactly one standard normal even when its noise level is 0, so the
// random stream, and therefore the noise of the other sensors, does not depend on which noise
// levels a sweep sets to 0.
//
// Reading = ADC(PSE540(p + bias + noise)), noise ~ N(0, pressure_noise_pa^2); with its
// hardware (pressure_hardware.h), ADC(PSE540(round(hw(p) + bias + noise))).
class PressureSensor {
 public:
  explicit PressureSensor(const SensorConfig& config,
                          std::optional<PressureHardware> hardware = std::nullopt);
  PressureReading sample(double p_true_pa, std::mt19937_64& rng);

 private:
  double noise_pa_;
  double bias_pa_;
  AdcParams adc_;
  std::optional<PressureHardware> hardware_;
};

// Strain gauge on a quarter bridge, Eq. (8): V = q f + V_base, or, given its hardware
// (gauge_hardware.h), what that gauge reads; plus N(0, gauge_noise_v^2), then the ADC. The
// gauge sees tension only: a slack line (f = 0) reads V_base (+ noise), or with the hardware
// the gauge's own zero (its bridge offset, near the calibrated V_base).
class StrainGauge {
 public:
  StrainGauge(const StrainGaugeParams& gauge, const SensorConfig& config,
              std::optional<GaugeHardware> hardware = std::nullopt);
  double sample(double f_true_n, std::mt19937_64& rng);  // [V]
  // The board's ringing (gauge_hardware.h): on, then fed the pull at every physics step.
  void enable_vibration(double physics_dt_s);
  bool vibrates() const { return hardware_ && hardware_->vibrates(); }
  void observe(double f_true_n);
  // Each tick before sample(): where the line bears on the board (gauge_contact.h).
  void follow(double length_m, double f_true_n);

 private:
  StrainGaugeParams gauge_;
  double noise_v_;
  AdcParams adc_;
  std::optional<GaugeHardware> hardware_;
};

// Conductive-fiber sensor: measures the rate of change of length. Modelled as the true mean
// velocity over the last sample period, (l_j - l_{j-1}) / dt from the encoder (PlantSample
// carries no velocity), plus N(0, fiber_noise_m_s^2); 0 + noise at the first sample. Its
// absolute length is the rate integrated from the encoder reading at the first sample, as
// the paper calibrated it (Sec. IV-C): l_j = l_{j-1} + rate_j dt, so Eq. (11) applied to
// that length gives back the rate. With its hardware (fiber_hardware.h) the rate is that of
// the fabric's reading of the displacement from the first sample's length; with the encoder
// as counts (EncoderConfig) the calibration is the encoder's count, not the true length.
class FiberSensor {
 public:
  FiberSensor(const SensorConfig& config, double sample_period_s,
              std::optional<FiberHardware> hardware = std::nullopt);
  // One sample; encoder_length_m is the true length at this tick.
  double sample(double encoder_length_m, std::mt19937_64& rng);  // rate [m/s]
  double length_m() const { return length_m_; }                  // integrated [m]

 private:
  double noise_m_s_;
  double dt_s_;
  EncoderConfig encoder_;
  std::optional<FiberHardware> hardware_;
  bool started_ = false;
  double start_m_ = 0.0;      // the true length at the first sample
  double last_read_m_ = 0.0;  // the length the fabric read at the last sample
  double length_m_ = 0.0;
};

}  // namespace pamsim
