// scenario_sensors.cc: sensors.* (noise, ADCs, low-pass: the rows of sensing/sensor_keys.h)
// and the sensors as hardware:
// sensors.gauge.* and sensors.instrument_seed (sensing/gauge_hardware.h), sensors.pressure.*
// (sensing/pressure_hardware.h), sensors.fiber.* (sensing/fiber_hardware.h) and
// sensors.encoder.* (sensing/sensors.h). Validated with the sensing (sensing/sensing.h).
#include <cstdint>
#include <string>
#include <vector>

#include "base/enum_names.h"
#include "base/key_table.h"
#include "base/units.h"
#include "sensing/sensor_keys.h"
#include "sim/scenario/scenario_reading.h"

namespace pamsim {
namespace {

constexpr EnumName<bool> kGaugeModels[] = {{false, "linear"}, {true, "bridge"}};
constexpr EnumName<bool> kContactModels[] = {{false, "fixed"}, {true, "sliding"}};
constexpr EnumName<bool> kPressureModels[] = {{false, "ideal"}, {true, "pse540"}};
constexpr EnumName<bool> kFiberModels[] = {{false, "ideal"}, {true, "fabric"}};
constexpr EnumName<bool> kEncoderModels[] = {{false, "ideal"}, {true, "counts"}};

// a model key: one of its names, or the default's
bool read_model(ConfigReader& in, const std::string& key, const EnumName<bool> (&names)[2],
                bool fallback) {
  const std::string model = in.get_string(key, name_of(names, fallback));
  return parse_name(names, model, in.where(key));
}

// An instrument's model, "<prefix>model": its hardware keys (the rest under <prefix>) are
// used only by the hardware model and refused with the ideal one, which would ignore them
// (as the valve's regulator keys are).
bool read_instrument_model(ConfigReader& in, const std::string& prefix,
                           const EnumName<bool> (&names)[2], bool fallback) {
  const bool hardware = read_model(in, prefix + "model", names, fallback);
  if (hardware) return true;
  for (const std::string& key : in.leaf_keys()) {
    if (key.rfind(prefix, 0) != 0 || key == prefix + "model") continue;
    in.check(false, key,
             std::string("is used only by ") + prefix + "model = \"" + name_of(names, true) +
                 "\", not \"" + name_of(names, false) + "\"");
  }
  return false;
}

// a length key in mm, kept in m
double get_mm(ConfigReader& in, const std::string& key, double fallback_m) {
  return units::mm_to_m(in.get_double(key, units::m_to_mm(fallback_m)));
}

// a pressure key in MPa, kept in Pa
double get_mpa(ConfigReader& in, const std::string& key, double fallback_pa) {
  return units::mpa_to_pa(in.get_double(key, units::pa_to_mpa(fallback_pa)));
}

// a Prony series as two lists of one length: <prefix>creep_weights and creep_times_s
std::vector<PronyTerm> read_creep(ConfigReader& in, const std::string& prefix,
                                  const std::vector<PronyTerm>& fallback) {
  std::vector<double> weights_fallback, times_fallback;
  for (const PronyTerm& t : fallback) {
    weights_fallback.push_back(t.weight);
    times_fallback.push_back(t.time_s);
  }
  const std::vector<double> weights = in.get_double_list(prefix + "creep_weights", weights_fallback);
  const std::vector<double> times = in.get_double_list(prefix + "creep_times_s", times_fallback);
  in.check(weights.size() == times.size(), prefix + "creep_times_s",
           "must list one time per weight (" + std::to_string(weights.size()) + "), got " +
               std::to_string(times.size()));
  std::vector<PronyTerm> creep;
  for (std::size_t i = 0; i < weights.size(); ++i) creep.push_back({weights[i], times[i]});
  return creep;
}

// sensors.gauge.contact.*: where the line bears on the board (sensing/gauge_contact.h)
void read_gauge_contact(ConfigReader& in, GaugeContactParams* c) {
  const std::string k = "sensors.gauge.contact.";
  c->sliding = read_model(in, k + "model", kContactModels, c->sliding);
  c->misalignment_m = get_mm(in, k + "misalignment_mm", c->misalignment_m);
  c->fitting_distance_m = get_mm(in, k + "fitting_distance_mm", c->fitting_distance_m);
  c->shaft_distance_m = get_mm(in, k + "shaft_distance_mm", c->shaft_distance_m);
  c->wrap_deg = in.get_double(k + "wrap_deg", c->wrap_deg);
  c->friction_coefficient = in.get_double(k + "friction_coefficient", c->friction_coefficient);
}

// sensors.gauge.* and sensors.instrument_seed: the gauge as hardware (sensing/gauge_hardware.h)
void read_gauge_hardware(ConfigReader& in, GaugeHardwareConfig* g) {
  g->enabled = read_instrument_model(in, "sensors.gauge.", kGaugeModels, false);
  const std::string b = "sensors.gauge.";
  g->bridge.excitation_v = in.get_double(b + "excitation_V", g->bridge.excitation_v);
  g->bridge.gauge_factor = in.get_double(b + "gauge_factor", g->bridge.gauge_factor);
  g->bridge.nominal_ohm = in.get_double(b + "nominal_Ohm", g->bridge.nominal_ohm);
  g->bridge.tolerance_pct = in.get_double(b + "tolerance_pct", g->bridge.tolerance_pct);
  GaugeBoardParams& board = g->board;
  board.youngs_modulus_pa = units::mpa_to_pa(in.get_double(
      b + "board.youngs_modulus_MPa", units::pa_to_mpa(board.youngs_modulus_pa)));
  board.width_m = get_mm(in, b + "board.width_mm", board.width_m);
  board.thickness_m = get_mm(in, b + "board.thickness_mm", board.thickness_m);
  board.gauge_position_m = get_mm(in, b + "board.gauge_position_mm", board.gauge_position_m);
  board.contact_position_m = get_mm(in, b + "board.contact_position_mm", board.contact_position_m);
  board.length_m = get_mm(in, b + "board.length_mm", board.length_m);
  g->creep = read_creep(in, b + "board.", g->creep);
  BoardVibrationParams& v = g->vibration;
  v.enabled = in.get_bool(b + "board.vibration", v.enabled);
  v.density_kg_m3 = in.get_double(b + "board.density_kg_m3", v.density_kg_m3);
  v.loss_factor = in.get_double(b + "board.loss_factor", v.loss_factor);
  read_gauge_contact(in, &g->contact);
  g->calibration_max_n = in.get_double(b + "calibration.max_N", g->calibration_max_n);
  const std::int64_t steps = in.get_int(b + "calibration.steps", g->calibration_steps);
  in.check(steps >= 1 && steps <= 1000, b + "calibration.steps",
           "must be within [1, 1000], got " + std::to_string(steps));
  g->calibration_steps = static_cast<int>(steps);
  g->calibration_hold_s = in.get_double(b + "calibration.hold_s", g->calibration_hold_s);
  const std::int64_t seed = in.get_int("sensors.instrument_seed", 1);
  in.check(seed >= 0, "sensors.instrument_seed", "must be >= 0, got " + std::to_string(seed));
  g->instrument_seed = static_cast<std::uint64_t>(seed);
}

// sensors.pressure.*: the PSE540 as hardware (sensing/pressure_hardware.h)
void read_pressure_hardware(ConfigReader& in, PressureHardwareConfig* p) {
  const std::string b = "sensors.pressure.";
  p->enabled = read_instrument_model(in, b, kPressureModels, p->enabled);
  p->bias_mean_pa = get_mpa(in, b + "bias_mean_MPa", p->bias_mean_pa);
  p->bias_stddev_pa = get_mpa(in, b + "bias_stddev_MPa", p->bias_stddev_pa);
  p->gain_error_stddev_pct = in.get_double(b + "gain_error_stddev_pct", p->gain_error_stddev_pct);
  p->dynamic_bias_stddev_pa = get_mpa(in, b + "dynamic_bias_stddev_MPa", p->dynamic_bias_stddev_pa);
  p->dynamic_bias_correlation_time_s = in.get_double(b + "dynamic_bias_correlation_time_s",
                                                     p->dynamic_bias_correlation_time_s);
  p->hysteresis_pa = get_mpa(in, b + "hysteresis_MPa", p->hysteresis_pa);
  p->response_time_s = in.get_double(b + "response_time_ms", 1e3 * p->response_time_s) / 1e3;
  p->precision_pa = get_mpa(in, b + "precision_MPa", p->precision_pa);
}

// sensors.fiber.* (sensing/fiber_hardware.h) and sensors.encoder.* (sensing/sensors.h)
void read_fiber_and_encoder(ConfigReader& in, FiberHardwareConfig* f, EncoderConfig* e) {
  f->enabled = read_instrument_model(in, "sensors.fiber.", kFiberModels, f->enabled);
  f->nonlinearity_pct = in.get_double("sensors.fiber.nonlinearity_pct", f->nonlinearity_pct);
  f->span_m = get_mm(in, "sensors.fiber.span_mm", f->span_m);
  f->creep = read_creep(in, "sensors.fiber.", f->creep);
  e->enabled = read_instrument_model(in, "sensors.encoder.", kEncoderModels, e->enabled);
  e->resolution_m = get_mm(in, "sensors.encoder.resolution_mm", e->resolution_m);
}

}  // namespace

void read_sensors(ConfigReader& in, Scenario* sc) {
  SensorConfig& s = sc->sensing.sensors;
  read_key_rows(in, sensor_key_table(&s));   // sensors.*: noise, ADCs, the pressure low-pass
  read_gauge_hardware(in, &s.gauge_hardware);
  read_pressure_hardware(in, &s.pressure_hardware);
  read_fiber_and_encoder(in, &s.fiber_hardware, &s.encoder);
  sc->sensing.control_hz = sc->control_hz;   // velocity_lowpass_hz: the controller's config
  sc->sensing.physics_dt_s = sc->timestep_s;
  in_file(in, [&] {
    validate(sc->sensing);
    return 0;
  });
}

}  // namespace pamsim
