// reaching_protocol.cc: reading the reaching task's protocol file (load_reaching_validation,
// reaching.h), and its `base`: a protocol file this one changes. A file with a base starts
// from every key the base gives; its own keys replace the base's, its [paper] cells replace
// or add cells, and a [[budget_source]] or [[bracket]] of a name the base has replaces that
// table in place (others are added after the base's). One layer: a base has no base itself.
#include "sim/validate/reaching.h"

#include <algorithm>

#include "base/config_reader.h"
#include "base/format.h"

namespace pamsim {
namespace {

// `layer`'s entries over `base`'s: one of the same name replaces the base's in place, a new
// one is added at the end
template <typename Entry>
std::vector<Entry> layered_by_name(std::vector<Entry> base, const std::vector<Entry>& layer) {
  for (const Entry& e : layer) {
    const auto same =
        std::find_if(base.begin(), base.end(), [&](const Entry& b) { return b.name == e.name; });
    if (same != base.end()) {
      *same = e;
    } else {
      base.push_back(e);
    }
  }
  return base;
}

void read_window(ConfigReader& in, bool layered, ReachingValidationSpec* spec) {
  std::vector<double> fallback;  // a base's window, or none: the key is required
  if (layered) fallback = {spec->window_start_s, spec->window_end_s};
  const std::vector<double> window = in.get_double_list("window_s", fallback);
  std::string got;
  for (double w : window) got += (got.empty() ? "" : ", ") + format_value(w);
  in.check(window.size() == 2 && window[0] >= 0.0 && window[1] > window[0], "window_s",
           "must be [start, end] with 0 <= start < end, got [" + got + "]");
  spec->window_start_s = window[0];
  spec->window_end_s = window[1];
}

void read_paper(ConfigReader& in, ReachingValidationSpec* spec) {
  for (const std::string& name : in.child_keys("paper")) {
    const std::string key = "paper." + name;
    const std::vector<double> v = in.get_double_list(key, {});
    in.check(v.size() == 2 && v[0] >= 0.0 && v[1] >= 0.0, key,
             "must be [max, RMSE] in % of length, both >= 0");
    in.check(name.rfind("model_", 0) == 0 || name.rfind("fiber_", 0) == 0, key,
             "must start with model_ or fiber_");
    spec->paper[name] = {v[0], v[1]};
  }
  in.raw("paper");
}

// the brackets and their seed over the base's; two brackets of one key are refused
void read_layered_brackets(ConfigReader& in, bool layered, ReachingValidationSpec* spec) {
  std::uint64_t seed = 1;
  const std::vector<Bracket> own = read_brackets(in, &seed);
  if (!layered || in.has("bracket_seed")) spec->bracket_seed = seed;
  spec->brackets = layered_by_name(spec->brackets, own);
  in.check(static_cast<int>(spec->brackets.size()) <= kMaxBrackets, "bracket",
           "may hold at most " + std::to_string(kMaxBrackets) + " brackets with the base's, got " +
               std::to_string(spec->brackets.size()));
  for (std::size_t i = 0; i < spec->brackets.size(); ++i) {
    for (std::size_t j = 0; j < i; ++j) {
      in.check(spec->brackets[i].key != spec->brackets[j].key, "bracket",
               "\"" + spec->brackets[i].name + "\" repeats the key of the base's \"" +
                   spec->brackets[j].name + "\"");
    }
  }
}

ReachingValidationSpec read_protocol(const std::string& path,
                                     const std::vector<std::string>& overrides, bool is_base) {
  ConfigReader in(path);
  in.apply_overrides(overrides);
  const std::string base = in.get_input_path("base", "");
  in.check(base.empty() || !is_base, "base",
           "is given in a base protocol: a base has no base itself");
  const bool layered = !base.empty();
  ReachingValidationSpec spec = layered ? read_protocol(base, {}, true) : ReachingValidationSpec{};
  spec.file = path;
  if (!layered || in.has("scenario")) {  // (a base's path is already resolved)
    spec.scenario_file = in.require_path("scenario", "the reaching scenario");
  }
  const std::int64_t trials = in.get_int("trials", spec.trials);
  in.check(trials >= 1 && trials <= 1000, "trials",
           "must be in [1, 1000], got " + std::to_string(trials));
  spec.trials = static_cast<int>(trials);
  read_window(in, layered, &spec);
  spec.min_slack_s = in.get_double("min_slack_s", spec.min_slack_s);
  in.check(spec.min_slack_s > 0.0, "min_slack_s",
           "must be > 0 s, got " + format_value(spec.min_slack_s));
  read_paper(in, &spec);
  spec.budget = layered_by_name(spec.budget, read_budget_sources(in));
  in.check(static_cast<int>(spec.budget.size()) <= kMaxBudgetSources, "budget_source",
           "may hold at most " + std::to_string(kMaxBudgetSources) +
               " sources with the base's, got " + std::to_string(spec.budget.size()));
  read_layered_brackets(in, layered, &spec);
  in.reject_unknown();
  return spec;
}

}  // namespace

ReachingValidationSpec load_reaching_validation(
    const std::string& path, const std::vector<std::string>& protocol_overrides) {
  return read_protocol(path, protocol_overrides, false);
}

}  // namespace pamsim
