// tensile_csv.cc: write and read tensile-test CSV files, see tensile_csv.h.
#include "pam_actuator/tensile_csv.h"

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include "base/format.h"
#include "base/input_error.h"
#include "base/toml_file.h"

namespace pamsim {
namespace {

constexpr const char* kRequired[] = {"pressure_MPa", "deformation_mm", "force_N", "length_mm"};

std::string trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t\r");
  if (b == std::string::npos) return "";
  const auto e = s.find_last_not_of(" \t\r");
  return s.substr(b, e - b + 1);
}

std::vector<std::string> split(const std::string& line) {
  std::vector<std::string> cells;
  std::stringstream in(line);
  std::string cell;
  while (std::getline(in, cell, ',')) cells.push_back(trim(cell));
  if (!line.empty() && line.back() == ',') cells.emplace_back();
  return cells;
}

// a finite decimal number, the whole cell consumed (strtod also reads hexadecimal floats
// and "inf"/"nan", which no instrument writes: refused)
double parse_cell(const std::string& cell, const std::string& where) {
  if (cell.empty()) throw InputError(where + ": empty cell, a number is required");
  if (cell.find_first_not_of("0123456789+-.eE") != std::string::npos) {
    throw InputError(where + ": \"" + cell + "\" is not a decimal number");
  }
  char* end = nullptr;
  const double v = std::strtod(cell.c_str(), &end);
  if (end != cell.c_str() + cell.size()) {
    throw InputError(where + ": \"" + cell + "\" is not a number");
  }
  if (!std::isfinite(v)) {
    throw InputError(where + ": \"" + cell + "\" is not finite");
  }
  return v;
}

// where the columns are: kRequired's, in its order, and the optional direction (-1: none)
struct Columns {
  int required[4];
  int direction = -1;
};

// Throws InputError naming `path` for a column named twice or a required one missing.
Columns locate_columns(const std::string& path, const std::vector<std::string>& header) {
  for (size_t c = 0; c < header.size(); ++c) {
    for (size_t d = 0; d < c; ++d) {
      if (!header[c].empty() && header[c] == header[d]) {
        throw InputError(path + ": header: column " + header[c] + " appears twice (columns " +
                         std::to_string(d + 1) + " and " + std::to_string(c + 1) + ")");
      }
    }
  }
  Columns columns;
  int* col = columns.required;
  for (int k = 0; k < 4; ++k) {
    col[k] = -1;
    for (size_t c = 0; c < header.size(); ++c) {
      if (header[c] == kRequired[k]) col[k] = static_cast<int>(c);
    }
    if (col[k] < 0) {
      throw InputError(path + ": header: missing column " + kRequired[k] +
                       " (required: pressure_MPa, deformation_mm, force_N, length_mm)");
    }
  }
  for (size_t c = 0; c < header.size(); ++c) {
    if (header[c] == "direction") columns.direction = static_cast<int>(c);
  }
  return columns;
}

}  // namespace

std::string tensile_rows_to_csv(const std::vector<TensileRow>& rows) {
  std::string out = "pressure_MPa,deformation_mm,force_N,length_mm,direction\n";
  for (const TensileRow& r : rows) {
    out += format_shortest(r.pressure_mpa) + "," + format_shortest(r.deformation_mm) + "," +
           format_shortest(r.force_n) + "," + format_shortest(r.length_mm) + "," +
           to_string(r.direction) + "\n";
  }
  return out;
}

std::vector<TensileRow> read_tensile_csv(const std::string& path) {
  std::istringstream in(read_text_file(path));  // "-": standard input

  // header: locate the required columns and the optional direction
  std::string line;
  if (!std::getline(in, line)) throw InputError(path + ": empty file, no header row");
  // a UTF-8 byte-order mark, as spreadsheet programs write, is not part of the first name
  if (line.rfind("\xEF\xBB\xBF", 0) == 0) line.erase(0, 3);
  const std::vector<std::string> header = split(line);
  const Columns columns = locate_columns(path, header);
  const int* col = columns.required;
  const int direction_col = columns.direction;

  // data rows; row numbers count file lines, the header is row 1
  std::vector<TensileRow> rows;
  for (int line_no = 2; std::getline(in, line); ++line_no) {
    if (trim(line).empty()) continue;
    const std::vector<std::string> cells = split(line);
    const std::string row_name = path + ": row " + std::to_string(line_no);
    if (cells.size() < header.size()) {
      throw InputError(row_name + ": " + std::to_string(cells.size()) + " cells, the header has " +
                       std::to_string(header.size()));
    }
    double v[4];
    for (int k = 0; k < 4; ++k) {
      v[k] = parse_cell(cells[col[k]], row_name + ", column " + kRequired[k]);
    }
    if (v[0] < 0.0) {
      throw InputError(row_name + ", column pressure_MPa: negative pressure " + cells[col[0]] +
                       " (gauge pressure must be >= 0)");
    }
    TensileRow r{v[0], v[1], v[2], v[3], StrokeDirection::kLoading};
    if (direction_col >= 0) {
      const std::string& d = cells[direction_col];
      if (d == "unloading") {
        r.direction = StrokeDirection::kUnloading;
      } else if (d != "loading") {
        throw InputError(row_name + ", column direction: \"" + d +
                         "\" (allowed: loading, unloading)");
      }
    }
    rows.push_back(r);
  }
  if (rows.empty()) throw InputError(path + ": no data rows after the header");
  return rows;
}

}  // namespace pamsim
