// key_table_test_util.h: bad values generated from a key table's row (base/key_table.h), for
// the tests that every row refuses what it excludes: each finite side of its range, a value
// of another type, NaN.
#pragma once

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
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

}  // namespace pamsim
