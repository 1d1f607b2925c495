// checks.cc: see checks.h.
#include "reflex/checks.h"

#include <cmath>

#include "base/input_error.h"

namespace pamsim::checks {

void fail(const std::string& key, const std::string& allowed, double value) {
  throw InputError(key + " must be " + allowed + ", got " + format_value(value));
}

void require_finite(const std::string& key, double value) {
  if (!std::isfinite(value)) fail(key, "finite", value);
}

void require_positive(const std::string& key, double value) {
  if (!(std::isfinite(value) && value > 0.0)) fail(key, "> 0", value);
}

void require_non_negative(const std::string& key, double value) {
  if (!(std::isfinite(value) && value >= 0.0)) fail(key, ">= 0", value);
}

void require_cutoff(const std::string& key, double value, double control_hz) {
  const double nyquist = 0.5 * control_hz;
  if (!(std::isfinite(value) && value >= 0.0 && value <= nyquist)) {
    fail(key, "0 (off) or in (0, " + format_value(nyquist) + "] Hz (sim.control_hz / 2)",
         value);
  }
}

void require_adc(const std::string& prefix, int bits, double v_min, double v_max) {
  if (!(bits == 0 || (bits >= 4 && bits <= 24))) {
    fail(prefix + "_bits", "0 (ideal) or in [4, 24]", bits);
  }
  require_finite(prefix + "_min_V", v_min);
  require_finite(prefix + "_max_V", v_max);
  if (!(v_max > v_min)) {
    fail(prefix + "_max_V", "> " + prefix + "_min_V = " + format_value(v_min), v_max);
  }
}

}  // namespace pamsim::checks
