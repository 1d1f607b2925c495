// checks.h: the value checks behind validate() in sensing.h and stretch_reflex_controller.h.
// Each throws InputError "<key> must be <allowed>, got <value>" naming the scenario key.
#pragma once

#include <string>

#include "base/format.h"  // format_value: the numbers in the messages

namespace pamsim::checks {

[[noreturn]] void fail(const std::string& key, const std::string& allowed, double value);
void require_finite(const std::string& key, double value);
void require_positive(const std::string& key, double value);
void require_non_negative(const std::string& key, double value);
// a low-pass cutoff: 0 (off) or up to the Nyquist frequency of the control rate
void require_cutoff(const std::string& key, double value, double control_hz);
// a reflex window (ReflexWindow, stretch_reflex.h) under `prefix` ("reflex", "reflex.ib"):
// its duration at least one control period of `dt` s, its refractory time and arming delay
// not negative; both times counted in int ticks, so at most 1e9 of them
void require_window(const std::string& prefix, double duration_s, double refractory_s,
                    double arm_after_s, double dt);
// an ADC: 0 or 4..24 bits over a finite, non-empty voltage range
void require_adc(const std::string& prefix, int bits, double v_min, double v_max);

}  // namespace pamsim::checks
