// figure_text.cc: see figure_text.h.
#include "sim/io/figure_text.h"

#include <filesystem>

#include "sim/io/gnuplot.h"

namespace pamsim {

std::string xrange_line(const std::vector<double>& time_s) {
  double lo, hi;
  if (!finite_range(time_s, lo, hi)) lo = 0, hi = 1;
  if (hi <= lo) hi = lo + 1;
  return "set xrange [" + gp_num(lo) + ":" + gp_num(hi) + "]\n";
}

std::string file_name(const std::string& path) {
  const std::string name = std::filesystem::path(path).filename().string();
  return name.empty() ? path : name;
}

}  // namespace pamsim
