// html_chart.cc: the line charts and the page frame of html_page.h.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "base/format.h"
#include "sim/io/html_page.h"

namespace pamsim {
namespace {

constexpr double kWidth = 640, kHeight = 220, kLeft = 60, kTop = 28, kRight = 150, kBottom = 40;
const char* const kLineColours[] = {"#1f77b4", "#d62728", "#2ca02c", "#9467bd",
                                    "#ff7f0e", "#8c564b", "#17becf", "#7f7f7f"};

// The finite range of the series' values (x or y), widened when flat
std::pair<double, double> range_of(const LineChart& c, bool y) {
  double lo = INFINITY, hi = -INFINITY;
  for (const LineSeries& s : c.series) {
    for (double v : y ? s.y : s.x) {
      if (std::isfinite(v)) lo = std::min(lo, v), hi = std::max(hi, v);
    }
  }
  if (!(lo <= hi)) return {0.0, 1.0};
  if (hi - lo < 1e-12 * std::max(1.0, std::abs(hi))) return {lo - 0.5, hi + 0.5};
  return {lo, hi};
}

// Ticks at a round step, about five over [lo, hi]
std::vector<double> ticks(double lo, double hi) {
  const double raw = (hi - lo) / 4.0;
  const double mag = std::pow(10.0, std::floor(std::log10(raw)));
  double step = mag;
  for (double m : {1.0, 2.0, 5.0, 10.0}) {
    if (m * mag >= raw) {
      step = m * mag;
      break;
    }
  }
  std::vector<double> t;
  // (bounded: a step below the values' resolution would not advance)
  for (double v = std::ceil(lo / step) * step; v <= hi + 1e-9 * step && t.size() < 12; v += step) {
    t.push_back(v);
  }
  return t;
}

std::string axes(const LineChart& c, std::pair<double, double> xr, std::pair<double, double> yr) {
  std::ostringstream s;
  const double pw = kWidth - kLeft - kRight, ph = kHeight - kTop - kBottom;
  s << "<rect x=\"" << kLeft << "\" y=\"" << kTop << "\" width=\"" << pw << "\" height=\"" << ph
    << "\" fill=\"none\" stroke=\"#888\"/>";
  for (double t : ticks(xr.first, xr.second)) {
    const double x = kLeft + (t - xr.first) / (xr.second - xr.first) * pw;
    s << "<text x=\"" << svg_number(x) << "\" y=\"" << svg_number(kTop + ph + 14)
      << "\" text-anchor=\"middle\">" << short_number(t) << "</text>";
  }
  for (double t : ticks(yr.first, yr.second)) {
    const double y = kTop + ph - (t - yr.first) / (yr.second - yr.first) * ph;
    s << "<text x=\"" << svg_number(kLeft - 4) << "\" y=\"" << svg_number(y + 4)
      << "\" text-anchor=\"end\">" << short_number(t) << "</text>";
  }
  s << "<text x=\"" << svg_number(kLeft + pw / 2) << "\" y=\"" << svg_number(kHeight - 6)
    << "\" text-anchor=\"middle\">" << html_escape(c.x_label) << "</text><text x=\"" << kLeft
    << "\" y=\"16\" class=\"title\">" << html_escape(c.title + " [" + c.y_label + "]") << "</text>";
  return s.str();
}

// A series as markers, each with its values as its title; its label in the legend
std::string markers(const LineSeries& ls, const char* col, std::pair<double, double> xr,
                    std::pair<double, double> yr) {
  const double pw = kWidth - kLeft - kRight, ph = kHeight - kTop - kBottom;
  std::ostringstream s;
  for (std::size_t i = 0; i < ls.x.size() && i < ls.y.size(); ++i) {
    if (!std::isfinite(ls.x[i]) || !std::isfinite(ls.y[i])) continue;
    s << "<circle class=\"marker\" r=\"3\" fill=\"" << col << "\" cx=\""
      << svg_number(kLeft + (ls.x[i] - xr.first) / (xr.second - xr.first) * pw) << "\" cy=\""
      << svg_number(kTop + ph - (ls.y[i] - yr.first) / (yr.second - yr.first) * ph) << "\"><title>"
      << short_number(ls.x[i]) << ": " << short_number(ls.y[i]) << "</title></circle>";
  }
  return s.str();
}

}  // namespace

std::string svg_line_chart(const LineChart& c) {
  const auto xr = range_of(c, false), yr = range_of(c, true);
  const double pw = kWidth - kLeft - kRight, ph = kHeight - kTop - kBottom;
  std::ostringstream s;
  s << "<svg class=\"chart\" width=\"" << kWidth << "\" height=\"" << kHeight << "\">"
    << axes(c, xr, yr);
  for (std::size_t k = 0; k < c.series.size(); ++k) {
    const LineSeries& ls = c.series[k];
    const char* col = kLineColours[k % std::size(kLineColours)];
    if (ls.markers) {
      s << markers(ls, col, xr, yr);
    } else {
      s << "<polyline class=\"series\" fill=\"none\" stroke=\"" << col << "\" points=\"";
      for (std::size_t i = 0; i < ls.x.size() && i < ls.y.size(); ++i) {
        if (!std::isfinite(ls.x[i]) || !std::isfinite(ls.y[i])) continue;
        s << svg_number(kLeft + (ls.x[i] - xr.first) / (xr.second - xr.first) * pw) << ','
          << svg_number(kTop + ph - (ls.y[i] - yr.first) / (yr.second - yr.first) * ph) << ' ';
      }
      s << "\"><title>" << html_escape(ls.label) << "</title></polyline>";
    }
    s << "<text x=\"" << svg_number(kWidth - kRight + 8) << "\" y=\""
      << svg_number(kTop + 12 + 14.0 * k) << "\" style=\"fill:" << col << "\">"
      << html_escape(ls.label) << "</text>";
  }
  s << "</svg>";
  return s.str();
}

namespace {

// Column `col` of `t` against its time, every k-th row so that at most max_points remain
LineSeries column_series(const Trajectory& t, std::size_t col, const std::string& label,
                         std::size_t max_points) {
  LineSeries s;
  s.label = label;
  const std::size_t step = std::max<std::size_t>(1, (t.rows() + max_points - 1) / max_points);
  for (std::size_t r = 0; r < t.rows(); r += step) {
    s.x.push_back(t.at(r, 0));
    s.y.push_back(t.at(r, col));
  }
  return s;
}

}  // namespace

std::vector<LineChart> trial_charts(
    const std::vector<std::pair<std::string, const Trajectory*>>& trials, std::size_t max_points) {
  if (trials.empty() || trials.front().second->columns.size() < 2) return {};
  const Trajectory& first = *trials.front().second;
  LineChart position{"joint", "time [s]", first.columns[1], {}};
  for (const auto& [label, t] : trials) {
    position.series.push_back(column_series(*t, 1, label, max_points));
  }
  LineChart pressures{"pressures, " + trials.front().first, "time [s]", "MPa", {}};
  for (std::size_t c = 0; c < first.columns.size(); ++c) {
    const std::string& name = first.columns[c];
    const bool commanded = name.rfind("p_cmd_", 0) == 0;
    const bool chamber = !commanded && name.rfind("p_", 0) == 0 && name.size() > 6 &&
                         name.compare(name.size() - 4, 4, "_MPa") == 0 &&
                         name.find("_meas_") == std::string::npos;
    if (commanded || chamber) pressures.series.push_back(column_series(first, c, name, max_points));
  }
  std::vector<LineChart> charts = {position};
  if (!pressures.series.empty()) charts.push_back(pressures);
  return charts;
}

std::string html_document(const std::string& title, const std::string& body,
                          const std::string& script, const std::string& footer) {
  std::ostringstream s;
  s << "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><title>"
    << html_escape(title)
    << "</title><style>\n"
       "body{font-family:sans-serif;margin:1.5em;max-width:72em;color:#222}\n"
       "svg text{font-size:11px;fill:#222} svg text.title{font-size:13px;font-weight:bold}\n"
       ".cell{cursor:pointer} .cell.marked{stroke:#d62728;stroke-width:3}\n"
       ".cell:hover{stroke:#000;stroke-width:2}\n"
       "#tip{position:fixed;background:#fff;border:1px solid #888;padding:.5em;font-size:12px;"
       "max-width:36em;box-shadow:2px 2px 6px #0003;pointer-events:none}\n"
       "table{border-collapse:collapse;font-size:12px} td,th{border:1px solid #ccc;"
       "padding:2px 6px} code{font-size:12px}\n"
       "footer{margin-top:2em;font-size:11px;color:#555} img{max-width:100%}\n"
       "</style></head><body>\n"
    << body << "\n<div id=\"tip\" hidden></div>\n<footer>" << footer << "</footer>\n<script>\n"
    << script << "\n</script></body></html>\n";
  return s.str();
}

}  // namespace pamsim
