// report_page.h: what `pamsim report --html` puts on a sweep's page that the database does not
// hold: the best points' trials run again (the scenario each ran on, sweep_trials.h) and drawn,
// and the provenance of the page and of the sweep.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "sim/sweep/report.h"
#include "sim/sweep/results_db.h"

namespace pamsim {

inline constexpr std::size_t kReplayedBestPoints = 3;

// A page's foot for a database (its meta's pamsim_version and git_commit) at db_path: what
// made the page and what made the database, escaped; `more` (plain text) after it.
std::string database_footer(const std::string& db_path, const std::string& db_version,
                            const std::string& db_commit, const std::string& more);

// The stored points numbered `asked`; throws InputError ("--html-points N: not a stored point
// of DB ...") for a number that is none.
std::vector<const PointSummary*> asked_points(const SweepSummary& sweep,
                                              const std::vector<std::int64_t>& asked,
                                              const std::string& db_path);

// The page (report_html.h) of the sweep in `db` (at db_path): heat maps of heat_metrics, the
// best kReplayedBestPoints points by `metric` and the points `asked` (point numbers) with
// their trials replayed. Throws InputError for an asked number that is no point of the sweep.
std::string sweep_page_html(const ResultsDb& db, const SweepSummary& sweep,
                            const std::string& db_path, const std::string& metric,
                            const std::vector<std::string>& heat_metrics,
                            const std::vector<std::int64_t>& asked);

}  // namespace pamsim
