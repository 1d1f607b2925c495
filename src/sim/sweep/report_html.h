// report_html.h: a sweep's report as one self-contained HTML page (`pamsim report --html`):
// its heat maps, hovering a cell showing its points' metrics with their spread over the seeds
// and the `pamsim replay` line of their first trial; the best points' trials and those of any
// point asked for (the joint's position and the pressures, replayed when the page was made)
// opening from their cells and from the table of points; the provenance at its foot. The page's
// data ride along as JSON, read by its script; nothing is fetched.
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "sim/io/html_page.h"
#include "sim/sweep/report.h"

namespace pamsim {

struct SweepPage {
  const SweepSummary* sweep = nullptr;
  std::string metric;                         // the criterion's (report --metric)
  std::vector<std::string> heat_metrics;      // a heat map each (grids and scattered designs)
  std::vector<const PointSummary*> best;      // best first (best_points)
  std::vector<const PointSummary*> replayed;  // the best, then the points asked for
  std::map<std::int64_t, std::vector<LineChart>> charts;  // by replayed point: its trials
  std::map<std::int64_t, std::int64_t> first_trial;       // by point: its first stored trial
  std::string db_path;
  std::string footer_html;  // what made the page (escaped HTML)
};

std::string sweep_report_html(const SweepPage& page);

}  // namespace pamsim
