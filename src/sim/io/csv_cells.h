// csv_cells.h: the cells of pamsim's input CSV files (schedules, recordings): a line split at
// its commas, and a cell read as a whole, trimmed, finite number.
#pragma once

#include <string>
#include <vector>

namespace pamsim {

// `line` split at every comma (no quoting: pamsim's CSV inputs are numbers and names).
std::vector<std::string> split_csv_line(const std::string& line);

// `cell` without its surrounding blanks (spaces, tabs, a trailing CR).
std::string trim_cell(const std::string& cell);

// True, with *value set, if the trimmed cell is all of one finite number ("+1.5", "2e-3");
// false for an empty cell, text, "nan" or "inf".
bool parse_finite_cell(const std::string& cell, double* value);

}  // namespace pamsim
