// tune_outputs.h: what `pamsim tune` (and `pamsim report` on a tuning database) writes from
// the evaluations: best.toml (the base scenario with the best values, ready for `pamsim run`
// from the output folder), evaluations.csv, convergence.png, and with several objectives
// pareto.csv and pareto.png; the held-out checks' tables (tuning_seeds.csv, held_out.csv).
#pragma once

#include <string>
#include <vector>

#include "sim/io/plot.h"  // plot_file_names
#include "sim/optimize/tune.h"

namespace pamsim {

class StagedOutputs;

// The files write_tune_outputs writes (what `pamsim report` on a tuning database replaces),
// and with pamsim tune's own tuning_seeds.csv and held_out.csv (what `pamsim tune` replaces:
// a report must not remove the held-out checks it does not rerun).
inline const std::vector<std::string> kTuneReportOutputs = [] {
  std::vector<std::string> names = {"best.toml", "evaluations.csv", "pareto.csv"};
  for (const std::string& plot : plot_file_names({"convergence.png", "pareto.png"})) {
    names.push_back(plot);
  }
  return names;
}();
inline const std::vector<std::string> kTuneOutputs = [] {
  std::vector<std::string> names = kTuneReportOutputs;
  names.insert(names.end(), {"tuning_seeds.csv", "held_out.csv"});
  return names;
}();

// best.toml, evaluations.csv, convergence.png, and with several objectives pareto.csv and
// pareto.png, into the staging folder of `out` (published by the caller with the rest);
// without `plots`, no PNG. Throws InputError when no evaluation is stored.
void write_tune_outputs(const TuneDefinition& def, const std::vector<TuneEvaluation>& history,
                        const StagedOutputs& out, bool plots = true);
// evaluations.csv: one row per evaluation (parameters, objective means, violation, feasible,
// trials, ok).
std::string tune_evaluations_csv(const TuneDefinition& def,
                                 const std::vector<TuneEvaluation>& history);
// held_out.csv (and tuning_seeds.csv): one row per setting checked.
std::string held_out_csv(const TuneDefinition& def, const std::vector<HeldOutCheck>& checks);

}  // namespace pamsim
