// sweep_axis_file.cc: see sweep_axis_file.h: what the parts of the sweep file's reader share.
#include "sim/sweep/sweep_axis_file.h"

#include <cmath>

#include "base/format.h"
#include "base/input_error.h"
#include "base/toml_file.h"

namespace pamsim::detail {

void Where::fail(const std::string& key, const std::string& problem) const {
  throw InputError(file + ": " + prefix + key + " " + problem, {file, prefix + key, problem});
}

void check_entry(const toml::table& t, const std::vector<EntryKey>& keys, const Where& where,
                 const std::string& unknown) {
  for (const auto& [k, v] : t) {
    const std::string key(k.str());
    where.check(is_entry_key(keys, key), key, unknown);
    const std::string problem = entry_value_problem(keys, key, v);
    where.check(problem.empty(), key, problem);
  }
}

AxisValue axis_value(const toml::node& n, const Where& where, const std::string& key) {
  AxisValue v;
  if (n.is_integer()) {
    v.kind = AxisValue::Kind::kInteger;
    v.number = static_cast<double>(*n.value<std::int64_t>());
  } else if (n.is_floating_point()) {
    v.number = *n.value<double>();
    where.check(std::isfinite(v.number), key, "must be finite, got " + format_value(v.number));
  } else if (n.is_string()) {
    v.kind = AxisValue::Kind::kString;
    v.text = *n.value<std::string>();
  } else if (n.is_boolean()) {
    v.kind = AxisValue::Kind::kBool;
    v.flag = *n.value<bool>();
  } else {
    where.fail(key, "must be a number, a string or a boolean");
  }
  return v;
}

void flatten_keys(const toml::table& t, const std::string& prefix, const Where& where,
                  std::vector<std::string>* out) {
  for (const auto& [k, node] : t) {
    const std::string key = prefix + std::string(k.str());
    if (const toml::table* sub = node.as_table()) {
      flatten_keys(*sub, key + ".", where, out);
    } else if (const toml::array* list = node.as_array()) {
      for (const toml::node& item : *list) axis_value(item, where, key);  // checks each
      out->push_back(key + "=" + toml_value_text(*list));
    } else {
      out->push_back(key + "=" + axis_value(node, where, key).toml());
    }
  }
}

std::string override_key(const std::string& assignment) {
  return assignment.substr(0, assignment.find('='));
}

}  // namespace pamsim::detail
