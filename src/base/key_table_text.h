// key_table_text.h: the words a key table's messages and references share (key_table.cc
// reads a scenario's rows and writes the reference, key_table_file.cc reads a parameter file):
// a choice's names, an integer's range, a list's allowance and count, a value out of its
// range.
#pragma once

#include <cstddef>
#include <string>

#include "base/format.h"
#include "base/key_table.h"

namespace pamsim::key_table_text {

// "\"a\" | \"b\"": the names a choice allows, as TOML strings
inline std::string choices_text(const ChoiceRow& row) {
  std::string allowed;
  for (const std::string& a : row.allowed) {
    allowed += (allowed.empty() ? "\"" : " | \"") + a + "\"";
  }
  return allowed;
}

// "[0, 64]"
inline std::string int_range(const IntRow& row) {
  return "[" + std::to_string(row.lo) + ", " + std::to_string(row.hi) + "]";
}

inline bool allows(const ChoiceRow& row, const std::string& value) {
  for (const std::string& a : row.allowed) {
    if (value == a) return true;
  }
  return false;
}

// "must be in (0, inf) mm, got -1"
template <typename Row>
std::string out_of_range(const Row& row, double v) {
  return "must be in " + row.range.text() + (row.unit.empty() ? "" : " " + row.unit) +
         ", got " + format_value(v);
}

// "up to 4 of (0, inf)", "1 to 4 of ...", "3 of ..."
inline std::string list_allowed(const ListRow& row) {
  const std::string count = row.min_count == row.max_count ? std::to_string(row.max_count)
                            : row.min_count > 0 ? std::to_string(row.min_count) + " to " +
                                                      std::to_string(row.max_count)
                                                : "up to " + std::to_string(row.max_count);
  return count + " of " + row.range.text();
}

// "must list 3 values, got 2": a list's count outside [min_count, max_count], or ""
inline std::string list_count_problem(const ListRow& row, std::size_t n) {
  if (n >= row.min_count && n <= row.max_count) return "";
  return "must list " + list_allowed(row).substr(0, list_allowed(row).find(" of ")) +
         " values, got " + std::to_string(n);
}

}  // namespace pamsim::key_table_text
