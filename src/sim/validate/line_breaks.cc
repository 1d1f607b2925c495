// line_breaks.cc: see line_breaks.h.
#include "sim/validate/line_breaks.h"

#include <algorithm>
#include <cmath>

#include "base/format.h"
#include "base/input_error.h"

namespace pamsim {

void check_line_breaks(const Scenario& sc, const std::vector<const Trajectory*>& trajectories) {
  for (const MuscleSpec& m : sc.muscles) {
    if (std::isnan(m.line_break_n)) continue;
    double peak = 0.0;
    for (const Trajectory* tr : trajectories) {
      const std::size_t force = tr->column("force_" + m.label + "_N");
      for (std::size_t i = 0; i < tr->rows(); ++i) peak = std::max(peak, tr->at(i, force));
    }
    if (peak > m.line_break_n) {
      throw file_key_error(sc.path, m.key + ".line_strength_MPa",
                           "its line breaks: it pulls " + format_value(peak) +
                               " N, past its break load of " + format_value(m.line_break_n) +
                               " N");
    }
  }
}

}  // namespace pamsim
