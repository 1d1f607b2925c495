// instrument_keys.cc: the rows of sensors.gauge.*, .pressure.*, .fiber.*, .encoder.* (see
// instrument_keys.h). The figures' sources are in each struct's header.
#include "sensing/instrument_keys.h"

#include <limits>
#include <string>

#include "base/units.h"
#include "sensing/instrument_kinds.h"

namespace pamsim {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kMm = units::kMPerMm;
constexpr double kMPa = units::kPaPerMPa;

// a choice of two names whose second turns `on` on (an instrument's hardware model)
ChoiceRow two_way(const std::string& name, const std::string& off, const std::string& on_name,
                  const std::string& doc, bool* on) {
  return {name,
          {off, on_name},
          doc,
          [on, on_name](const std::string& value) { *on = value == on_name; },
          [on, off, on_name] { return *on ? on_name : off; }};
}

KeyTable board_table(GaugeHardwareConfig& g) {
  GaugeBoardParams& b = g.board;
  BoardVibrationParams& v = g.vibration;
  KeyTable t{"sensors.gauge.board", {}, {}, {}};
  t.bools = {{"vibration",
              "the board's first bending mode rings under a sharp pull and the gauge samples it "
              "(board_vibration.h)",
              &v.enabled}};
  t.numbers = {
      {"youngs_modulus_MPa", "MPa", kMPa, kPositiveRange, "the acrylic board's modulus",
       &b.youngs_modulus_pa},
      {"width_mm", "mm", kMm, kPositiveRange, "the board's width (ASSUMPTION: not published)",
       &b.width_m},
      {"thickness_mm", "mm", kMm, kPositiveRange, "the board's thickness (ASSUMPTION)",
       &b.thickness_m},
      {"gauge_position_mm", "mm", kMm, kNonNegativeRange,
       "the gauge's distance from the clamp (ASSUMPTION)", &b.gauge_position_m},
      {"contact_position_mm", "mm", kMm, kPositiveRange,
       "where the line bears on the board, beyond gauge_position_mm (ASSUMPTION)",
       &b.contact_position_m},
      {"length_mm", "mm", kMm, kNonNegativeRange,
       "the board's free end: 0 (it ends at contact_position_mm) or at least that "
       "(ASSUMPTION)",
       &b.length_m},
      {"density_kg_m3", "kg/m^3", 1.0, kPositiveRange, "the board's density (PMMA)",
       &v.density_kg_m3},
      {"loss_factor",
       "",
       1.0,
       {0.0, 1.0, true, true},
       "the board's material loss factor (PMMA 0.02-0.04); damping ratio = half of it",
       &v.loss_factor},
      {"creep_exponent",
       "",
       1.0,
       {0.0, kMaxFindleyExponent, true, false},
       "n of the board's Findley creep A (t / 1000 h)^n (cast PMMA: 0.24; findley_creep.h)",
       &g.findley.exponent},
      {"creep_1000h", "", 1.0, kNonNegativeRange,
       "A: the board's creep after 1000 h per unit strain, 0: none (cast PMMA: about 0.6)",
       &g.findley.creep_1000h}};
  return t;
}

KeyTable contact_rows(GaugeContactParams& c) {
  KeyTable t{"sensors.gauge.contact", {}, {}, {}};
  t.choices = {two_way("model", "fixed", "sliding",
                       "the line's contact on the board held, or sliding and sticking along its "
                       "edge and lost past its free end (gauge_contact.h)",
                       &c.sliding)};
  t.numbers = {
      {"misalignment_mm", "mm", kMm, kAnyRange,
       "the arm's shaft beside the muscle's fitting, along the board's edge (ASSUMPTION)",
       &c.misalignment_m},
      {"fitting_distance_mm",
       "mm",
       kMm,
       {1.0, kInf, false, false},
       "from the muscle's end fitting to the board's edge at the start (ASSUMPTION)",
       &c.fitting_distance_m},
      {"shaft_distance_mm", "mm", kMm, kPositiveRange,
       "from the board's edge on to the arm's shaft (ASSUMPTION)", &c.shaft_distance_m},
      {"wrap_deg",
       "deg",
       1.0,
       {0.0, 180.0, true, true},
       "the line's bend over the board's edge (ASSUMPTION)",
       &c.wrap_deg},
      {"friction_coefficient", "", 1.0, kNonNegativeRange,
       "line on board (ASSUMPTION: nylon on acrylic)", &c.friction_coefficient},
      {"reseat_mm", "mm", kMm, kAnyRange,
       "the contact moved along the edge between the static calibration and the trial (the "
       "line re-laid; within its stick band, gauge_contact.h)",
       &c.reseat_m},
      {"lost_at_shortening_mm", "mm", kMm, kNonNegativeRange,
       "0: misalignment_mm as given; > 0: misalignment_mm solved so that the line leaves the "
       "board's free end once the muscle has shortened this far from the trial's start (a "
       "calibration to an observed signal loss, gauge_contact.h)",
       &c.lost_at_shortening_m}};
  return t;
}

}  // namespace

KeyTable gauge_contact_key_table(GaugeContactParams* contact) {
  KeyTable t = contact_rows(*contact);
  t.trial_only = true;
  return t;
}

std::vector<KeyTable> gauge_hardware_key_tables(GaugeHardwareConfig* gauge) {
  GaugeHardwareConfig& g = *gauge;
  QuarterBridgeParams& q = g.bridge;
  KeyTable bridge{"sensors.gauge", {}, {}, {}};
  bridge.choices = {two_way("model", "linear", "bridge",
                            "Eq. (8) as exact, or the gauge as board, bridge and calibration",
                            &g.enabled)};
  bridge.numbers = {
      {"excitation_V", "V", 1.0, kPositiveRange, "the bridge's excitation", &q.excitation_v},
      {"gauge_factor", "", 1.0, kPositiveRange, "the foil gauge's gauge factor", &q.gauge_factor},
      {"nominal_Ohm", "Ohm", 1.0, kPositiveRange,
       "the gauge's and the completion resistors' resistance", &q.nominal_ohm},
      {"tolerance_pct",
       "%",
       1.0,
       {0.0, 100.0, false, true},
       "each bridge arm within nominal +- this (paper: 0.5 Ohm of 120)",
       &q.tolerance_pct}};
  KeyTable calibration{"sensors.gauge.calibration", {}, {}, {}};
  calibration.ints = {
      int_row("steps", "its load steps up (and as many down)", 1, 1000, &g.calibration_steps)};
  calibration.numbers = {{"max_N", "N", 1.0, kPositiveRange,
                          "the static calibration's largest load", &g.calibration_max_n},
                         {"hold_s",
                          "s",
                          1.0,
                          {0.0, 3600.0, false, false},
                          "how long each load is held before it is read",
                          &g.calibration_hold_s}};
  return {bridge, board_table(g), contact_rows(g.contact), calibration};
}

KeyTable pressure_hardware_key_table(PressureHardwareConfig* pressure) {
  PressureHardwareConfig& p = *pressure;
  KeyTable t{"sensors.pressure", {}, {}, {}};
  t.choices = {two_way("model", "ideal", "pse540",
                       "the pressure sensor exact (+ noise), or the PSE540 class's offset, gain, "
                       "hysteresis, response and drift",
                       &p.enabled)};
  t.numbers = {
      {"bias_mean_MPa", "MPa", kMPa, kAnyRange,
       "mean of each sensor's offset, drawn once per instrument", &p.bias_mean_pa},
      {"bias_stddev_MPa", "MPa", kMPa, kNonNegativeRange,
       "spread of each sensor's offset (ASSUMPTION: +-2 % F.S. as 3 sigma, half of it zero)",
       &p.bias_stddev_pa},
      {"gain_error_stddev_pct",
       "%",
       1.0,
       {0.0, 50.0, false, false},
       "spread of each sensor's gain error (ASSUMPTION: the other half)",
       &p.gain_error_stddev_pct},
      {"dynamic_bias_stddev_MPa", "MPa", kMPa, kNonNegativeRange,
       "stationary SD of the zero's Gauss-Markov drift, drawn per trial (ASSUMPTION)",
       &p.dynamic_bias_stddev_pa},
      {"dynamic_bias_correlation_time_s", "s", 1.0, kPositiveRange, "that drift's correlation time",
       &p.dynamic_bias_correlation_time_s},
      {"hysteresis_MPa", "MPa", kMPa, kNonNegativeRange,
       "full width of the rising/falling loop (ASSUMPTION: the 0.2 % F.S. repeatability)",
       &p.hysteresis_pa},
      {"response_time_ms", "ms", 1e-3, kNonNegativeRange,
       "0-90 % rise of the first-order response (ASSUMPTION)", &p.response_time_s},
      {"precision_MPa", "MPa", kMPa, kNonNegativeRange,
       "the output rounded to this step, 0: none (Gazebo's precision; the ADC quantises too)",
       &p.precision_pa}};
  return t;
}

KeyTable fiber_hardware_key_table(FiberHardwareConfig* fiber) {
  KeyTable t{"sensors.fiber", {}, {}, {}};
  t.choices = {two_way("model", "ideal", "fabric",
                       "the fiber sensor's rate exact (+ noise), or the fabric's nonlinearity "
                       "and creep",
                       &fiber->enabled)};
  t.numbers = {{"nonlinearity_pct",
                "%",
                1.0,
                {-100.0, 100.0, true, true},
                "the reading's error at span_mm from the calibration length (ASSUMPTION)",
                &fiber->nonlinearity_pct},
               {"span_mm", "mm", kMm, kPositiveRange, "the displacement nonlinearity_pct refers to",
                &fiber->span_m}};
  return t;
}

KeyTable encoder_key_table(EncoderConfig* encoder) {
  KeyTable t{"sensors.encoder", {}, {}, {}};
  t.choices = {two_way("model", "ideal", "counts",
                       "the linear encoder exact, or counting resolution_mm steps",
                       &encoder->enabled)};
  t.numbers = {{"resolution_mm", "mm", kMm, kPositiveRange,
                "the encoder's count (ASSUMPTION: DS-025 class); used by the fiber's "
                "calibration",
                &encoder->resolution_m}};
  return t;
}

std::vector<KeyTable> instrument_key_tables(SensorConfig* sensors) {
  std::vector<KeyTable> tables;
  for (const InstrumentKind& kind : instrument_kinds()) {
    for (KeyTable& t : kind.key_tables(sensors)) {
      t.trial_only = true;  // the instruments are the trial's, not the model's
      tables.push_back(std::move(t));
    }
  }
  return tables;
}

}  // namespace pamsim
