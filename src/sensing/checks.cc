// checks.cc: see checks.h.
#include "sensing/checks.h"

#include <cmath>
#include <utility>

#include "base/input_error.h"

namespace pamsim::checks {

void fail(const std::string& key, const std::string& allowed, double value) {
  const std::string problem = "must be " + allowed + ", got " + format_value(value);
  throw InputError(key + " " + problem, {"", key, problem});  // (its parts: a reader renames)
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
    fail(key, "0 (off) or in (0, " + format_value(nyquist) + "] Hz (sim.control_hz / 2)", value);
  }
}

void require_window(const std::string& prefix, double duration_s, double refractory_s,
                    double arm_after_s, double dt) {
  if (!(std::isfinite(duration_s) && duration_s >= dt * (1.0 - 1e-9))) {
    fail(prefix + ".duration_s", ">= one control period (" + format_value(dt) + " s)", duration_s);
  }
  require_non_negative(prefix + ".refractory_s", refractory_s);
  const double max_ticks_s = 1e9 * dt;
  for (const auto& [key, value] :
       {std::pair{".duration_s", duration_s}, std::pair{".refractory_s", refractory_s}}) {
    if (!(value <= max_ticks_s)) {
      fail(prefix + key, "at most " + format_value(max_ticks_s) + " s (1e9 control periods)",
           value);
    }
  }
  require_non_negative(prefix + ".arm_after_s", arm_after_s);
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
