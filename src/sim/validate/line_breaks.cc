// line_breaks.cc: see line_breaks.h.
#include "sim/validate/line_breaks.h"

#include <algorithm>
#include <cmath>

#include "base/format.h"
#include "base/input_error.h"

namespace pamsim {

double logged_peak_tension(const MuscleSpec& m,
                           const std::vector<const Trajectory*>& trajectories) {
  double peak = 0.0;
  for (const Trajectory* tr : trajectories) {
    const std::size_t force = tr->column("force_" + m.label + "_N");
    for (std::size_t i = 0; i < tr->rows(); ++i) peak = std::max(peak, tr->at(i, force));
  }
  return peak;
}

std::string line_break_problem(const MuscleSpec& m, double peak_n) {
  if (std::isnan(m.line_break_n) || !(peak_n > m.line_break_n)) return "";
  return "its line breaks: it pulls " + format_value(peak_n) + " N, past its break load of " +
         format_value(m.line_break_n) + " N";
}

void check_line_breaks(const Scenario& sc, const std::vector<const Trajectory*>& trajectories) {
  for (const MuscleSpec& m : sc.muscles) {
    if (std::isnan(m.line_break_n)) continue;
    const std::string problem = line_break_problem(m, logged_peak_tension(m, trajectories));
    if (!problem.empty()) throw file_key_error(sc.path, m.key + ".line_strength_MPa", problem);
  }
}

}  // namespace pamsim
