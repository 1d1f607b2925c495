// sensor_keys.cc: the rows of sensors.* (see sensor_keys.h).
#include "sensing/sensor_keys.h"

#include <cstdint>
#include <limits>

#include "base/units.h"

namespace pamsim {

KeyTable sensor_key_table(SensorConfig* sensors) {
  SensorConfig& s = *sensors;
  constexpr double inf = std::numeric_limits<double>::infinity();
  const KeyRange non_negative{0.0, inf, false, true};
  const KeyRange any{-inf, inf, true, true};
  KeyTable t{"sensors", {}, {}, {}};
  t.trial_only = true;  // the instruments are the trial's, not the model's
  // a bit count within an int; validate() allows 0 (no ADC) or 4..24
  t.ints = {
      int_row("pressure_adc_bits", "the pressure ADC's resolution (0: ideal, else 4 to 24)", 0, 64,
              &s.pressure_adc_bits),
      int_row("gauge_adc_bits", "the gauge ADC's resolution (0: ideal, else 4 to 24)", 0, 64,
              &s.gauge_adc_bits),
      int_row("instrument_seed",
              "which built instruments (bridge arms, pressure sensors' offsets and gains): "
              "fixed across trials",
              0, std::numeric_limits<std::int64_t>::max(), &s.gauge_hardware.instrument_seed)};
  t.numbers = {
      {"pressure_noise_MPa", "MPa", units::kPaPerMPa, non_negative, "pressure sensor noise SD",
       &s.pressure_noise_pa},
      {"pressure_bias_MPa",
       "MPa",
       units::kPaPerMPa,
       {-1.0, 1.0, true, true},
       "pressure sensor offset",
       &s.pressure_bias_pa},
      {"pressure_adc_min_V", "V", 1.0, any, "the pressure ADC's range, low end",
       &s.pressure_adc_min_v},
      {"pressure_adc_max_V", "V", 1.0, any,
       "the pressure ADC's range, high end (above the low end)", &s.pressure_adc_max_v},
      {"pressure_lowpass_hz", "Hz", 1.0, non_negative,
       "low-pass on the measured pressure (0: off; at most sim.control_hz / 2)",
       &s.pressure_lowpass_hz},
      {"gauge_noise_V", "V", 1.0, non_negative, "strain gauge noise SD", &s.gauge_noise_v},
      {"gauge_adc_min_V", "V", 1.0, any, "the gauge ADC's range, low end", &s.gauge_adc_min_v},
      {"gauge_adc_max_V", "V", 1.0, any, "the gauge ADC's range, high end (above the low end)",
       &s.gauge_adc_max_v},
      {"fiber_noise_mm_s", "mm/s", units::kMPerMm, non_negative, "fiber sensor noise SD",
       &s.fiber_noise_m_s},
      {"noise_scale",
       "",
       1.0,
       {0.0, 1000.0, false, false},
       "multiplies the three noise SDs (a sweep's one knob)",
       &s.noise_scale}};
  return t;
}

}  // namespace pamsim
