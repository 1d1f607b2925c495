// outputs.h: a trial's files: trajectory.csv (header row, one row per control tick, units
// in the column names) and summary.json (metrics, NaN written as null), and the aggregate
// summary of repeated trials (mean, min, max of every metric). Written atomically.
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "sim/core/scenario.h"
#include "sim/core/trial.h"

namespace pamsim {

std::string trajectory_to_csv(const Trajectory& trajectory);
nlohmann::json summary_to_json(const TrialSummary& summary, const Scenario& scenario);
// {"trials": N, "seeds": [...], "status_counts": {...}, "metrics": {name: {mean,min,max}}}
nlohmann::json aggregate_summaries(const std::vector<TrialSummary>& summaries,
                                   const Scenario& scenario);

// Creates `dir` (and parents) or throws InputError naming it.
void make_directories(const std::string& dir);

// DIR/trajectory.csv and DIR/summary.json.
void write_trial_outputs(const std::string& dir, const TrialResult& result,
                         const Scenario& scenario);

}  // namespace pamsim
