// sweep_axis_file.h: the pieces of a sweep file's reader that its parts share (sweep_file.cc
// reads the file, sweep_cases.cc its case axes): where a problem is, a TOML value as an axis
// value, and a table of scenario keys flattened to "key=value" overrides.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include <toml++/toml.h>

#include "sim/sweep/sweep.h"

namespace pamsim::detail {

// Where a problem is: "<file>: axis[<i>].<key>" and the like.
struct Where {
  const std::string& file;
  std::string prefix;
  [[noreturn]] void fail(const std::string& key, const std::string& problem) const;
  void check(bool ok, const std::string& key, const std::string& problem) const {
    if (!ok) fail(key, problem);
  }
};

// Refuses a key of `t` that `keys` lacks ("<key> " + `unknown`, which names the table's keys
// as this reader words them) and a value its row's type, range or names exclude
// (entry_value_problem, base/entry_keys.h), before the table is read.
void check_entry(const toml::table& t, const std::vector<EntryKey>& keys, const Where& where,
                 const std::string& unknown);

// A number (finite), integer, string or boolean as an axis value; fails naming `key`.
AxisValue axis_value(const toml::node& n, const Where& where, const std::string& key);

// "a.b=value" for every leaf of `t` (nested tables and quoted dotted keys alike; a list of
// numbers, strings or booleans as one value), keys prefixed with `prefix`.
void flatten_keys(const toml::table& t, const std::string& prefix, const Where& where,
                  std::vector<std::string>* out);

// The scenario key of a "key=value" override.
std::string override_key(const std::string& assignment);

// A case axis: name and [[axis.case]] tables (name, set), on a grid design only.
SweepAxis read_case_axis(const toml::table& t, std::size_t index, SweepDesign design,
                         const std::string& file);

// Refuses two axes (or an axis and a [[randomize]] draw, or either and [fixed]) that set the
// same scenario key: the later would silently win. `drawn` are the randomized keys, `fixed`
// [fixed]'s "key=value" overrides.
void check_axes_disjoint(const std::vector<SweepAxis>& axes, const std::vector<std::string>& drawn,
                         const std::vector<std::string>& fixed, const std::string& file);

}  // namespace pamsim::detail
