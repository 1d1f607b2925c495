// figure_text.h: the pieces of gnuplot script text the figures of plot.h share (the x
// range of a time axis, a file's name for a title). Internal to src/sim/io.
#pragma once

#include <string>
#include <vector>

namespace pamsim {

// "set xrange [a:b]\n" over the finite times, widened if there is a single time ([0:1]
// if none)
std::string xrange_line(const std::vector<double>& time_s);

// the last part of `path` ("drop_mass.toml"); `path` itself if it has none
std::string file_name(const std::string& path);

}  // namespace pamsim
