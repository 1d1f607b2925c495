// pneumatics_test_util.h: the muscle the chamber and regulator tests share, Table I of
// Yoshida and Hosoda (180 mm long, 16 mm sleeve; the braid angle, which the paper does not give,
// assumed 25 deg), and their physics step.
#pragma once

#include "base/units.h"
#include "pneumatics/pneumatics.h"

namespace pamsim_test {

constexpr double kDt = 1e-3;      // physics step [s]
constexpr double kL0 = 0.18;      // Table I muscle length [m]
constexpr double kLength = 0.15;  // a contracted Table I muscle [m]

inline pamsim::BraidGeometry table_one_braid() {
  return pamsim::braid_from_initial_shape(kL0, 0.016, pamsim::units::deg_to_rad(25.0));
}

}  // namespace pamsim_test
