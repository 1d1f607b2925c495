// tune_html.h: a tuning as one self-contained HTML page (`pamsim report TUNE_DB --html`): the
// best setting with each parameter's bounds and the objectives it reached, the convergence
// (every evaluation, hovering one showing its setting, and the best feasible so far), and
// every evaluation in a table; what made it at the foot.
#pragma once

#include <string>
#include <vector>

#include "sim/optimize/tune_db.h"
#include "sim/optimize/tuning_file.h"

namespace pamsim {

// history non-empty (a tuning database with no evaluation is refused before).
std::string tune_report_html(const TuneDefinition& def, const std::vector<TuneEvaluation>& history,
                             const std::string& db_path, const std::string& footer_html);

}  // namespace pamsim
