// gauge_hardware.h: the strain gauge as hardware (sensors.gauge.model = "bridge") instead of
// Eq. (8) taken as exact: the line's pull bends the acrylic board (gauge_board.h), the
// board creeps (prony_creep.h), the foil gauge on it sits in a quarter bridge whose arms
// differ within their tolerance (quarter_bridge.h), and an amplifier brings the bridge to
// volts. The estimator is not told this gauge's slope: like the lab (Yoshida and Hosoda, Sec. IV-B,
// "q was obtained by measuring voltage and force while statically loading the strain
// gauge"), pamsim loads the simulated gauge in steps, reads it, and fits Eq. (8)'s q and
// V_base by least squares (calibrate_gauge).
#pragma once

#include <cstdint>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include "pam_actuator/pam_params.h"
#include "sensing/board_vibration.h"
#include "sensing/gauge_board.h"
#include "sensing/findley_creep.h"
#include "sensing/gauge_contact.h"
#include "sensing/prony_creep.h"
#include "sensing/quarter_bridge.h"

namespace pamsim {

// Keys sensors.gauge.* (read in sim/io; SI inside).
struct GaugeHardwareConfig {
  bool enabled = false;  // sensors.gauge.model: "linear" (Eq. (8) exact) | "bridge"
  // sensors.gauge.excitation_V, gauge_factor, nominal_Ohm, tolerance_pct. The amplifier's
  // gain is the one unknown the paper pins: it is set so that a nominal gauge (equal arms,
  // no creep, small strain) has the muscle's published slope q (Table IV), and its output
  // offset is the published V_base; everything else is this gauge's physics.
  QuarterBridgeParams bridge;
  // sensors.gauge.board.*: the paper gives no board dimensions; these are an ASSUMPTION (a
  // 20 x 5 mm acrylic strip, the gauge 10 mm from the clamp, the line 30 mm beyond it:
  // about 0.5 % strain at 50 N), a row of docs/physics.md's departures. E from gauge_board.h.
  GaugeBoardParams board = {3.3e9, 0.020, 0.005, 0.010, 0.040, 0.045};
  // sensors.gauge.board.creep_weights and creep_times_s (two lists of one length): none
  // by default; or the board's creep as cast PMMA's Findley law (findley_creep.h),
  // sensors.gauge.board.creep_exponent and creep_1000h, run as its Prony series
  std::vector<PronyTerm> creep;
  FindleyCreep findley;
  BoardVibrationParams vibration;     // sensors.gauge.board.vibration, density_kg_m3, loss_factor
  GaugeContactParams contact;         // sensors.gauge.contact.*
  std::uint64_t instrument_seed = 1;  // sensors.instrument_seed: which built instruments
  // the static calibration (sensors.gauge.calibration.*): loads 0 .. max_n in `steps`
  // equal steps up and back down, each held hold_s before it is read
  double calibration_max_n = 50.0;
  int calibration_steps = 10;
  double calibration_hold_s = 2.0;
};

// Throws InputError "<key> must be ..., got <value>" naming the sensors.gauge.* key
// (including a board so thin that calibration.max_N would strain it beyond 3 %).
void validate(const GaugeHardwareConfig& config);
// The calibration's length at the control rate: at most 1e7 ticks (hold_s named).
void validate_calibration_length(const GaugeHardwareConfig& config, double control_hz);
inline constexpr double kMaxBoardStrain = 0.03;
inline constexpr double kMaxCalibrationTicks = 1e7;

class GaugeHardware {
 public:
  // One built gauge: its bridge arms drawn from `instrument_rng` (four draws), its gain set
  // from the muscle's published Eq. (8) constants `nominal`. sample_period_s > 0.
  GaugeHardware(const GaugeHardwareConfig& config, const StrainGaugeParams& nominal,
                std::mt19937_64& instrument_rng, double sample_period_s);

  // The board's ringing, stepped by physics_dt_s from the first observe() on (a no-op when
  // sensors.gauge.board.vibration is off). The board rings (board_vibration.h): fed the
  // line's pull at every physics step (observe()), a gauge reads the board's bend, not the
  // pull of this instant. Without those calls (the static calibration) it reads the pull
  // held over the tick.
  void enable_vibration(double physics_dt_s);
  bool vibrates() const { return vibration_.has_value(); }
  // One physics step with the line's pull f_n [N] held over it.
  void observe(double f_n);
  // One control tick: where the line bears on the board now (gauge_contact.h), the muscle
  // at length_m pulled by f_n [N].
  void follow(double length_m, double f_n);
  bool contact_lost() const { return contact_.lost(); }
  // The line re-seated between the static calibration and use: its contact moves by
  // sensors.gauge.contact.reseat_mm along the board's edge (a no-op at 0).
  void reseat() { contact_.reseat(config_.contact.reseat_m); }

  // The amplifier's output at the end of a tick over which the line pulled f_n [N] (or, once
  // observed, as far as the ringing board is bent now).
  double voltage(double f_n);
  double gain() const { return gain_; }
  const BridgeResistors& arms() const { return arms_; }

 private:
  GaugeHardwareConfig config_;
  BridgeResistors arms_;
  double gain_ = 0.0;
  double offset_v_ = 0.0;
  PronyCreep creep_;
  std::optional<BoardVibration> vibration_;
  GaugeContact contact_;
};

// The lab's static calibration of `gauge` (pass one not yet sampled: its creep must start
// unloaded; a pre-tensioned start is not modelled yet), Eq. (8)
// fitted by least squares to the readings at the end of each hold. Throws InputError
// "<key>: the calibration found no positive slope" should the fit fail.
StrainGaugeParams calibrate_gauge(GaugeHardware gauge, const GaugeHardwareConfig& config,
                                  double sample_period_s, const std::string& key);

}  // namespace pamsim
