// outputs.h: a trial's files: trajectory.csv (header row, one row per control tick, units
// in the column names, numbers in shortest round-trip form) and summary.json (metrics, NaN
// written as null; the timing metrics, which vary from run to run, go to provenance.json),
// and the aggregate summary of repeated trials (mean, SD, 95 % confidence interval of the
// mean, min, max of every metric). Written atomically.
#pragma once

#include <cmath>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "sim/core/scenario.h"
#include "sim/core/trial.h"

namespace pamsim {

std::string trajectory_to_csv(const Trajectory& trajectory);
// With `with_timing`, wall_time_s and realtime_factor too (not in summary.json files).
nlohmann::json summary_to_json(const TrialSummary& summary, const Scenario& scenario,
                               bool with_timing);
// {"trials": N, "seeds": [...], "status_counts": {...},
//  "metrics": {name: {mean, sd, ci95_low, ci95_high, min, max, count}}} (no timing metrics)
nlohmann::json aggregate_summaries(const std::vector<TrialSummary>& summaries,
                                   const Scenario& scenario);

// Mean, sample SD and the 95 % confidence interval of the mean (Student's t, n - 1 degrees
// of freedom) of `values`; NaN where undefined (SD and interval need two values).
struct SampleStats {
  int count = 0;
  double mean = NAN, sd = NAN, ci95_low = NAN, ci95_high = NAN, min = NAN, max = NAN;
};
SampleStats sample_stats(const std::vector<double>& values);
// The half width of that interval for a sample of `count` values with SD `sd`: t(0.975,
// count - 1) sd / sqrt(count); NaN for fewer than two values.
double ci95_half_width(double sd, int count);

// Outputs are not replaced silently: throws InputError "<path>: exists; add --force to
// replace it" if `path` is an existing file or folder, unless `force`. Standard output ("-"),
// a FIFO or a device (written through, never replaced) are always allowed.
void refuse_existing_file(const std::string& path, bool force);

// A finite number, or null for NaN and infinities (JSON has neither).
nlohmann::json number_or_null(double v);

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
  void keep() { made_.clear(); }  // an output is in place: the folders stay

 private:
  void remove_made();
  std::vector<std::string> made_;  // the folders made here, outermost first
};

// DIR/trajectory.csv and DIR/summary.json.
void write_trial_outputs(const std::string& dir, const TrialResult& result,
                         const Scenario& scenario);

}  // namespace pamsim
