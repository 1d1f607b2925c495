// report_page.cc: see report_page.h.
#include "sim/cli/report_page.h"

#include <algorithm>
#include <cstdio>

#include "base/input_error.h"

#include "sim/cli/sweep_trials.h"
#include "sim/core/trial.h"
#include "sim/core/trial_model.h"
#include "sim/io/build_info.h"
#include "sim/io/html_page.h"
#include "sim/io/provenance.h"
#include "sim/scenario/scenario_file.h"
#include "sim/sweep/report_html.h"

namespace pamsim {
namespace {

// A point's stored trials run again, charted (a series per seed)
std::vector<LineChart> replayed_charts(const ResultsDb& db, const SweepSummary& sweep,
                                       const std::vector<std::int64_t>& trials) {
  std::vector<Trajectory> logs;
  std::vector<std::string> labels;
  for (const std::int64_t trial : trials) {
    const StoredTrial t = stored_trial(db, sweep, trial);
    const Scenario sc = load_scenario_text(sweep.base_scenario, sweep.base_path, t.overrides);
    const TrialModel model = load_trial_model(sc);
    logs.push_back(run_trial(model, sc, t.seed, true).trajectory);
    labels.push_back("trial " + std::to_string(trial) + ", seed " + std::to_string(t.seed));
  }
  std::vector<std::pair<std::string, const Trajectory*>> charted;
  for (std::size_t i = 0; i < logs.size(); ++i) charted.emplace_back(labels[i], &logs[i]);
  return trial_charts(charted);
}

}  // namespace

std::string database_footer(const std::string& db_path, const std::string& db_version,
                            const std::string& db_commit, const std::string& more) {
  const BuildInfo b = build_info();
  return html_escape("Made by pamsim " + b.pamsim_version + " (commit " + b.git_commit + ") from " +
                     db_path + ", written by pamsim " + db_version + " (commit " + db_commit +
                     "). " + more);
}

std::vector<const PointSummary*> asked_points(const SweepSummary& sweep,
                                              const std::vector<std::int64_t>& asked,
                                              const std::string& db_path) {
  std::vector<const PointSummary*> points;
  for (const std::int64_t n : asked) {
    const auto at = std::find_if(sweep.points.begin(), sweep.points.end(),
                                 [n](const PointSummary& p) { return p.point == n; });
    if (at == sweep.points.end()) {
      throw InputError("--html-points " + std::to_string(n) + ": not a stored point of " + db_path +
                       " (points 0-" + std::to_string(sweep.points_total - 1) + ")");
    }
    points.push_back(&*at);
  }
  return points;
}

std::string sweep_page_html(const ResultsDb& db, const SweepSummary& sweep,
                            const std::string& db_path, const std::string& metric,
                            const std::vector<std::string>& heat_metrics,
                            const std::vector<std::int64_t>& asked) {
  SweepPage page;
  page.sweep = &sweep;
  page.metric = metric;
  page.heat_metrics = heat_metrics;
  page.db_path = db_path;
  page.best = best_points(sweep, metric, kReplayedBestPoints);
  page.replayed = page.best;
  for (const PointSummary* p : asked_points(sweep, asked, db_path)) {
    if (std::find(page.replayed.begin(), page.replayed.end(), p) == page.replayed.end()) {
      page.replayed.push_back(p);
    }
  }
  const std::map<std::int64_t, std::vector<std::int64_t>> trials = trials_by_point(db);
  for (const auto& [point, list] : trials) page.first_trial[point] = list.front();
  for (const PointSummary* p : page.replayed) {
    const auto t = trials.find(p->point);
    if (t != trials.end()) page.charts[p->point] = replayed_charts(db, sweep, t->second);
  }
  char digest[17];
  std::snprintf(digest, sizeof(digest), "%016llx",
                static_cast<unsigned long long>(fnv1a64(sweep.base_scenario)));
  page.footer_html =
      database_footer(db_path, db.meta("pamsim_version"), db.meta("git_commit"),
                      "Its base scenario " + sweep.base_path + ", FNV-1a digest " + digest +
                          ". The replayed points' trials were run again when the page was made.");
  return sweep_report_html(page);
}

}  // namespace pamsim
