// heatmap_plot.cc: write_heatmap of plot.h, a sweep metric over two axes.
#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "sim/io/gnuplot.h"
#include "sim/io/plot.h"

namespace pamsim {
namespace {

// Throws std::invalid_argument naming `png_path` when the map's sizes do not agree.
void check_heatmap(const std::string& png_path, const HeatMap& map) {
  const std::size_t nx = map.x_levels.size(), ny = map.y_levels.size();
  if (!map.scattered && map.cells.size() != nx * ny) {
    throw std::invalid_argument(png_path + ": heat map has " + std::to_string(map.cells.size()) +
                                " cells for " + std::to_string(nx) + " x " + std::to_string(ny) +
                                " levels");
  }
  if (!map.scattered && !map.cell_texts.empty() && map.cell_texts.size() != map.cells.size()) {
    throw std::invalid_argument(png_path + ": heat map has " +
                                std::to_string(map.cell_texts.size()) + " cell texts for " +
                                std::to_string(map.cells.size()) + " cells");
  }
  if (map.scattered && (map.x.size() != map.values.size() || map.y.size() != map.values.size())) {
    throw std::invalid_argument(png_path + ": heat map points and values differ in number");
  }
}

// The colour scale [*lo, *hi]: the map's bounds, else the data's; written as cbrange when
// both are known.
void colour_range(std::ostringstream& s, const HeatMap& map, double* lo, double* hi) {
  *lo = map.value_min;
  *hi = map.value_max;
  double data_lo, data_hi;
  const std::vector<double>& all = map.scattered ? map.values : map.cells;
  if (finite_range(all, data_lo, data_hi)) {
    if (!std::isfinite(*lo)) *lo = data_lo;
    if (!std::isfinite(*hi)) *hi = data_hi;
  }
  if (std::isfinite(*lo) && std::isfinite(*hi)) {
    if (*hi <= *lo) *hi = *lo + (*lo == 0 ? 1.0 : std::fabs(*lo) * 0.01);
    s << "set cbrange [" << gp_num(*lo) << ":" << gp_num(*hi) << "]\n";
  }
}

// A grid map: cells as boxes in index space, levels as tick labels, each cell's text or
// number on it. Returns cells.dat; the plot command (unfinished) goes to `s`.
std::string grid_cells(std::ostringstream& s, const HeatMap& map, double lo, double hi) {
  const std::size_t nx = map.x_levels.size(), ny = map.y_levels.size();
  std::string dat;
  for (std::size_t iy = 0; iy < ny; ++iy) {
    for (std::size_t ix = 0; ix < nx; ++ix) {
      const double v = map.cells[iy * nx + ix];
      if (!std::isfinite(v)) continue;
      dat += gp_num(ix) + " " + gp_num(iy) + " " + gp_num(v);
      // the cell's text as a quoted column (gnuplot reads "..." as one)
      if (!map.cell_texts.empty()) dat += " \"" + map.cell_texts[iy * nx + ix] + "\"";
      dat += "\n";
    }
  }
  auto tics = [](const char* axis, const std::vector<std::string>& levels) {
    std::string t = std::string("set ") + axis + "tics (";
    for (std::size_t i = 0; i < levels.size(); ++i) {
      t += (i ? ", " : "") + gp_quote(levels[i]) + " " + std::to_string(i);
    }
    return t + ")\n";
  };
  s << tics("x", map.x_levels) << tics("y", map.y_levels)
    << (nx > 8 ? "set xtics rotate by 45 right\n" : "") << "set xrange [-0.5:" << gp_num(nx - 0.5)
    << "]\nset yrange [-0.5:" << gp_num(ny - 0.5) << "]\n"
    << "set tics scale 0\n";
  s << "plot 'cells.dat' using 1:2:(0.5):(0.5):3 with boxxyerror fc palette fs solid 1.0 "
       "border lc rgb 'white' notitle";
  if (!map.cell_format.empty() || !map.cell_texts.empty()) {
    // white text on the dark half of the palette, black on the light half
    const int font = nx * ny > 200 ? 7 : 9;
    const std::string mid = gp_num(std::isfinite(lo) && std::isfinite(hi) ? (lo + hi) / 2 : 0.0);
    const std::string text = map.cell_texts.empty()
                                 ? "sprintf(" + gp_quote(map.cell_format) + ", $3)"
                                 : "stringcolumn(4)";
    for (const auto& [test, colour] : {std::pair{"<", "white"}, {">=", "black"}}) {
      s << ", 'cells.dat' using 1:2:($3 " << test << " " << mid << " ? " << text
        << " : '') with labels font '," << font << "' tc rgb '" << colour << "' notitle";
    }
  }
  return dat;
}

// A scattered map: a point per value. Returns cells.dat; the plot command (unfinished)
// goes to `s`.
std::string scattered_points(std::ostringstream& s, const HeatMap& map) {
  std::string dat;
  for (std::size_t i = 0; i < map.values.size(); ++i) {
    dat += gp_num(map.x[i]) + " " + gp_num(map.y[i]) + " " + gp_num(map.values[i]) + "\n";
  }
  s << (map.x_log ? "set logscale x\n" : "") << (map.y_log ? "set logscale y\n" : "")
    << "set grid\nplot 'cells.dat' using 1:2:3 with points pt 7 ps 1.6 lc palette notitle";
  return dat;
}

}  // namespace

void write_heatmap(const std::string& png_path, const HeatMap& map) {
  check_heatmap(png_path, map);
  GnuplotJob job;
  job.width_px = kHeatMapWidthPx;
  job.height_px = kHeatMapHeightPx;
  std::ostringstream s;
  s << "set encoding utf8\nset title " << gp_quote(map.title) << " font ',14'\n"
    << "set xlabel " << gp_quote(map.x_label) << "\nset ylabel " << gp_quote(map.y_label) << "\n"
    << "set cblabel " << gp_quote(map.value_label)
    << "\n"
    // viridis: dark is low, yellow is high; no data is grey
    << "set palette defined (0 '#440154', 0.25 '#3b528b', 0.5 '#21918c', 0.75 '#5ec962', "
       "1 '#fde725')\n"
    << "set object 1 rectangle from graph 0,0 to graph 1,1 behind fc rgb '#d0d0d0' fs solid "
       "noborder\n"
    << "set key outside bottom center horizontal\n";
  double lo, hi;
  colour_range(s, map, &lo, &hi);

  // the data, then the marked point and the key for cells without data
  std::string dat = map.scattered ? scattered_points(s, map) : grid_cells(s, map, lo, hi);
  const std::string mark_plot =
      map.scattered
          ? "'mark.dat' using 1:2 with points pt 6 ps 3 lw 3 lc rgb '#e31a1c'"
          : "'mark.dat' using 1:2:(0.5):(0.5) with boxxyerror fs empty border lc rgb '#e31a1c' "
            "lw 3";
  if (map.has_mark) {
    job.data_files.emplace_back("mark.dat", gp_num(map.mark_x) + " " + gp_num(map.mark_y) + "\n");
    s << ", " << mark_plot << " title " << gp_quote(map.mark_label);
  }
  const bool any_missing =
      !map.scattered &&
      std::any_of(map.cells.begin(), map.cells.end(), [](double v) { return !std::isfinite(v); });
  if (any_missing && !map.missing_label.empty()) {
    s << ", keyentry with boxes fc rgb '#d0d0d0' fs solid 1.0 title "
      << gp_quote(map.missing_label);
  }
  s << "\n";
  if (dat.empty()) dat = "nan nan nan\n";  // nothing to colour: gnuplot still draws the axes
  job.data_files.emplace_back("cells.dat", dat);
  job.script = s.str();
  run_gnuplot(png_path, job);
}

}  // namespace pamsim
