// error_budget.cc: the budget's sources read and checked, its runs, and the shares; the
// tables and the chart are written in error_budget_tables.cc.
#include "sim/validate/error_budget.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "base/input_error.h"
#include "sim/validate/table_cells.h"

namespace pamsim {
namespace {

// "key=value" -> "key" (blanks around it dropped)
std::string override_key(const std::string& assignment) {
  std::string key = assignment.substr(0, assignment.find('='));
  const auto blank = [](char c) { return c == ' ' || c == '\t'; };
  while (!key.empty() && blank(key.back())) key.pop_back();
  key.erase(key.begin(), std::find_if_not(key.begin(), key.end(), blank));
  return key;
}

void check_source_name(const TableEntry& e, const std::string& name,
                       const std::vector<BudgetSource>& before) {
  check_cell_name(e, name);
  for (const BudgetSource& s : before) {
    e.in.check(s.name != name, e.where + "name", "repeats another source's, \"" + name + "\"");
  }
}

// A source's overrides: each "key=value" with a key, none of its keys twice
void check_source_overrides(const TableEntry& e, const char* field,
                            const std::vector<std::string>& overrides) {
  std::vector<std::string> keys;
  for (const std::string& o : overrides) {
    const std::string key = override_key(o);
    e.in.check(o.find('=') != std::string::npos && !key.empty(), e.where + field,
               "must hold \"key=value\" overrides, got \"" + o + "\"");
    e.in.check(std::find(keys.begin(), keys.end(), key) == keys.end(), e.where + field,
               "sets " + key + " twice");
    keys.push_back(key);
  }
}

}  // namespace

const std::vector<EntryKey>& budget_source_entry_keys() {
  static const std::vector<EntryKey> keys = {
      {"name", "", "a plain name, unique", "(required)", "the error source", EntryType::kText},
      {"on", "", "list of \"key=value\" scenario overrides, at least one", "(required)",
       "the source switched on", EntryType::kTexts},
      {"off", "", "list of \"key=value\" scenario overrides", "[]",
       "the source switched off, where the protocol's own scenario has it on", EntryType::kTexts}};
  return keys;
}

std::vector<BudgetSource> read_budget_sources(ConfigReader& in) {
  std::vector<BudgetSource> sources;
  const TableArray tables(in, "budget_source");
  for (const TableEntry& e : tables.entries(budget_source_entry_keys())) {
    BudgetSource s;
    s.name = e.text("name", true);
    check_source_name(e, s.name, sources);
    s.on = e.texts("on", true);
    e.in.check(!s.on.empty(), e.where + "on", "must hold at least one override");
    check_source_overrides(e, "on", s.on);
    s.off = e.texts("off", false);
    check_source_overrides(e, "off", s.off);
    sources.push_back(std::move(s));
  }
  in.check(static_cast<int>(sources.size()) <= kMaxBudgetSources, "budget_source",
           "may hold at most " + std::to_string(kMaxBudgetSources) + " sources, got " +
               std::to_string(sources.size()));
  return sources;
}

std::vector<BudgetConfig> budget_configs(const std::vector<BudgetSource>& sources) {
  using Kind = BudgetConfig::Kind;
  const int n = static_cast<int>(sources.size());
  const auto make = [&](Kind kind, int source, std::string name) {
    BudgetConfig c{kind, source, std::move(name), {}};
    for (int i = 0; i < n; ++i) {
      const bool on = kind == Kind::kAll || (kind == Kind::kOnly && i == source) ||
                      (kind == Kind::kWithout && i != source);
      const std::vector<std::string>& set = on ? sources[i].on : sources[i].off;
      c.overrides.insert(c.overrides.end(), set.begin(), set.end());
    }
    return c;
  };
  std::vector<BudgetConfig> configs = {make(Kind::kNone, -1, "none"), make(Kind::kAll, -1, "all")};
  for (int i = 0; i < n; ++i) configs.push_back(make(Kind::kOnly, i, "only " + sources[i].name));
  for (int i = 0; i < n; ++i) {
    configs.push_back(make(Kind::kWithout, i, "all but " + sources[i].name));
  }
  return configs;
}

void check_budget_sources(const std::vector<BudgetSource>& sources,
                          const std::vector<std::string>& user_overrides, const std::string& what,
                          const std::function<void(const std::vector<std::string>&)>& check) {
  for (const BudgetSource& s : sources) {
    const std::string where = what + ": budget source \"" + s.name + "\"";
    for (const std::vector<std::string>* set : {&s.on, &s.off}) {
      for (const std::string& o : *set) {
        for (const std::string& user : user_overrides) {
          if (override_key(user) == override_key(o)) {
            throw InputError("--set " + user + ": " + where + " sets " + override_key(o) +
                             " in the budget's runs");
          }
        }
      }
      std::vector<std::string> overrides = user_overrides;
      overrides.insert(overrides.end(), set->begin(), set->end());
      try {
        check(overrides);
      } catch (const InputError& e) {
        throw InputError(where + (set == &s.on ? " on" : " off") + ": " + e.what());
      }
    }
  }
}

const ErrorPct& ErrorBudget::at(BudgetConfig::Kind kind, int source, std::size_t c) const {
  for (std::size_t k = 0; k < configs.size(); ++k) {
    if (configs[k].kind == kind && configs[k].source == source) return errors[k][c];
  }
  throw std::logic_error("error budget: no such run");
}

namespace {
// sqrt(a^2 - b^2), zero where b >= a (NaN stays NaN)
double quadrature_difference(double a, double b) {
  const double d = a * a - b * b;
  return d > 0.0 ? std::sqrt(d) : (std::isnan(d) ? d : 0.0);
}
}  // namespace

double ErrorBudget::share_alone(int source, std::size_t c) const {
  using Kind = BudgetConfig::Kind;
  return quadrature_difference(at(Kind::kOnly, source, c).rmse_pct,
                               at(Kind::kNone, -1, c).rmse_pct);
}

double ErrorBudget::share_by_removal(int source, std::size_t c) const {
  using Kind = BudgetConfig::Kind;
  return quadrature_difference(at(Kind::kAll, -1, c).rmse_pct,
                               at(Kind::kWithout, source, c).rmse_pct);
}

ErrorBudget run_error_budget(
    const std::vector<BudgetSource>& sources,
    const std::function<std::vector<BudgetCell>(const BudgetConfig&)>& run) {
  ErrorBudget budget;
  budget.sources = sources;
  budget.configs = budget_configs(sources);
  for (const BudgetConfig& config : budget.configs) {
    const std::vector<BudgetCell> cells = run(config);
    std::vector<std::string> names;
    std::vector<ErrorPct> errors;
    for (const BudgetCell& cell : cells) {
      names.push_back(cell.name);
      errors.push_back(cell.error);
    }
    if (budget.errors.empty()) budget.cases = names;
    if (names != budget.cases) throw std::logic_error("error budget: the runs' cells differ");
    budget.errors.push_back(std::move(errors));
  }
  return budget;
}

}  // namespace pamsim
