// gauge_board.cc: see gauge_board.h.
#include "sensing/gauge_board.h"

#include <algorithm>

#include "base/units.h"
#include "sensing/checks.h"

namespace pamsim {

void validate_gauge_board(const GaugeBoardParams& b, const std::string& prefix) {
  if (!(b.contact_position_m > b.gauge_position_m)) {
    checks::fail(prefix + "contact_position_mm", "beyond gauge_position_mm (the lever's end)",
                 units::m_to_mm(b.contact_position_m));
  }
  if (!(b.length_m == 0.0 || b.length_m >= b.contact_position_m)) {
    checks::fail(prefix + "length_mm", "0 (ending at contact_position_mm) or at least it",
                 units::m_to_mm(b.length_m));
  }
}

double gauge_board_strain(const GaugeBoardParams& b, double f_n, double contact_m) {
  const double lever = std::max(contact_m - b.gauge_position_m, 0.0);
  const double force = std::max(f_n, 0.0);
  return 6.0 * force * lever / (b.youngs_modulus_pa * b.width_m * b.thickness_m * b.thickness_m);
}

}  // namespace pamsim
