// key_table_test_util.h: bad values generated from a key table's row (base/key_table.h), for
// the tests that every row refuses what it excludes: each finite side of its range, a value
// of another type, NaN; and the check that a reader's keys are its rows, each once.
#pragma once

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "base/format.h"
#include "base/input_error.h"
#include "base/key_table.h"

namespace pamsim {

// the values just outside a range, each side that is finite
inline std::vector<double> outside(const KeyRange& r) {
  std::vector<double> values;
  if (std::isfinite(r.lo)) values.push_back(r.lo_open ? r.lo : r.lo - 1.0 - std::fabs(r.lo));
  if (std::isfinite(r.hi)) values.push_back(r.hi_open ? r.hi : r.hi + 1.0 + std::fabs(r.hi));
  return values;
}

// a number row's bad values as TOML text: a string, NaN, a boolean, and outside(range)
inline std::vector<std::string> bad_number_texts(const NumberRow& row) {
  std::vector<std::string> bad = {"\"x\"", "nan", "true"};
  for (double v : outside(row.range)) bad.push_back(format_number(v));
  return bad;
}

// an integer row's bad values as TOML text: a fraction, a string, and each side just outside
// (none above a row that takes every integer up to TOML's largest)
inline std::vector<std::string> bad_int_texts(const IntRow& row) {
  std::vector<std::string> bad = {"1.5", "\"x\"", std::to_string(row.lo - 1)};
  if (row.hi < std::numeric_limits<std::int64_t>::max()) bad.push_back(std::to_string(row.hi + 1));
  return bad;
}

// The parts of the InputError that `read` throws, which must be one line; a test failure
// naming `what` (the key and value tried) if it throws none.
inline InputErrorParts refusal_parts(const std::function<void()>& read, const std::string& what) {
  try {
    read();
    ADD_FAILURE() << what << " was read";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos) << e.what();
    return e.parts();
  }
  return {};
}

// Every row's dotted key "<table>.<name>", counted (a key twice is a defect).
inline std::map<std::string, int> row_keys(const std::vector<KeyTable>& tables) {
  std::map<std::string, int> rows;
  for (const KeyTable& t : tables) {
    for (const NumberRow& r : t.numbers) ++rows[row_key(t, r.name)];
    for (const IntRow& r : t.ints) ++rows[row_key(t, r.name)];
    for (const BoolRow& r : t.bools) ++rows[row_key(t, r.name)];
    for (const ChoiceRow& r : t.choices) ++rows[row_key(t, r.name)];
    for (const TextRow& r : t.texts) ++rows[row_key(t, r.name)];
    for (const ListRow& r : t.lists) ++rows[row_key(t, r.name)];
    for (const NameListRow& r : t.name_lists) ++rows[row_key(t, r.name)];
  }
  return rows;
}

// Each row once, and the keys a reader asked for (`asked`) exactly the rows' keys.
inline void expect_rows_are_the_asked_keys(const std::map<std::string, int>& rows,
                                           const std::set<std::string>& asked) {
  for (const auto& [key, count] : rows) {
    EXPECT_EQ(count, 1) << key;
    EXPECT_EQ(asked.count(key), 1u) << key << " has a row but is not read";
  }
  for (const std::string& key : asked) {
    EXPECT_EQ(rows.count(key), 1u) << key << " is read but has no row";
  }
}

}  // namespace pamsim
