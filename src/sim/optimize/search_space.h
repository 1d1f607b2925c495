// search_space.h: the free parameters of a search over scenario keys (tuning, identification):
// each a scenario key with bounds and a scale, searched as a unit box [0, 1]^n that maps to
// the keys' values, and set on a scenario as `--set`-style overrides. Read from the
// [[parameter]] tables of a tuning (or identification) file.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "base/entry_keys.h"

namespace pamsim {

class ConfigReader;

// What a tuning or identification file starts from: `base` (a scenario file, made absolute so
// a stored definition does not depend on the folder pamsim ran from), its text, and
// `overrides` ("key=value" strings at every trial). Throws InputError "<file>: base ...".
struct SearchBase {
  std::string path, text;
  std::vector<std::string> overrides;
};
SearchBase read_search_base(ConfigReader& in);

// An integer key within [lo, hi] (`range_text` is the "[lo, hi]" the message shows).
std::int64_t read_bounded_int(ConfigReader& in, const std::string& key, std::int64_t fallback,
                              std::int64_t lo, std::int64_t hi, const std::string& range_text);

struct SearchParameter {
  std::string key;              // a scenario key, e.g. "reflex.v_thr_mm_s"
  double from = 0.0, to = 0.0;  // bounds, from < to
  bool log = false;             // log scale (from > 0)
};

// The parameter's value at `u` in [0, 1]: linear, or geometric on a log scale.
double value_at(const SearchParameter& p, double u);
// dx/du at `u`: the range, or on a log scale the value times log(to / from).
double slope_at(const SearchParameter& p, double u);

// `base` followed by "key=value" for each parameter (values in the parameters' order, in
// their shortest round-trip form).
std::vector<std::string> parameter_overrides(const std::vector<std::string>& base,
                                             const std::vector<SearchParameter>& parameters,
                                             const std::vector<double>& values);

// A [[parameter]] table's keys (key, from, to, scale), as the reader takes them and the key
// reference lists them.
const std::vector<EntryKey>& parameter_entry_keys();

// The [[parameter]] tables (key, from, to, scale = "linear" | "log") of `in`'s document;
// keys in `reserved` are refused with `reserved_hint` ("use the tuning file's seeds ..."). At
// least one is required unless `required` is false. Throws InputError
// "<file>: parameter[i].<key> <problem>".
std::vector<SearchParameter> read_search_parameters(ConfigReader& in,
                                                    const std::vector<std::string>& reserved,
                                                    const std::string& reserved_hint,
                                                    bool required = true);

// The parameters as their definitions' canonical JSON lists them (tuning and identification
// databases: [{key, from, to, log}, ...]), so that both store them alike.
nlohmann::json search_parameters_json(const std::vector<SearchParameter>& parameters);

}  // namespace pamsim
