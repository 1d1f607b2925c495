// gnuplot.h: draws a PNG with gnuplot (pngcairo terminal), driven from the program: the
// job's data files and script go to a private temp folder
// (<temp_directory_path>/pamsim_plot_<pid>_<n>), gnuplot writes <png>.tmp.XXXXXX (made
// exclusively), which is renamed into place once gnuplot exited 0 and the PNG is whole (its
// IEND chunk: gnuplot exits 0 on a full disk), so a failed plot leaves no partial file; n is
// a process-wide counter, so plots may be drawn from many threads; SVG and PDF copies beside
// the PNG the same way (set_extra_plot_formats). What plot.h's figures are drawn with.
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace pamsim {

// A plot to draw: image size, data files by name (in the temp folder) and the script body
// (the terminal and output lines are added).
struct GnuplotJob {
  int width_px = 1200;
  int height_px = 900;
  std::vector<std::pair<std::string, std::string>> data_files;  // name, content
  std::string script;
};

// Runs `job` and moves its PNG to png_path, and then the extra formats beside it (the same
// stem, .svg / .pdf; each checked whole: </svg>, %%EOF). Throws std::runtime_error
// "<file>: ..." if gnuplot is missing ("gnuplot not found") or fails ("gnuplot failed: <its
// error line>").
void run_gnuplot(const std::string& png_path, const GnuplotJob& job);

// The formats every plot of this process is also written in ("svg", "pdf"; none by
// default): a command's --plot-format, set before it draws. Throws std::invalid_argument
// for another name (parse_plot_formats, plot.h, validates the option).
void set_extra_plot_formats(const std::vector<std::string>& formats);

// The gnuplot executable on PATH, or "" if there is none.
std::string find_gnuplot();

// A gnuplot single-quoted string literal ('' escapes a quote).
std::string gp_quote(const std::string& s);
// A number for a .dat file or a script; non-finite as "nan" (missing, see set datafile).
std::string gp_num(double v);
// [lo, hi] of the finite values (an axis range); false if there are none.
bool finite_range(const std::vector<double>& v, double& lo, double& hi);

}  // namespace pamsim
