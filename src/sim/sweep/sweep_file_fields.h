// sweep_file_fields.h: what the readers of a sweep file's tables share (sweep_file.cc's
// [[axis]], randomize.cc's [[randomize]]): where a problem is ("<file>: axis[2].from ...")
// and a finite number field.
#pragma once

#include <cmath>
#include <optional>
#include <string>

#include <toml++/toml.h>

#include "base/format.h"
#include "base/input_error.h"

namespace pamsim {

// Where a problem is: throws InputError "<file>: <prefix><key> <problem>".
struct SweepFileWhere {
  const std::string& file;
  std::string prefix;   // "axis[2]."
  [[noreturn]] void fail(const std::string& key, const std::string& problem) const {
    throw InputError(file + ": " + prefix + key + " " + problem);
  }
  void check(bool ok, const std::string& key, const std::string& problem) const {
    if (!ok) fail(key, problem);
  }
};

// The finite number t[key] (an integer too, when it has an exact double).
inline double sweep_number(const toml::table& t, const char* key, const SweepFileWhere& where) {
  const toml::node* n = t.get(key);
  // (an integer beyond 2^53 has no exact double: toml++ gives none)
  const bool numeric = n && (n->is_integer() || n->is_floating_point());
  const std::optional<double> value = numeric ? n->value<double>() : std::nullopt;
  if (!value) where.fail(key, "must be a number");
  where.check(std::isfinite(*value), key, "must be finite, got " + format_value(*value));
  return *value;
}

}  // namespace pamsim
