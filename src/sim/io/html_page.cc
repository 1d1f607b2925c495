// html_page.cc: see html_page.h.
#include "sim/io/html_page.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <limits>
#include <sstream>

#include "base/format.h"

namespace pamsim {
namespace {

// A value's colour between lo and hi: viridis through five of its stops
std::string colour(double v, double lo, double hi) {
  if (!std::isfinite(v)) return "#c8c8c8";
  static const std::array<std::array<double, 3>, 5> kStops = {
      {{68, 1, 84}, {59, 82, 139}, {33, 145, 140}, {94, 201, 98}, {253, 231, 37}}};
  double u = hi > lo ? (v - lo) / (hi - lo) : 0.5;
  u = std::clamp(u, 0.0, 1.0) * 4.0;
  const auto k = std::min(static_cast<std::size_t>(u), std::size_t{3});
  const double f = u - static_cast<double>(k);
  char buf[8];
  int c[3];
  for (int i = 0; i < 3; ++i) {
    c[i] = static_cast<int>(std::lround(kStops[k][i] + f * (kStops[k + 1][i] - kStops[k][i])));
  }
  std::snprintf(buf, sizeof(buf), "#%02x%02x%02x", c[0], c[1], c[2]);
  return buf;
}

// The finite range of `values`, or of the map's own range where it gives one
std::pair<double, double> value_range(const HeatMap& map, const std::vector<double>& values) {
  double lo = map.value_min, hi = map.value_max;
  for (double v : values) {
    if (!std::isfinite(v)) continue;
    if (!std::isfinite(map.value_min)) lo = std::isfinite(lo) ? std::min(lo, v) : v;
    if (!std::isfinite(map.value_max)) hi = std::isfinite(hi) ? std::max(hi, v) : v;
  }
  if (!std::isfinite(lo) || !std::isfinite(hi)) return {0.0, 1.0};
  return {lo, hi};
}

std::string colour_bar(double lo, double hi, double x, double y, const std::string& label) {
  std::ostringstream s;
  for (int k = 0; k < 20; ++k) {
    s << "<rect x=\"" << svg_number(x + 12.0 * k) << "\" y=\"" << svg_number(y)
      << "\" width=\"12\" "
      << "height=\"10\" fill=\"" << colour(lo + (hi - lo) * (k + 0.5) / 20, lo, hi) << "\"/>";
  }
  s << "<text x=\"" << svg_number(x) << "\" y=\"" << svg_number(y + 24) << "\">" << short_number(lo)
    << "</text><text x=\"" << svg_number(x + 240) << "\" y=\"" << svg_number(y + 24)
    << "\" text-anchor=\"end\">" << short_number(hi) << "</text><text x=\"" << svg_number(x + 250)
    << "\" y=\"" << svg_number(y + 9) << "\">" << html_escape(label) << "</text>";
  return s.str();
}

std::string grid_cells(const HeatMap& map, const std::string& id, double x0, double y0, double w,
                       double h, std::pair<double, double> range) {
  std::ostringstream s;
  const std::size_t nx = map.x_levels.size(), ny = map.y_levels.size();
  for (std::size_t iy = 0; iy < ny; ++iy) {
    for (std::size_t ix = 0; ix < nx; ++ix) {
      const std::size_t c = iy * nx + ix;
      const double v =
          c < map.cells.size() ? map.cells[c] : std::numeric_limits<double>::quiet_NaN();
      const std::string text = c < map.cell_texts.size() ? map.cell_texts[c] : short_number(v);
      const bool marked = map.has_mark && map.mark_x == ix && map.mark_y == iy;
      s << "<rect class=\"cell" << (marked ? " marked" : "") << "\" data-map=\"" << id
        << "\" data-ix=\"" << ix << "\" data-iy=\"" << iy << "\" x=\"" << svg_number(x0 + ix * w)
        << "\" y=\"" << svg_number(y0 + (ny - 1 - iy) * h) << "\" width=\"" << svg_number(w)
        << "\" height=\"" << svg_number(h) << "\" fill=\"" << colour(v, range.first, range.second)
        << "\"><title>" << html_escape(text) << "</title></rect>";
    }
  }
  for (std::size_t ix = 0; ix < nx; ++ix) {
    s << "<text x=\"" << svg_number(x0 + (ix + 0.5) * w) << "\" y=\""
      << svg_number(y0 + ny * h + 14) << "\" text-anchor=\"middle\">"
      << html_escape(map.x_levels[ix]) << "</text>";
  }
  for (std::size_t iy = 0; iy < ny; ++iy) {
    s << "<text x=\"" << svg_number(x0 - 4) << "\" y=\""
      << svg_number(y0 + (ny - 1 - iy + 0.5) * h + 4) << "\" text-anchor=\"end\">"
      << html_escape(map.y_levels[iy]) << "</text>";
  }
  return s.str();
}

// where a scattered value lies along an axis of [lo, hi] drawn over `length` pixels
double place(double v, double lo, double hi, bool log, double length) {
  if (log) v = std::log10(v), lo = std::log10(lo), hi = std::log10(hi);
  return hi > lo ? (v - lo) / (hi - lo) * length : 0.5 * length;
}

std::string scattered_points(const HeatMap& map, const std::string& id, double x0, double y0,
                             double width, double height, std::pair<double, double> range) {
  if (map.x.empty()) return "";
  const auto [xlo, xhi] = std::minmax_element(map.x.begin(), map.x.end());
  const auto [ylo, yhi] = std::minmax_element(map.y.begin(), map.y.end());
  constexpr double kInset = 10;  // the markers kept off the frame
  std::ostringstream s;
  s << "<rect x=\"" << svg_number(x0) << "\" y=\"" << svg_number(y0) << "\" width=\""
    << svg_number(width) << "\" height=\"" << svg_number(height)
    << "\" fill=\"none\" stroke=\"#888\"/>";
  for (std::size_t i = 0; i < map.x.size(); ++i) {
    const double px = x0 + kInset + place(map.x[i], *xlo, *xhi, map.x_log, width - 2 * kInset);
    const double py =
        y0 + height - kInset - place(map.y[i], *ylo, *yhi, map.y_log, height - 2 * kInset);
    const bool marked = map.has_mark && map.x[i] == map.mark_x && map.y[i] == map.mark_y;
    s << "<circle class=\"cell" << (marked ? " marked" : "") << "\" data-map=\"" << id
      << "\" data-i=\"" << i << "\" cx=\"" << svg_number(px) << "\" cy=\"" << svg_number(py)
      << "\" r=\"6\" fill=\"" << colour(map.values[i], range.first, range.second) << "\"><title>"
      << html_escape(short_number(map.values[i])) << "</title></circle>";
  }
  s << "<text x=\"" << svg_number(x0) << "\" y=\"" << svg_number(y0 + height + 14) << "\">"
    << short_number(*xlo) << "</text><text x=\"" << svg_number(x0 + width) << "\" y=\""
    << svg_number(y0 + height + 14) << "\" text-anchor=\"end\">" << short_number(*xhi)
    << "</text><text x=\"" << svg_number(x0 - 4) << "\" y=\"" << svg_number(y0 + height)
    << "\" text-anchor=\"end\">" << short_number(*ylo) << "</text><text x=\"" << svg_number(x0 - 4)
    << "\" y=\"" << svg_number(y0 + 10) << "\" text-anchor=\"end\">" << short_number(*yhi)
    << "</text>";
  return s.str();
}

}  // namespace

std::string svg_number(double v) {
  char buf[32];
  std::snprintf(buf, sizeof(buf), "%.1f", v);
  return buf;
}

std::string short_number(double v) {
  if (!std::isfinite(v)) return "n/a";
  char buf[32];
  std::snprintf(buf, sizeof(buf), "%.4g", v);
  return buf;
}

std::string html_escape(const std::string& text) {
  std::string out;
  for (const char c : text) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      case '\'':
        out += "&#39;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

std::string json_for_script(const std::string& json_text) {
  std::string out;
  for (std::size_t i = 0; i < json_text.size(); ++i) {
    out += json_text[i];
    if (json_text[i] == '<' && i + 1 < json_text.size() && json_text[i + 1] == '/') out += '\\';
  }
  return out;
}

std::string svg_heat_map(const HeatMap& map, const std::string& id) {
  const bool grid = !map.scattered;
  const std::size_t nx = grid ? std::max<std::size_t>(map.x_levels.size(), 1) : 10;
  const std::size_t ny = grid ? std::max<std::size_t>(map.y_levels.size(), 1) : 8;
  const double w = std::clamp(480.0 / nx, 24.0, 64.0), h = std::clamp(320.0 / ny, 18.0, 48.0);
  const double x0 = 70, y0 = 48, width = w * nx, height = h * ny;
  const auto range = value_range(map, grid ? map.cells : map.values);
  std::ostringstream s;
  s << "<svg class=\"heatmap\" id=\"" << id << "\" width=\""
    << svg_number(std::max(x0 + width + 20, 560.0)) << "\" height=\""
    << svg_number(y0 + height + 80) << "\"><text x=\"4\" y=\"16\" class=\"title\">"
    << html_escape(map.title) << "</text><text x=\"4\" y=\"34\">y: " << html_escape(map.y_label)
    << "</text>"
    << (grid ? grid_cells(map, id, x0, y0, w, h, range)
             : scattered_points(map, id, x0, y0, width, height, range))
    << "<text x=\"" << svg_number(x0) << "\" y=\"" << svg_number(y0 + height + 32)
    << "\">x: " << html_escape(map.x_label) << "</text>"
    << colour_bar(range.first, range.second, x0, y0 + height + 44, "") << "</svg>";
  return s.str();
}

}  // namespace pamsim
