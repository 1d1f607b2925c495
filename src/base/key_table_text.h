// key_table_text.h: the words a key table's messages and references share (key_table.cc
// reads a scenario's rows and writes the reference, key_table_file.cc reads a parameter file):
// a choice's names, an integer's range, a list's allowance and count, a value out of its
// range.
#pragma once

#include <algorithm>
#include <cstddef>
#include <string>
#include <vector>

#include "base/format.h"
#include "base/key_table.h"

namespace pamsim::key_table_text {

// "\"a\" | \"b\"": names as TOML strings
inline std::string names_text(const std::vector<std::string>& names) {
  std::string text;
  for (const std::string& a : names) text += (text.empty() ? "\"" : " | \"") + a + "\"";
  return text;
}

// the names a choice (or a name list) allows, as names_text writes them
template <typename Row>
std::string choices_text(const Row& row) {
  return names_text(row.allowed);
}

// "[0, 64]"
inline std::string int_range(const IntRow& row) {
  return "[" + std::to_string(row.lo) + ", " + std::to_string(row.hi) + "]";
}

inline bool allows(const ChoiceRow& row, const std::string& value) {
  return std::find(row.allowed.begin(), row.allowed.end(), value) != row.allowed.end();
}

// A name list's item: one of its allowed names, or any where it lists none.
inline bool allows(const NameListRow& row, const std::string& value) {
  return row.allowed.empty() ||
         std::find(row.allowed.begin(), row.allowed.end(), value) != row.allowed.end();
}

// "holds \"x\", allowed \"a\" | \"b\"" for the first item a name list does not allow, or ""
inline std::string name_list_problem(const NameListRow& row,
                                     const std::vector<std::string>& names) {
  for (const std::string& n : names) {
    if (!allows(row, n)) return "holds \"" + n + "\", allowed " + choices_text(row);
  }
  return "";
}

// "a list of \"a\" | \"b\"" or "a list of strings"
inline std::string name_list_allowed(const NameListRow& row) {
  return "a list of " + (row.allowed.empty() ? std::string("strings") : choices_text(row));
}

// "must be in (0, inf) mm, got -1"
template <typename Row>
std::string out_of_range(const Row& row, double v) {
  return "must be in " + row.range.text() + (row.unit.empty() ? "" : " " + row.unit) + ", got " +
         format_value(v);
}

// "up to 4 of (0, inf)", "1 to 4 of ...", "3 of ..."
inline std::string list_allowed(const ListRow& row) {
  const std::string count =
      row.min_count == row.max_count ? std::to_string(row.max_count)
      : row.min_count > 0 ? std::to_string(row.min_count) + " to " + std::to_string(row.max_count)
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
