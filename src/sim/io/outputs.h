// outputs.h: a trial's files: trajectory.csv (header row, one row per control tick, units
// in the column names) and summary.json (metrics, NaN written as null), and the aggregate
// summary of repeated trials (mean, min, max of every metric). Written atomically.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

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

// Makes `dir` and any missing parents (make_directories), and removes the ones it made
// again when destroyed unless kept, innermost first and only while they are empty (rmdir):
// a command that fails before its first output leaves no empty folder behind, and never
// removes what anyone else put there meanwhile.
class FolderGuard {
 public:
  explicit FolderGuard(const std::string& dir);
  ~FolderGuard();
  FolderGuard(const FolderGuard&) = delete;
  FolderGuard& operator=(const FolderGuard&) = delete;
  void keep() { made_.clear(); }   // an output is in place: the folders stay

 private:
  void remove_made();
  std::vector<std::string> made_;   // the folders made here, outermost first
};

// DIR/trajectory.csv and DIR/summary.json.
void write_trial_outputs(const std::string& dir, const TrialResult& result,
                         const Scenario& scenario);

}  // namespace pamsim
