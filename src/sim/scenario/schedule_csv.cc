// schedule_csv.cc: see schedule_csv.h.
#include "sim/scenario/schedule_csv.h"

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <utility>
#include <vector>

#include "base/input_error.h"
#include "base/toml_file.h"
#include "base/units.h"
#include "sim/io/csv_cells.h"
#include "sim/io/recording_csv.h"

namespace pamsim {

PressureSchedule read_schedule_csv(const std::string& path) {
  require_input_file(path);
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path + ": cannot open the schedule file");
  // a schedule is a few thousand points; anything near this is not one (or would eat memory)
  constexpr std::uintmax_t kMaxBytes = 64u << 20;
  std::error_code size_error;
  if (std::filesystem::file_size(path, size_error) > kMaxBytes && !size_error) {
    throw InputError(path + ": larger than 64 MiB, not a schedule");
  }
  std::vector<double> times_s, values_pa;
  std::string line;
  long line_no = 0;
  bool header = false;
  while (std::getline(in, line)) {
    ++line_no;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    const auto first = line.find_first_not_of(" \t");
    if (first == std::string::npos || line[first] == '#') continue;
    const std::string where = path + ": line " + std::to_string(line_no);

    // the header names the two columns and their units
    if (!header) {
      std::string h;
      for (char c : line)
        if (c != ' ' && c != '\t') h += c;
      if (h != "time_s,MPa") throw InputError(where + ": expected the header \"time_s,MPa\"");
      header = true;
      continue;
    }

    // time_s, MPa: finite numbers, time strictly increasing
    const auto comma = line.find(',');
    double t = 0.0, p = 0.0;
    if (comma == std::string::npos || line.find(',', comma + 1) != std::string::npos ||
        !parse_finite_cell(line.substr(0, comma), &t) ||
        !parse_finite_cell(line.substr(comma + 1), &p)) {
      throw InputError(where + ": expected two finite numbers \"time_s,MPa\"");
    }
    if (!times_s.empty() && !(t > times_s.back())) {
      char buf[96];
      std::snprintf(buf, sizeof(buf), "got %.9g s after %.9g s", t, times_s.back());
      throw InputError(where + ": time must increase strictly, " + buf);
    }
    times_s.push_back(t);
    values_pa.push_back(units::mpa_to_pa(p));
  }
  if (!header) throw InputError(path + ": empty file, expected the header \"time_s,MPa\"");
  if (times_s.empty()) throw InputError(path + ": no (time_s, MPa) rows");
  return table_schedule(std::move(times_s), std::move(values_pa), path);
}

PressureSchedule read_schedule_column(const std::string& path, const std::string& column,
                                      bool hold) {
  PressureSchedule s;
  if (column == "MPa") {
    s = read_schedule_csv(path);
  } else {
    const std::string suffix = "_MPa";
    if (column.size() <= suffix.size() ||
        column.compare(column.size() - suffix.size(), suffix.size(), suffix) != 0) {
      throw InputError(path + ": column " + column + " is not in MPa (its name must end _MPa)");
    }
    const Recording log = read_recording_csv(path);
    const std::size_t c = log.channel(column);
    if (c == log.channels.size()) throw InputError(path + ": has no column " + column);
    std::vector<double> times_s, values_pa;
    for (std::size_t row = 0; row < log.time_s.size(); ++row) {
      if (std::isnan(log.samples[c][row])) continue;
      times_s.push_back(log.time_s[row]);
      values_pa.push_back(units::mpa_to_pa(log.samples[c][row]));
    }
    s = table_schedule(std::move(times_s), std::move(values_pa), path);
  }
  s.column = column;
  s.hold = hold;
  return s;
}

}  // namespace pamsim
