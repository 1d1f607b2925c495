// search_space.cc: see search_space.h.
#include "sim/optimize/search_space.h"

#include <algorithm>
#include <cmath>
#include <filesystem>

#include <nlohmann/json.hpp>

#include "base/config_reader.h"
#include "base/format.h"
#include "base/input_error.h"
#include "base/toml_file.h"

namespace pamsim {

SearchBase read_search_base(ConfigReader& in) {
  SearchBase base;
  base.path = in.require_path("base", "the base scenario file");
  std::error_code error;  // a path the system cannot resolve (a name too long) is the file's fault
  const std::filesystem::path absolute = std::filesystem::absolute(base.path, error);
  std::filesystem::path resolved;
  if (!error) resolved = std::filesystem::weakly_canonical(absolute, error);
  if (error) in.fail("base", "cannot be resolved (" + error.message() + ")");
  base.path = resolved.string();
  try {
    base.text = read_text_file(base.path);
  } catch (const InputError& e) {
    in.fail("base", std::string("(") + e.what() + ")");
  }
  base.overrides = in.get_string_list("overrides", {});
  return base;
}

std::int64_t read_bounded_int(ConfigReader& in, const std::string& key, std::int64_t fallback,
                              std::int64_t lo, std::int64_t hi, const std::string& range_text) {
  const std::int64_t v = in.get_int(key, fallback);
  in.check(v >= lo && v <= hi, key, "must be in " + range_text + ", got " + std::to_string(v));
  return v;
}

double value_at(const SearchParameter& p, double u) {
  if (p.log) return std::exp(std::log(p.from) + u * (std::log(p.to) - std::log(p.from)));
  return p.from + u * (p.to - p.from);
}

double slope_at(const SearchParameter& p, double u) {
  return p.log ? value_at(p, u) * std::log(p.to / p.from) : p.to - p.from;
}

std::vector<std::string> parameter_overrides(const std::vector<std::string>& base,
                                             const std::vector<SearchParameter>& parameters,
                                             const std::vector<double>& values) {
  std::vector<std::string> out = base;
  for (std::size_t i = 0; i < parameters.size(); ++i) {
    out.push_back(parameters[i].key + "=" + format_number(values[i]));
  }
  return out;
}

namespace {

SearchParameter read_parameter(ConfigReader& in, const TableEntry& e,
                               const std::vector<SearchParameter>& earlier,
                               const std::vector<std::string>& reserved,
                               const std::string& reserved_hint) {
  SearchParameter p;
  p.key = e.text("key", true);
  for (const SearchParameter& q : earlier) {
    in.check(q.key != p.key, e.where + "key", "names " + p.key + " twice");
  }
  in.check(std::find(reserved.begin(), reserved.end(), p.key) == reserved.end(), e.where + "key",
           "cannot be \"" + p.key + "\": " + reserved_hint);
  const auto from = e.number("from"), to = e.number("to");
  if (!from) in.fail(e.where + "from", "is required");
  if (!to) in.fail(e.where + "to", "is required");
  p.from = *from;
  p.to = *to;
  in.check(p.from < p.to, e.where + "from",
           "must be below to (" + format_value(p.from) + " >= " + format_value(p.to) + ")");
  p.log = e.text("scale", false, "linear") == "log";  // one of its row's names
  in.check(!p.log || p.from > 0.0, e.where + "from",
           "must be > 0 on a log scale, got " + format_value(p.from));
  return p;
}

}  // namespace

std::vector<SearchParameter> read_search_parameters(ConfigReader& in,
                                                    const std::vector<std::string>& reserved,
                                                    const std::string& reserved_hint,
                                                    bool required) {
  std::vector<SearchParameter> out;
  for (const TableEntry& e : TableArray(in, "parameter").entries(parameter_entry_keys())) {
    out.push_back(read_parameter(in, e, out, reserved, reserved_hint));
  }
  in.check(!required || !out.empty(), "parameter", "needs at least one [[parameter]]");
  return out;
}

const std::vector<EntryKey>& parameter_entry_keys() {
  static const std::vector<EntryKey> keys = {
      {"key", "", "a numeric scenario key", "(required)", "the scenario key searched",
       EntryType::kText},
      {"from", "(the key's)", "within the key's range", "(required)",
       "the search box's lower end, in the key's own unit", EntryType::kNumber},
      {"to", "(the key's)", "above from, within the key's range", "(required)",
       "the search box's upper end", EntryType::kNumber},
      {"scale",
       "",
       "log: from > 0",
       "\"linear\"",
       "how the search spaces the box",
       EntryType::kChoice,
       {},
       {"linear", "log"}}};
  return keys;
}

nlohmann::json search_parameters_json(const std::vector<SearchParameter>& parameters) {
  nlohmann::json params = nlohmann::json::array();
  for (const auto& p : parameters) {
    params.push_back({{"key", p.key}, {"from", p.from}, {"to", p.to}, {"log", p.log}});
  }
  return params;
}

}  // namespace pamsim
