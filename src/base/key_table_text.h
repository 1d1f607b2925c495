// key_table_text.h: the words a key table's messages and references share (key_table.cc
// reads a scenario's rows and writes the reference, key_table_file.cc reads a parameter file):
// a choice's names, an integer's range, a list's allowance, a value out of its range.
#pragma once

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

// "up to 4 of (0, inf)"
inline std::string list_allowed(const ListRow& row) {
  return "up to " + std::to_string(row.max_count) + " of " + row.range.text();
}

}  // namespace pamsim::key_table_text
