// protocol_budgets.cc: see protocol_budgets.h.
#include "sim/validate/protocol_budgets.h"

#include <filesystem>
#include <system_error>

#include "base/format.h"
#include "base/input_error.h"
#include "sim/scenario/scenario_file.h"

namespace pamsim {
namespace {

void require_sources(const std::vector<BudgetSource>& sources, const std::string& file) {
  if (sources.empty()) {
    throw InputError(file + ": budget_source: --budget needs at least one [[budget_source]] table");
  }
}

// Runs `run_protocol(options)` once per configuration of the budget, with the
// configuration's overrides after the user's and the progress counted over all runs
// (`per_run` trials each).
template <typename RunProtocol>
ErrorBudget run_budget(const std::vector<BudgetSource>& sources, const ValidationOptions& options,
                       int per_run, RunProtocol run_protocol) {
  const int total = per_run * static_cast<int>(budget_configs(sources).size());
  if (options.started) options.started(total);
  int runs_done = 0;
  return run_error_budget(sources, [&](const BudgetConfig& config) {
    ValidationOptions v = options;
    v.started = nullptr;
    v.overrides.insert(v.overrides.end(), config.overrides.begin(), config.overrides.end());
    v.progress = [&](int done, int) {
      if (options.progress) options.progress(runs_done * per_run + done, total);
    };
    std::vector<BudgetCell> cells = run_protocol(v);
    ++runs_done;
    return cells;
  });
}

}  // namespace

ErrorBudget run_length_budget(const LengthValidationSpec& spec, const ValidationOptions& options) {
  require_sources(spec.budget, spec.file);
  check_budget_sources(spec.budget, options.overrides, spec.file,
                       [&](const std::vector<std::string>& overrides) {
                         std::vector<std::string> all = spec.overrides;
                         all.insert(all.end(), overrides.begin(), overrides.end());
                         load_scenario(spec.rig_file, all);
                       });
  LengthValidationSpec headline = spec;
  headline.laws = {spec.laws.front()};
  headline.weights_kg = {spec.weights_kg.front()};
  const int per_run = static_cast<int>(spec.pams.size());
  ErrorBudget budget = run_budget(spec.budget, options, per_run, [&](const ValidationOptions& v) {
    const LengthValidationResult result = run_length_validation(headline, v);
    std::error_code ec;
    std::filesystem::remove_all(result.fits_dir, ec);  // the budget keeps no fitted files
    std::vector<BudgetCell> cells;
    for (const DynamicRow& row : result.rows) cells.push_back({"PAM-" + row.pam, row.sim});
    return cells;
  });
  budget.protocol = "length-estimation";
  budget.cases_are = std::string("each PAM's ") + to_string(headline.laws.front()) +
                     " estimate at " + format_value(headline.weights_kg.front()) +
                     " kg on the pulley rig";
  return budget;
}

ErrorBudget run_reaching_budget(const ReachingValidationSpec& spec,
                                const ValidationOptions& options) {
  require_sources(spec.budget, spec.file);
  check_budget_sources(spec.budget, options.overrides, spec.file,
                       [&](const std::vector<std::string>& overrides) {
                         load_scenario(spec.scenario_file, overrides);
                       });
  ErrorBudget budget =
      run_budget(spec.budget, options, spec.trials, [&](const ValidationOptions& v) {
        const ReachingValidationResult result = run_reaching_validation(spec, v);
        std::vector<BudgetCell> cells;
        for (const ReachingRow& row : result.rows) {
          if (row.part == "all") cells.push_back({row.muscle + " " + row.method, row.sim});
        }
        return cells;
      });
  budget.protocol = "reaching";
  budget.cases_are = "each muscle's model estimate and fiber sensor over " +
                     format_value(spec.window_start_s) + "-" + format_value(spec.window_end_s) +
                     " s, " + std::to_string(spec.trials) + " trials";
  return budget;
}

}  // namespace pamsim
