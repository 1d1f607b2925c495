// html_page.h: self-contained HTML pages (`pamsim report --html`): text escaped, data for the
// page's script as JSON, figures as inline SVG (a heat map whose cells say where they lie, line
// charts of a trial's series), one stylesheet, and a footer saying what made the page. Nothing
// a page shows is fetched: it opens offline, from a file, and makes no request.
#pragma once

#include <cstddef>
#include <string>
#include <utility>
#include <vector>

#include "sim/core/trial_log.h"
#include "sim/io/plot.h"

namespace pamsim {

// The page `pamsim report --html` writes into a folder; a command that writes the folder's
// other files lists it among its outputs, so that its forced rerun leaves no stale page.
inline constexpr const char* kReportPageFile = "report.html";

// A coordinate as SVG takes it: one decimal.
std::string svg_number(double v);
// A number for a reader: four significant digits ("n/a" when not finite).
std::string short_number(double v);
// &, <, >, " and ' as entities.
std::string html_escape(const std::string& text);
// JSON text that may stand inside <script type="application/json">: every "</" written "<\/".
std::string json_for_script(const std::string& json_text);

// A heat map (plot.h's, as gnuplot draws it) as SVG with id `id`: a grid's cells, or a
// scattered design's points, coloured on one scale between the map's value range (grey where a
// cell has no value), each an element of class "cell" with data-map = id and data-ix, data-iy
// (grid) or data-i (scattered), and a <title> of its text; the marked cell outlined; a colour
// bar with the range's ends.
std::string svg_heat_map(const HeatMap& map, const std::string& id);

struct LineSeries {
  std::string label;
  std::vector<double> x, y;  // one length; NaN: a gap
  bool markers = false;      // a marker per value (its <title> "x: y"), not a line
};
struct LineChart {
  std::string title, x_label, y_label;
  std::vector<LineSeries> series;
};
// A line chart as SVG: the series as polylines (or markers, class "marker") on shared axes
// (their ranges, a few ticks), a legend of their labels.
std::string svg_line_chart(const LineChart& chart);

// A point's trials as charts: the joint's position (the log's column 1: angle_deg, or a
// pulley's position_mm) of each trial, a series per label; and the first trial's pressures,
// each muscle's commanded and chamber pressure (its p_cmd_<m>_MPa and p_<m>_MPa columns). Each
// series keeps at most `max_points` evenly spaced rows.
std::vector<LineChart> trial_charts(
    const std::vector<std::pair<std::string, const Trajectory*>>& trials,
    std::size_t max_points = 800);

// The page: its <head> (title, stylesheet), the body, the script and the footer.
std::string html_document(const std::string& title, const std::string& body,
                          const std::string& script, const std::string& footer);

}  // namespace pamsim
