// readings_csv.cc: readings.csv written losslessly, and a controller's input stream read
// from it or from a log with the same columns.
#include "sim/io/readings_csv.h"

#include <map>
#include <sstream>

#include "base/atomic_file.h"
#include "base/format.h"
#include "base/input_error.h"
#include "base/no_value.h"
#include "sim/io/csv_cells.h"

namespace pamsim {
// (a named namespace: the unity build joins this file with others of src/sim/io)
namespace readings_csv_cells {

// a column's position, or -1 when the header lacks it
using Header = std::map<std::string, int>;
int column(const Header& header, const std::string& name) {
  const auto it = header.find(name);
  return it == header.end() ? -1 : it->second;
}

// one quantity's column, in SI or in the papers' unit (`factor` to SI)
struct Source {
  int index = -1;
  double factor = 1.0;
  std::string name;
};
Source either(const Header& header, const std::string& si, const std::string& paper,
              double factor) {
  if (column(header, si) >= 0) return {column(header, si), 1.0, si};
  if (column(header, paper) >= 0) return {column(header, paper), factor, paper};
  return {};
}

Source required(const Header& header, const std::string& name, const std::string& path,
                const std::string& what) {
  if (column(header, name) < 0) throw InputError(path + ": no column " + name + " (" + what + ")");
  return {column(header, name), 1.0, name};
}

struct MuscleSources {
  Source pressure, gauge, fiber, p_tp, p_cmd;
};

// a cell as a number: a reading may be missing (nan, empty), nothing else may
double cell_value(const std::string& cell, const Source& s, int line, const std::string& path,
                  bool may_be_missing, int* missing) {
  double v = 0.0;
  if (parse_finite_cell(cell, &v)) return v * s.factor;
  const std::string t = trim_cell(cell);
  if (may_be_missing && (t.empty() || t == "nan" || t == "NaN" || t == "-nan")) {
    ++*missing;
    return kNaN;
  }
  throw InputError(path + ": line " + std::to_string(line) + ", column " + s.name + ": '" + t +
                   "' is not a number" +
                   (may_be_missing ? " (nan or empty: a missing reading)" : ""));
}

Header read_header(const std::string& line, const std::string& path) {
  Header header;
  const std::vector<std::string> names = split_csv_line(line);
  for (std::size_t k = 0; k < names.size(); ++k) {
    const std::string name = trim_cell(names[k]);
    if (!header.emplace(name, static_cast<int>(k)).second) {
      throw InputError(path + ": line 1: column " + name + " appears twice");
    }
  }
  return header;
}

MuscleSources muscle_sources(const Header& h, const std::string& m, const std::string& path) {
  MuscleSources s;
  const std::string what = "the readings of muscle " + m;
  s.pressure = required(h, "pressure_sensor_" + m + "_V", path, what);
  s.gauge = required(h, "gauge_" + m + "_V", path, what);
  s.fiber = either(h, "fiber_rate_" + m + "_m_s", "fiber_rate_" + m + "_mm_s", 1e-3);
  s.p_tp = either(h, "p_tp_" + m + "_Pa", "p_tp_" + m + "_MPa", 1e6);
  s.p_cmd = either(h, "p_cmd_" + m + "_Pa", "p_cmd_" + m + "_MPa", 1e6);
  return s;
}

// one row's cells into the stream
void read_row(const std::vector<std::string>& cells, int line, const std::string& path,
              const Source& time, const Source& enabled, const std::vector<MuscleSources>& src,
              ControlStream* out) {
  int ignored = 0;
  out->time_s.push_back(cell_value(cells[time.index], time, line, path, false, &ignored));
  char on = 1;
  if (enabled.index >= 0) {
    const double e = cell_value(cells[enabled.index], enabled, line, path, false, &ignored);
    if (e != 0.0 && e != 1.0) {
      throw InputError(path + ": line " + std::to_string(line) +
                       ", column enabled: must be 0 "
                       "or 1, got " +
                       format_value(e));
    }
    on = e == 1.0 ? 1 : 0;
  }
  out->enabled.push_back(on);
  int* missing = &out->missing_readings;
  for (std::size_t j = 0; j < src.size(); ++j) {
    const MuscleSources& s = src[j];
    MuscleStream& m = out->muscles[j];
    m.pressure_v.push_back(
        cell_value(cells[s.pressure.index], s.pressure, line, path, true, missing));
    m.gauge_v.push_back(cell_value(cells[s.gauge.index], s.gauge, line, path, true, missing));
    m.fiber_rate_m_s.push_back(
        s.fiber.index < 0 ? 0.0
                          : cell_value(cells[s.fiber.index], s.fiber, line, path, true, missing));
    if (s.p_tp.index >= 0) {
      m.p_tp_pa.push_back(cell_value(cells[s.p_tp.index], s.p_tp, line, path, false, &ignored));
    }
    if (s.p_cmd.index >= 0) {
      m.p_cmd_pa.push_back(cell_value(cells[s.p_cmd.index], s.p_cmd, line, path, true, &ignored));
    }
  }
}

}  // namespace readings_csv_cells

using namespace readings_csv_cells;

std::vector<std::string> readings_columns(const std::vector<std::string>& muscles) {
  std::vector<std::string> names = {"time_s", "enabled"};
  for (const std::string& m : muscles) {
    for (const char* c :
         {"pressure_sensor_%_V", "gauge_%_V", "fiber_rate_%_m_s", "p_tp_%_Pa", "p_cmd_%_Pa"}) {
      std::string name = c;
      name.replace(name.find('%'), 1, m);
      names.push_back(name);
    }
  }
  return names;
}

void write_readings_csv(const std::string& path, const std::vector<std::string>& muscles,
                        const ControlLog& log) {
  // the header, then one row per tick in the log's own order: shortest exact decimals
  std::ostringstream text;
  const std::vector<std::string> names = readings_columns(muscles);
  for (std::size_t k = 0; k < names.size(); ++k) text << (k ? "," : "") << names[k];
  text << "\n";
  const std::size_t width = names.size();
  for (std::size_t row = 0; row < log.ticks(); ++row) {
    for (std::size_t k = 0; k < width; ++k) {
      const double v = log.values[row * width + k];
      text << (k ? "," : "") << (k == 1 ? std::to_string(static_cast<int>(v)) : format_shortest(v));
    }
    text << "\n";
  }
  write_file_atomically(path, text.str());
}

ControlStream read_control_stream(const std::string& text, const std::string& path,
                                  const std::vector<std::string>& muscles) {
  std::istringstream in(text);
  std::string line;
  if (!std::getline(in, line)) throw InputError(path + ": empty (no header row)");
  const Header header = read_header(line, path);
  const Source time = required(header, "time_s", path, "the tick's time");
  const Source enabled = {column(header, "enabled"), 1.0, "enabled"};
  std::vector<MuscleSources> sources;
  for (const std::string& m : muscles) sources.push_back(muscle_sources(header, m, path));

  ControlStream out;
  out.has_enabled = enabled.index >= 0;
  out.muscles.resize(muscles.size());
  for (int number = 2; std::getline(in, line); ++number) {
    if (trim_cell(line).empty()) continue;
    const std::vector<std::string> cells = split_csv_line(line);
    if (cells.size() != header.size()) {
      throw InputError(path + ": line " + std::to_string(number) + " has " +
                       std::to_string(cells.size()) + " cells, the header has " +
                       std::to_string(header.size()) + " columns");
    }
    read_row(cells, number, path, time, enabled, sources, &out);
  }
  if (out.time_s.empty()) throw InputError(path + ": no rows after the header");
  return out;
}

}  // namespace pamsim
