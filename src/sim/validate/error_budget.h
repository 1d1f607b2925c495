// error_budget.h: what each of the hardware's error sources costs the length estimate. A
// validation protocol (length_estimation.h, reaching.h) is run with no source on, with every
// source on, with each source alone and with each off in turn; per case (a PAM, a muscle's
// estimate) the budget gives the max and RMS error of every run and each source's share of
// the RMS error, in quadrature (ErrorBudget::share_alone, share_by_removal).
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "base/config_reader.h"
#include "sim/validate/validation_options.h"

namespace pamsim {

// The sources are data, a protocol file's [[budget_source]] tables:
//   name   what the source is ("pressure sensor"), unique; no comma, quote, bar, tab or
//          newline (it is a cell of the CSV, the Markdown and the chart's data)
//   on     the scenario overrides ("key=value") that turn it on, at least one
//   off    those that turn it off; default none (the scenario's own setting is off)
// Every run sets every source's `on` or `off` after the user's --set, so a --set of a key
// that a source sets is refused.
struct BudgetSource {
  std::string name;
  std::vector<std::string> on, off;
};

// A [[budget_source]] table's keys, as the reader takes them and the key reference lists them.
const std::vector<EntryKey>& budget_source_entry_keys();

// Reads and checks [[budget_source]]; empty if the file has none. At most kMaxBudgetSources.
inline constexpr int kMaxBudgetSources = 16;
std::vector<BudgetSource> read_budget_sources(ConfigReader& in);

// One run of the protocol: which sources are on.
struct BudgetConfig {
  enum class Kind { kNone, kAll, kOnly, kWithout };
  Kind kind = Kind::kNone;
  int source = -1;                     // the source of kOnly and kWithout
  std::string name;                    // "none", "all", "only <source>", "all but <source>"
  std::vector<std::string> overrides;  // every source's `on` or `off`, in the sources' order
};

// none, all, then only and all-but for each source, in the sources' order.
std::vector<BudgetConfig> budget_configs(const std::vector<BudgetSource>& sources);

// Refuses (InputError "<what>: budget source "<name>" ...") a source whose `on` or `off`
// the protocol's scenario refuses: `check(overrides)` loads it with them (and throws), and
// a --set (`user_overrides`) of a key a source sets.
void check_budget_sources(const std::vector<BudgetSource>& sources,
                          const std::vector<std::string>& user_overrides, const std::string& what,
                          const std::function<void(const std::vector<std::string>&)>& check);

// A cell of a protocol's table that the budget follows, by name ("PAM-A", "agonist model").
struct BudgetCell {
  std::string name;
  ErrorPct error;
};

struct ErrorBudget {
  std::string protocol;   // "length-estimation", "reaching"
  std::string cases_are;  // what a case is, for the Markdown ("Eq. (3) at 5 kg, 20 s")
  std::vector<BudgetSource> sources;
  std::vector<BudgetConfig> configs;
  std::vector<std::string> cases;
  std::vector<std::vector<ErrorPct>> errors;  // [config][case]

  const ErrorPct& at(BudgetConfig::Kind kind, int source, std::size_t c) const;
  // A source's share of case c's RMS error, alone and by removal, in quadrature:
  //   alone:       sqrt(RMSE(only s)^2 - RMSE(none)^2)
  //   by removal:  sqrt(RMSE(all)^2 - RMSE(all but s)^2)
  // (zero where the difference is negative: a source that lowers the error). Were the
  // sources' errors independent and additive, both would be equal and RMSE(all)^2 would be
  // RMSE(none)^2 plus the sum of the shares' squares; the budget prints how close it comes.
  double share_alone(int source, std::size_t c) const;
  double share_by_removal(int source, std::size_t c) const;
};

// Runs `run` once per configuration (budget_configs), `run(overrides)` returning the cells of
// one protocol run: the same names in the same order every time (std::logic_error if not).
ErrorBudget run_error_budget(
    const std::vector<BudgetSource>& sources,
    const std::function<std::vector<BudgetCell>(const BudgetConfig&)>& run);

// budget.csv: case, config, source, max_error_pct, rmse_pct, share_rmse_pct (a source's
// share alone on its "only" row, by removal on its "all but" row; empty on none and all).
std::string budget_csv(const ErrorBudget& budget);
// budget.md: every run's errors per case, each source's shares, the sum-of-squares check.
std::string budget_markdown(const ErrorBudget& budget);
// out_dir/budget.csv, budget.md and, with `draw`, budget.png (each source's share alone per
// case as bars, the none run's RMSE beside them). Each file whole or not at all.
void write_error_budget(const ErrorBudget& budget, const std::string& out_dir, bool draw);

}  // namespace pamsim
