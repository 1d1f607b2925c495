// trajectory_csv.cc: see trajectory_csv.h.
#include "sim/io/trajectory_csv.h"

#include <charconv>
#include <fstream>
#include <set>
#include <vector>

#include "base/input_error.h"

namespace pamsim {
namespace {

// the cells of one line, blanks around each trimmed
std::vector<std::string> split_cells(const std::string& line) {
  std::vector<std::string> cells;
  std::size_t begin = 0;
  while (true) {
    const std::size_t end = line.find(',', begin);
    std::string cell =
        line.substr(begin, end == std::string::npos ? std::string::npos : end - begin);
    const auto b = cell.find_first_not_of(" \t");
    const auto e = cell.find_last_not_of(" \t");
    cells.push_back(b == std::string::npos ? "" : cell.substr(b, e - b + 1));
    if (end == std::string::npos) break;
    begin = end + 1;
  }
  return cells;
}

// the whole cell as a number ("nan" and "inf" included); false if it is not one
bool parse_number(const std::string& cell, double& value) {
  if (cell.empty()) return false;
  const char* first = cell.data();
  const char* last = cell.data() + cell.size();
  if (*first == '+') ++first;
  const auto [ptr, ec] = std::from_chars(first, last, value);
  return ec == std::errc() && ptr == last;
}

}  // namespace

Trajectory read_trajectory_csv(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path + ": cannot open trajectory file");
  Trajectory tr;

  // header row: distinct, non-empty column names
  std::string line;
  long line_no = 0;
  auto next_line = [&]() {
    if (!std::getline(in, line)) return false;
    ++line_no;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    return true;
  };
  while (next_line() && line.find_first_not_of(" \t") == std::string::npos) {
  }
  if (line_no == 0 || line.find_first_not_of(" \t") == std::string::npos) {
    throw InputError(path + ": empty file, expected a header row of column names");
  }
  tr.columns = split_cells(line);
  std::set<std::string> seen;
  for (std::size_t c = 0; c < tr.columns.size(); ++c) {
    const std::string& name = tr.columns[c];
    if (name.empty()) {
      throw InputError(path + ": line " + std::to_string(line_no) + ": header column " +
                       std::to_string(c + 1) + " has no name");
    }
    if (!seen.insert(name).second) {
      throw InputError(path + ": line " + std::to_string(line_no) + ": header repeats column " +
                       name);
    }
  }

  // numeric rows of the header's width; blank lines skipped
  while (next_line()) {
    if (line.find_first_not_of(" \t") == std::string::npos) continue;
    const std::vector<std::string> cells = split_cells(line);
    if (cells.size() != tr.columns.size()) {
      throw InputError(path + ": line " + std::to_string(line_no) + " has " +
                       std::to_string(cells.size()) + " cells, the header has " +
                       std::to_string(tr.columns.size()) + " columns");
    }
    for (std::size_t c = 0; c < cells.size(); ++c) {
      double v = 0;
      if (!parse_number(cells[c], v)) {
        throw InputError(path + ": line " + std::to_string(line_no) + ", column " + tr.columns[c] +
                         ": '" + cells[c] + "' is not a number");
      }
      tr.values.push_back(v);
    }
  }
  if (in.bad()) throw InputError(path + ": read error after line " + std::to_string(line_no));
  return tr;
}

}  // namespace pamsim
