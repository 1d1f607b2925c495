// quarter_bridge.h: a foil strain gauge in a quarter Wheatstone bridge, as the paper's
// gauges are wired (Yoshida and Hosoda, Sec. IV-B: foil gauges on acrylic boards, a quarter bridge
// completed by 120 +- 0.5 Ohm resistors). The output is the bridge formula
//   V_out = G V_ex ( R_g / (R_g + R_3) - R_2 / (R_1 + R_2) ),  R_g = R_g0 (1 + GF eps),
// which for four equal arms is G V_ex GF eps / (4 + 2 GF eps): V_base is not zero once the
// arms differ within their tolerance, and the output bends away from linear with strain.
// A built bridge's four resistances are drawn once per instrument (uniform within the
// tolerance), so an instrument keeps its offset from trial to trial.
#pragma once

#include <random>
#include <string>

namespace pamsim {

struct QuarterBridgeParams {
  double excitation_v = 5.0;  // V_ex > 0
  // GF > 0. Cu-Ni (constantan) foil gauges such as the paper's Kyowa KFP-5-120-C1-65: about
  // 2.0-2.1, the exact factor printed on each package.
  double gauge_factor = 2.0;
  double nominal_ohm = 120.0;  // R > 0: the gauge and the completion resistors
  // each arm within R (1 +- tolerance): 0.5 Ohm of 120, the paper's for the three completion
  // resistors; the gauge's own spread is taken the same (an assumption); in [0, 100) percent
  double tolerance_pct = 100.0 * 0.5 / 120.0;
  double amplifier_gain = 1.0;  // G > 0 (an instrumentation amplifier after the bridge)
};

// One built bridge: the gauge's unstrained resistance and the three completion resistors.
struct BridgeResistors {
  double r1_ohm = 120.0, r2_ohm = 120.0, r3_ohm = 120.0, gauge_ohm = 120.0;
};
// All four at the nominal value (an ideal bridge).
BridgeResistors nominal_bridge(const QuarterBridgeParams& params);
// Each arm uniform in R (1 +- tolerance), four draws from `rng` in the order r1, r2, r3, gauge.
BridgeResistors draw_bridge(const QuarterBridgeParams& params, std::mt19937_64& rng);

// The bridge's (amplified) output at the gauge's strain [V].
double quarter_bridge_output_v(const QuarterBridgeParams& params, const BridgeResistors& arms,
                               double strain);

}  // namespace pamsim
