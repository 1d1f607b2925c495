// toml_section.h: one table of a parameter file (pam_params.cc, plant_params.cc) with the
// file name and the dotted key prefix for messages: typed, validated reads that throw
// InputError "<file>: <key>: <problem>", and the check that every key is known.
#pragma once

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include <toml++/toml.h>

#include "base/format.h"
#include "base/input_error.h"

namespace pamsim {

// one table of the file with the file name and dotted prefix for messages
struct Section {
  const std::string& file;
  std::string prefix;   // "" or "spring."
  const toml::table& table;

  std::string key(const std::string& k) const { return prefix + k; }

  [[noreturn]] void fail(const std::string& k, const std::string& problem) const {
    throw file_key_error(file, key(k), problem);
  }

  // every key must be in `allowed`
  void reject_unknown(const std::set<std::string>& allowed) const {
    for (const auto& [k, v] : table) {
      const std::string name(k.str());
      if (allowed.count(name) == 0) {
        std::string list;
        for (const auto& a : allowed) list += (list.empty() ? "" : ", ") + a;
        fail(name, "unknown key (allowed here: " + list + ")");
      }
    }
  }

  bool has(const std::string& k) const { return table.contains(k); }

  double number(const std::string& k) const {
    const toml::node* n = table.get(k);
    if (n == nullptr) fail(k, "missing (a number is required)");
    const std::optional<double> v = n->value<double>();
    if (!v || n->is_boolean()) fail(k, "must be a number");
    if (!std::isfinite(*v)) fail(k, "must be finite, got " + format_number(*v));
    return *v;
  }

  double positive(const std::string& k, const std::string& unit) const {
    const double v = number(k);
    if (!(v > 0.0)) fail(k, "must be > 0 " + unit + ", got " + format_number(v));
    return v;
  }

  double non_negative(const std::string& k, const std::string& unit) const {
    const double v = number(k);
    if (!(v >= 0.0)) fail(k, "must be >= 0 " + unit + ", got " + format_number(v));
    return v;
  }

  // A list of finite numbers, [] when absent (a single value is not a list).
  std::vector<double> numbers(const std::string& k) const {
    const toml::node* n = table.get(k);
    if (n == nullptr) return {};
    const toml::array* list = n->as_array();
    if (list == nullptr) fail(k, "must be a list of numbers");
    std::vector<double> out;
    for (const toml::node& item : *list) {
      const std::optional<double> v = item.value<double>();
      if (!v || item.is_boolean()) fail(k, "must be a list of numbers");
      if (!std::isfinite(*v)) fail(k, "must be finite, got " + format_number(*v));
      out.push_back(*v);
    }
    return out;
  }

  std::string text(const std::string& k, const std::string& fallback) const {
    const toml::node* n = table.get(k);
    if (n == nullptr) return fallback;
    const std::optional<std::string> v = n->value<std::string>();
    if (!v) fail(k, "must be a string");
    return *v;
  }

  Section sub(const std::string& k) const {
    const toml::node* n = table.get(k);
    if (n == nullptr || !n->is_table()) fail(k, "must be a table");
    return Section{file, prefix + k + ".", *n->as_table()};
  }
};

}  // namespace pamsim
