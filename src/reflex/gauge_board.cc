// gauge_board.cc: see gauge_board.h.
#include "reflex/gauge_board.h"

#include <algorithm>

#include "reflex/checks.h"

namespace pamsim {

void validate_gauge_board(const GaugeBoardParams& b, const std::string& prefix) {
  checks::require_positive(prefix + "youngs_modulus_MPa", b.youngs_modulus_pa * 1e-6);
  checks::require_positive(prefix + "width_mm", b.width_m * 1e3);
  checks::require_positive(prefix + "thickness_mm", b.thickness_m * 1e3);
  checks::require_non_negative(prefix + "gauge_position_mm", b.gauge_position_m * 1e3);
  if (!(b.contact_position_m > b.gauge_position_m)) {
    checks::fail(prefix + "contact_position_mm", "beyond gauge_position_mm (the lever's end)",
                 b.contact_position_m * 1e3);
  }
}

double gauge_board_strain(const GaugeBoardParams& b, double f_n, double contact_m) {
  const double lever = std::max(contact_m - b.gauge_position_m, 0.0);
  const double force = std::max(f_n, 0.0);
  return 6.0 * force * lever / (b.youngs_modulus_pa * b.width_m * b.thickness_m * b.thickness_m);
}

}  // namespace pamsim
