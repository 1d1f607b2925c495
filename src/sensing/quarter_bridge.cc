// quarter_bridge.cc: see quarter_bridge.h.
#include "sensing/quarter_bridge.h"

#include <cmath>

#include "base/portable_random.h"

namespace pamsim {

BridgeResistors nominal_bridge(const QuarterBridgeParams& p) {
  return {p.nominal_ohm, p.nominal_ohm, p.nominal_ohm, p.nominal_ohm};
}

BridgeResistors draw_bridge(const QuarterBridgeParams& p, std::mt19937_64& rng) {
  const double spread = p.nominal_ohm * p.tolerance_pct / 100.0;
  // a portable uniform [0, 1): the same arms on every platform
  const auto arm = [&] {
    const double u = unit_uniform(rng);
    return p.nominal_ohm + spread * (2.0 * u - 1.0);
  };
  BridgeResistors r;
  r.r1_ohm = arm();
  r.r2_ohm = arm();
  r.r3_ohm = arm();
  r.gauge_ohm = arm();
  return r;
}

double quarter_bridge_output_v(const QuarterBridgeParams& p, const BridgeResistors& r,
                               double strain) {
  const double r_gauge = r.gauge_ohm * (1.0 + p.gauge_factor * strain);
  const double bridge = r_gauge / (r_gauge + r.r3_ohm) - r.r2_ohm / (r.r1_ohm + r.r2_ohm);
  return p.amplifier_gain * p.excitation_v * bridge;
}

}  // namespace pamsim
