// sweep_trials.cc: see sweep_trials.h.
#include "sim/cli/sweep_trials.h"

#include "base/format.h"
#include "base/input_error.h"

namespace pamsim {
namespace {

// The overrides that make a trial's scenario: its point's, its seed, and the values
// [[randomize]] drew for it (as stored in its `row`).
std::vector<std::string> trial_overrides(const ResultsDb& db, const SweepSummary& sweep,
                                         std::int64_t point, std::uint64_t seed,
                                         const std::map<std::string, DbValue>& row) {
  const PointSummary* at = nullptr;
  for (const PointSummary& p : sweep.points) {
    if (p.point == point) at = &p;
  }
  if (at == nullptr)
    throw InputError(db.path() + ": point " + std::to_string(point) + " is missing");
  std::vector<std::string> overrides = point_overrides(sweep, *at);
  overrides.push_back("seed=" + std::to_string(seed));
  for (const std::string& key : sweep.randomize_keys) {
    overrides.push_back(key + "=" + format_number(row.at(key).number));
  }
  return overrides;
}

}  // namespace

StoredTrial stored_trial(const ResultsDb& db, const SweepSummary& sweep, std::int64_t trial) {
  const std::vector<DbValue> cells = db.trial_row(trial);
  if (cells.empty()) {
    throw InputError(db.path() + ": --trial " + std::to_string(trial) +
                     " is not stored (the sweep has not run it, or it has fewer trials)");
  }
  StoredTrial t;
  t.trial = trial;
  const std::vector<std::string> columns = db.trial_columns();
  for (std::size_t c = 0; c < columns.size() && c < cells.size(); ++c) t.row[columns[c]] = cells[c];
  t.point = static_cast<std::int64_t>(t.row.at("point").number);
  t.seed = static_cast<std::uint64_t>(t.row.at("seed").number);
  t.overrides = trial_overrides(db, sweep, t.point, t.seed, t.row);
  return t;
}

std::map<std::int64_t, std::vector<std::int64_t>> trials_by_point(const ResultsDb& db) {
  const std::vector<std::string> columns = db.trial_columns();
  std::size_t trial_col = columns.size(), point_col = columns.size();
  for (std::size_t c = 0; c < columns.size(); ++c) {
    if (columns[c] == "trial") trial_col = c;
    if (columns[c] == "point") point_col = c;
  }
  std::map<std::int64_t, std::vector<std::int64_t>> out;
  db.for_each_trial([&](const std::vector<DbValue>& cells) {
    if (trial_col >= cells.size() || point_col >= cells.size()) return;
    out[static_cast<std::int64_t>(cells[point_col].number)].push_back(
        static_cast<std::int64_t>(cells[trial_col].number));
  });
  return out;
}

}  // namespace pamsim
