// sweep_trials.h: one stored trial of a sweep database, and the scenario the sweep ran it on
// (the base scenario stored in the database, its fixed keys, the point's axis values, the
// trial's seed and its [[randomize]] draws): what `pamsim replay` runs again and writes out, and
// what `pamsim report --html` runs again to draw the best points' trials.
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "sim/sweep/report.h"
#include "sim/sweep/results_db.h"

namespace pamsim {

struct StoredTrial {
  std::int64_t trial = 0, point = 0;
  std::uint64_t seed = 0;
  std::map<std::string, DbValue> row;  // its stored cells by column name
  std::vector<std::string> overrides;  // the point's, its seed, its [[randomize]] draws
};

// Trial `trial` of the database; throws InputError when it is not stored.
StoredTrial stored_trial(const ResultsDb& db, const SweepSummary& sweep, std::int64_t trial);

// The stored trials of each point (by point number), in trial order.
std::map<std::int64_t, std::vector<std::int64_t>> trials_by_point(const ResultsDb& db);

}  // namespace pamsim
