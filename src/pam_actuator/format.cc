// format.cc: see format.h.
#include "pam_actuator/format.h"

#include <cstdio>
#include <cstdlib>

namespace pamsim {

std::string format_value(double v) {
  char buf[64];
  std::snprintf(buf, sizeof(buf), "%.10g", v);
  return buf;
}

std::string format_shortest(double v) {
  char buf[40];
  for (int digits : {15, 16, 17}) {
    std::snprintf(buf, sizeof(buf), "%.*g", digits, v);
    if (std::strtod(buf, nullptr) == v) break;
  }
  return buf;
}

std::string format_number(double v) {
  std::string s = format_shortest(v);
  if (s.find_first_of(".eEn") == std::string::npos) s += ".0";
  return s;
}

}  // namespace pamsim
