// recording_csv.cc: see recording_csv.h.
#include "sim/io/recording_csv.h"

#include <cmath>
#include <fstream>
#include <limits>
#include <set>

#include "base/format.h"
#include "base/input_error.h"
#include "base/toml_file.h"
#include "sim/io/csv_cells.h"

namespace pamsim {
namespace {

// The header: time_s and the channels, each named once.
void read_header(const std::string& line, const std::string& where, Recording* r,
                 std::size_t* time_column) {
  const std::vector<std::string> names = split_csv_line(line);
  std::set<std::string> seen;
  *time_column = names.size();
  for (std::size_t i = 0; i < names.size(); ++i) {
    const std::string name = trim_cell(names[i]);
    if (name.empty())
      throw InputError(where + ": column " + std::to_string(i + 1) + " has no name");
    if (!seen.insert(name).second) throw InputError(where + ": column " + name + " is named twice");
    if (name == "time_s")
      *time_column = i;
    else
      r->channels.push_back(name);
  }
  if (*time_column == names.size()) {
    throw InputError(where + ": the header has no time_s column (columns: " + trim_cell(line) +
                     ")");
  }
  if (r->channels.empty()) throw InputError(where + ": the header names no channel besides time_s");
  r->samples.resize(r->channels.size());
}

// One row: its time (increasing, >= 0) and a number or an empty cell per channel.
void read_row(const std::string& line, const std::string& where, std::size_t time_column,
              const std::vector<std::string>& header, Recording* r) {
  const std::vector<std::string> cells = split_csv_line(line);
  if (cells.size() != header.size()) {
    throw InputError(where + ": " + std::to_string(cells.size()) + " cells, the header has " +
                     std::to_string(header.size()));
  }
  double t = 0.0;
  if (!parse_finite_cell(cells[time_column], &t)) {
    throw InputError(where + ": time_s must be a finite number, got \"" +
                     trim_cell(cells[time_column]) + "\"");
  }
  if (t < 0.0) throw InputError(where + ": time_s must be >= 0, got " + format_value(t));
  if (!r->time_s.empty() && !(t > r->time_s.back())) {
    throw InputError(where + ": time_s must increase strictly, got " + format_value(t) +
                     " s after " + format_value(r->time_s.back()) + " s");
  }
  r->time_s.push_back(t);
  std::size_t c = 0;
  for (std::size_t i = 0; i < cells.size(); ++i) {
    if (i == time_column) continue;
    double v = std::numeric_limits<double>::quiet_NaN();
    if (!trim_cell(cells[i]).empty() && !parse_finite_cell(cells[i], &v)) {
      throw InputError(where + ": " + r->channels[c] + " must be a finite number or empty, got \"" +
                       trim_cell(cells[i]) + "\"");
    }
    r->samples[c++].push_back(v);
  }
}

}  // namespace

std::size_t Recording::channel(const std::string& name) const {
  for (std::size_t c = 0; c < channels.size(); ++c) {
    if (channels[c] == name) return c;
  }
  return channels.size();
}

std::size_t Recording::sample_count(std::size_t c) const {
  std::size_t n = 0;
  for (double v : samples[c]) n += std::isnan(v) ? 0 : 1;
  return n;
}

Recording read_recording_csv(const std::string& path) {
  require_input_file(path);
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path + ": cannot open the recording");
  Recording r;
  r.path = path;
  std::vector<std::string> header;
  std::size_t time_column = 0;
  std::string line;
  long line_no = 0;
  while (std::getline(in, line)) {
    ++line_no;
    const std::string trimmed = trim_cell(line);
    if (trimmed.empty() || trimmed[0] == '#') continue;
    const std::string where = path + ": line " + std::to_string(line_no);
    if (header.empty()) {
      read_header(line, where, &r, &time_column);
      header = split_csv_line(line);
    } else {
      read_row(line, where, time_column, header, &r);
    }
  }
  if (header.empty()) throw InputError(path + ": empty file, expected a header with time_s");
  if (r.time_s.size() < 2) throw InputError(path + ": fewer than two rows of samples");
  for (std::size_t c = 0; c < r.channels.size(); ++c) {
    if (r.sample_count(c) == 0) throw InputError(path + ": " + r.channels[c] + " has no samples");
  }
  return r;
}

}  // namespace pamsim
