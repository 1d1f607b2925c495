// csv_cells.cc: see csv_cells.h.
#include "sim/io/csv_cells.h"

#include <charconv>
#include <cmath>

namespace pamsim {

std::vector<std::string> split_csv_line(const std::string& line) {
  std::vector<std::string> cells;
  std::size_t start = 0;
  while (true) {
    const std::size_t comma = line.find(',', start);
    cells.push_back(
        line.substr(start, comma == std::string::npos ? std::string::npos : comma - start));
    if (comma == std::string::npos) return cells;
    start = comma + 1;
  }
}

std::string trim_cell(const std::string& cell) {
  const auto b = cell.find_first_not_of(" \t\r");
  if (b == std::string::npos) return "";
  const auto e = cell.find_last_not_of(" \t\r");
  return cell.substr(b, e - b + 1);
}

bool parse_finite_cell(const std::string& raw, double* value) {
  const std::string cell = trim_cell(raw);
  if (cell.empty()) return false;
  const char* first = cell.data();
  if (*first == '+') ++first;
  const auto [ptr, ec] = std::from_chars(first, cell.data() + cell.size(), *value);
  return ec == std::errc() && ptr == cell.data() + cell.size() && std::isfinite(*value);
}

}  // namespace pamsim
