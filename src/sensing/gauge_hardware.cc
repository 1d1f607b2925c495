// gauge_hardware.cc: see gauge_hardware.h.
#include "sensing/gauge_hardware.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include <Eigen/Dense>

#include "base/format.h"
#include "base/input_error.h"
#include "base/units.h"
#include "sensing/checks.h"
#include "sensing/instrument_keys.h"

namespace pamsim {
namespace {

// The bridge's output per newton of a nominal gauge at small strain: V_ex GF / 4 per unit
// strain (quarter_bridge.h) times the board's strain per newton (gauge_board.h).
double nominal_volts_per_newton(const GaugeHardwareConfig& c) {
  const GaugeBoardParams& b = c.board;
  const double strain_per_n = gauge_board_strain(b, 1.0, b.contact_position_m);
  return c.bridge.excitation_v * c.bridge.gauge_factor / 4.0 * strain_per_n;
}

// the board's creep: its Prony lists, or its Findley law as a series
std::vector<PronyTerm> board_creep(const GaugeHardwareConfig& c) {
  return c.creep.empty() ? findley_prony_terms(c.findley) : c.creep;
}

}  // namespace

void validate(const GaugeHardwareConfig& c) {
  // each key's own range (instrument_keys.h), then what joins keys
  GaugeHardwareConfig fields = c;
  for (const KeyTable& table : gauge_hardware_key_tables(&fields)) check_key_rows(table);
  validate_gauge_board(c.board, "sensors.gauge.board.");
  validate_prony(c.creep, "sensors.gauge.board.creep_weights", "sensors.gauge.board.creep_times_s");
  if (!c.creep.empty() && c.findley.creep_1000h > 0.0) {
    checks::fail("sensors.gauge.board.creep_1000h",
                 "0 when creep_weights give the board's creep (one law or the other)",
                 c.findley.creep_1000h);
  }
  // the re-seated line bears beyond the gauge and on the board
  const double seat = c.board.contact_position_m + c.contact.reseat_m;
  if (!(seat > c.board.gauge_position_m && seat <= board_free_length_m(c.board))) {
    checks::fail("sensors.gauge.contact.reseat_mm",
                 "such that the contact stays between gauge_position_mm and the board's free end",
                 units::m_to_mm(c.contact.reseat_m));
  }
  if (c.contact.lost_at_shortening_m > 0.0 && !c.contact.sliding) {
    checks::fail("sensors.gauge.contact.lost_at_shortening_mm",
                 "0 with a fixed contact (model = \"sliding\" to solve its loss)",
                 units::m_to_mm(c.contact.lost_at_shortening_m));
  }
  const double f1 = board_first_mode_hz(c.board, c.vibration);
  if (c.vibration.enabled && !(f1 > 0.0 && std::isfinite(f1))) {
    checks::fail("sensors.gauge.board.length_mm", "short enough that the board has a first mode",
                 units::m_to_mm(c.board.length_m));
  }
  // PMMA breaks at a few percent of strain: a board bent further is no gauge
  const double strain =
      gauge_board_strain(c.board, c.calibration_max_n, c.board.contact_position_m);
  if (!(strain <= kMaxBoardStrain)) {
    checks::fail("sensors.gauge.board.thickness_mm",
                 "thick enough that calibration.max_N strains the board at most 3 %",
                 units::m_to_mm(c.board.thickness_m));
  }
}

void validate_calibration_length(const GaugeHardwareConfig& c, double control_hz) {
  const double ticks = (2.0 * c.calibration_steps + 1.0) *
                       std::max(1.0, std::round(c.calibration_hold_s * control_hz));
  if (!(ticks <= kMaxCalibrationTicks)) {
    checks::fail("sensors.gauge.calibration.hold_s",
                 "short enough that the calibration takes at most 1e7 control ticks",
                 c.calibration_hold_s);
  }
}

GaugeHardware::GaugeHardware(const GaugeHardwareConfig& config, const StrainGaugeParams& nominal,
                             std::mt19937_64& instrument_rng, double sample_period_s)
    : config_(config),
      arms_(draw_bridge(config.bridge, instrument_rng)),
      gain_(nominal.q_v_per_n / nominal_volts_per_newton(config)),
      offset_v_(nominal.v_base_v),
      creep_(board_creep(config), sample_period_s),
      contact_(config.contact, config.board) {
  config_.bridge.amplifier_gain = gain_;
}

void GaugeHardware::enable_vibration(double physics_dt_s) {
  if (!config_.vibration.enabled) return;
  vibration_.emplace(board_first_mode_hz(config_.board, config_.vibration),
                     config_.vibration.loss_factor / 2.0, physics_dt_s);
}

void GaugeHardware::observe(double f_n) {
  // a line that has slid off the board no longer bends it
  if (vibration_) vibration_->step(contact_.lost() ? 0.0 : f_n);
}

void GaugeHardware::follow(double length_m, double f_n) { contact_.follow(length_m, f_n); }

double GaugeHardware::voltage(double f_n) {
  // the bend per newton at the contact of this moment (none once the line is off the
  // board); a ringing board bends either way, its strain linear in the equivalent pull
  const double per_newton =
      contact_.lost() ? 0.0 : gauge_board_strain(config_.board, 1.0, contact_.position_m());
  const double pull =
      vibration_ && vibration_->started() ? vibration_->equivalent_force_n() : std::max(f_n, 0.0);
  const double elastic = per_newton * pull;
  const double strain = creep_.step(elastic);
  return quarter_bridge_output_v(config_.bridge, arms_, strain) + offset_v_;
}

StrainGaugeParams calibrate_gauge(GaugeHardware gauge, const GaugeHardwareConfig& config,
                                  double sample_period_s, const std::string& key) {
  // the staircase: 0, 1, ..., steps, steps - 1, ..., 0 load steps, each held, then read
  const int n = config.calibration_steps;
  const std::int64_t ticks =
      std::max<std::int64_t>(1, std::llround(config.calibration_hold_s / sample_period_s));
  Eigen::MatrixXd a(2 * n + 1, 2);
  Eigen::VectorXd v(2 * n + 1);
  for (int row = 0; row <= 2 * n; ++row) {
    const double load = config.calibration_max_n * (row <= n ? row : 2 * n - row) / n;
    double reading = 0.0;
    for (std::int64_t k = 0; k < ticks; ++k) reading = gauge.voltage(load);
    a(row, 0) = load;
    a(row, 1) = 1.0;
    v[row] = reading;
  }
  const Eigen::Vector2d fit = a.colPivHouseholderQr().solve(v);
  if (!(fit[0] > 0.0)) {
    throw InputError(key + ": the calibration found no positive slope q (got " +
                     format_value(fit[0]) + " V/N)");
  }
  StrainGaugeParams calibrated;
  calibrated.q_v_per_n = fit[0];
  calibrated.v_base_v = fit[1];
  return calibrated;
}

}  // namespace pamsim
