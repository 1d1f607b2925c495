// sweep_report_test.cc: what `pamsim report` says of a sweep database with hand-made
// results: per-point statistics, the best point under its criterion and its ties, the heat
// map's cells and labels, points.csv's columns and intervals, the best point written back as a
// scenario, the best few ranked, and the HTML page's data.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <cmath>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "sim/cli_util.h"
#include "reflex/stretch_reflex_controller.h"
#include "sim/scenario/scenario_file.h"
#include "sim/sweep/report.h"
#include "sim/sweep/report_html.h"
#include "sim/sweep/results_db.h"
#include "sim/sweep/sweep.h"
#include "sim/test_paths.h"

namespace {

namespace fs = std::filesystem;
using pamsim::ResultsDb;
using pamsim::SweepDefinition;
using pamsim_test::fresh_dir;
using pamsim_test::kDropMass;
using pamsim_test::write_text;

class SweepReportTest : public ::testing::Test {
 protected:
  fs::path dir_ = fresh_dir("sweep_report_unit");
};

// A sweep database with hand-made results: point p, seed i has peak drop 10 + p + i and
// mistrips only at point 0.
pamsim::SweepSummary synthetic_summary(const fs::path& dir) {
  write_text(dir / "sweep.toml",
             "base = \"" + kDropMass +
                 "\"\n"
                 "seeds = 3\n[[axis]]\nkey = \"reflex.v_thr_mm_s\"\nvalues = [50.0, 60.0]\n"
                 "[[axis]]\nkey = \"reflex.k_MPa_s_per_mm\"\nvalues = [0.001, 0.002, 0.003]\n");
  const SweepDefinition s = pamsim::load_sweep((dir / "sweep.toml").string());
  const std::string path = (dir / "synthetic.db").string();
  fs::remove(path);
  ResultsDb db = ResultsDb::create(path, s);
  std::vector<pamsim::TrialRecord> records;
  for (std::int64_t t = 0; t < s.trials(); ++t) {
    pamsim::TrialRecord r;
    r.trial = t;
    r.point = t / 3;
    r.seed_index = t % 3;
    r.summary.seed = s.seed_of(t);
    // recovery 1 + p s, but point 1 never recovers in its first seed
    r.summary.metrics = {
        {"peak_drop_deg", 10.0 + static_cast<double>(r.point) + static_cast<double>(r.seed_index)},
        {"mistrips", r.point == 0 ? 1.0 : 0.0, true},
        {"recovery_time_s",
         r.point == 1 && r.seed_index == 0 ? std::nan("") : 1.0 + static_cast<double>(r.point)}};
    if (r.point == 5 && r.seed_index == 2) r.summary.status = "diverged";
    records.push_back(r);
  }
  db.insert(s, records);
  return pamsim::summarize_sweep(db);
}

TEST_F(SweepReportTest, StatisticsAndBestPointFollowTheCriterion) {
  const pamsim::SweepSummary sweep = synthetic_summary(dir_);
  ASSERT_EQ(sweep.points.size(), 6u);
  EXPECT_EQ(sweep.trials_not_ok, 1);
  const int m = sweep.metric_index("peak_drop_deg");
  ASSERT_GE(m, 0);
  const pamsim::MetricStats& p2 = sweep.points[2].metrics[m];
  EXPECT_EQ(p2.count, 3);
  EXPECT_DOUBLE_EQ(p2.mean, 13.0);  // 12, 13, 14
  EXPECT_DOUBLE_EQ(p2.std, 1.0);
  EXPECT_EQ(p2.min, 12.0);
  EXPECT_EQ(p2.max, 14.0);
  EXPECT_EQ(sweep.points[0].mistrip_rate(), 1.0);
  EXPECT_EQ(sweep.points[1].mistrip_rate(), 0.0);
  EXPECT_EQ(sweep.points[5].ok, 2);

  // point 0 has the smallest drop but mistrips: the best is point 1
  const pamsim::PointSummary* best = pamsim::best_point(sweep, "peak_drop_deg");
  ASSERT_NE(best, nullptr);
  EXPECT_EQ(best->point, 1);

  // by recovery time, point 1 (one seed never recovers) does not qualify
  const pamsim::PointSummary* by_recovery = pamsim::best_point(sweep, "recovery_time_s");
  ASSERT_NE(by_recovery, nullptr);
  EXPECT_EQ(by_recovery->point, 2);

  // a tie goes to the lowest point number, as the criterion says
  pamsim::SweepSummary tie = sweep;
  tie.points[3].metrics[m].mean = 1.0;
  tie.points[2].metrics[m].mean = 1.0;
  const pamsim::PointSummary* tied = pamsim::best_point(tie, "peak_drop_deg");
  ASSERT_NE(tied, nullptr);
  EXPECT_EQ(tied->point, 2);
}

TEST_F(SweepReportTest, HeatMapCellsAndLabelsSayWhatTheyShow) {
  const pamsim::SweepSummary sweep = synthetic_summary(dir_);
  const pamsim::PointSummary* best = pamsim::best_point(sweep, "peak_drop_deg");
  // heat map cells: x = v_thr level, y = k level
  const pamsim::HeatMap map = pamsim::sweep_heat_map(sweep, "peak_drop_deg", best, "peak_drop_deg");
  ASSERT_EQ(map.cells.size(), 6u);
  EXPECT_DOUBLE_EQ(map.cells[0 * 2 + 1], 14.0);  // v = 60 (ix 1), k = 0.001 (iy 0): point 3
  EXPECT_DOUBLE_EQ(map.cells[2 * 2 + 0], 13.0);  // v = 50, k = 0.003: point 2
  EXPECT_EQ(map.mark_x, 0.0);
  EXPECT_EQ(map.mark_y, 1.0);
  EXPECT_EQ(map.x_levels, (std::vector<std::string>{"50", "60"}));
  // labelled for a reader: meaning, unit and key; the spread beside the mean; the tie rule
  EXPECT_EQ(map.x_label, "trigger threshold V_thr, Eq. (12) [mm/s] (reflex.v_thr_mm_s)");
  EXPECT_NE(map.y_label.find("[MPa s/mm]"), std::string::npos) << map.y_label;
  EXPECT_EQ(map.title, "peak drop [deg]: mean ± SD over 3 seeds per point");
  ASSERT_EQ(map.cell_texts.size(), 6u);
  EXPECT_EQ(map.cell_texts[2 * 2 + 0], "13 ± 1");  // point 2: 12, 13, 14
  EXPECT_NE(map.mark_label.find("ties: lowest point"), std::string::npos);
  EXPECT_NE(pamsim::best_criterion(sweep, "peak_drop_deg").find("ties: the lowest point number"),
            std::string::npos);
  EXPECT_EQ(pamsim::metric_label("recovery_time_s"), "recovery time [s]");
  EXPECT_EQ(pamsim::metric_label("length_est_rmse_pct"), "length est rmse [% of length]");
  EXPECT_EQ(pamsim::metric_label("mistrips"), "mistrips");
}

TEST_F(SweepReportTest, PointsCsvGivesTheHeadlineMetricsAndAnIncompleteSweepSaysSo) {
  const pamsim::SweepSummary sweep = synthetic_summary(dir_);
  const pamsim::PointSummary* best = pamsim::best_point(sweep, "peak_drop_deg");
  // points.csv: the headline metrics with SD and 95 % interval; every column on request
  const std::string csv = pamsim::points_csv(sweep);
  const std::string header = csv.substr(0, csv.find('\n'));
  EXPECT_EQ(header.rfind("point,reflex.v_thr_mm_s,reflex.k_MPa_s_per_mm,trials,ok,mistrip_rate,"
                         "peak_drop_deg_mean,peak_drop_deg_sd,peak_drop_deg_ci95_low,"
                         "peak_drop_deg_ci95_high,recovery_time_s_mean",
                         0),
            0u)
      << header;
  EXPECT_EQ(header.find("_min"), std::string::npos) << header;
  const std::string row2 = csv.substr(csv.find("\n2,") + 1);
  // point 2: 12, 13, 14 -> mean 13, sd 1, 13 -+ t(0.975, 2) / sqrt(3)
  const double half = 4.30265272974946 / std::sqrt(3.0);
  std::istringstream cells(row2.substr(0, row2.find('\n')));
  std::vector<std::string> cell;
  for (std::string c; std::getline(cells, c, ',');) cell.push_back(c);
  ASSERT_GE(cell.size(), 10u);
  EXPECT_EQ(cell[6], "13");
  EXPECT_EQ(cell[7], "1");
  EXPECT_NEAR(std::stod(cell[8]), 13 - half, 1e-12);
  EXPECT_NEAR(std::stod(cell[9]), 13 + half, 1e-12);
  const std::string all = pamsim::points_csv(sweep, "peak_drop_deg", true);
  EXPECT_NE(all.find("peak_drop_deg_mean,peak_drop_deg_std,peak_drop_deg_min,peak_drop_deg_max"),
            std::string::npos);

  // an incomplete sweep says so in its title
  pamsim::SweepSummary part = sweep;
  part.trials_stored = 10;
  EXPECT_NE(pamsim::sweep_heat_map(part, "peak_drop_deg", best, "peak_drop_deg")
                .title.find("INCOMPLETE: 10 of 18 trials stored"),
            std::string::npos);
}

// A best point on a grid's first or last level is named: a better one may lie beyond.
TEST_F(SweepReportTest, APointOnTheGridsEdgeIsNamed) {
  const pamsim::SweepSummary sweep = synthetic_summary(dir_);
  // point 1: v = 50 (the lowest of 50, 60), k = 0.002 (inside 0.001-0.003)
  EXPECT_EQ(pamsim::grid_edges_of(sweep, sweep.points[1]),
            (std::vector<std::string>{"reflex.v_thr_mm_s = 50.0 (the grid's lowest level)"}));
  // point 3: v = 60 (the highest), k = 0.001 (the lowest)
  EXPECT_EQ(pamsim::grid_edges_of(sweep, sweep.points[3]).size(), 2u);
  pamsim::SweepSummary random = sweep;
  random.design = "random";
  EXPECT_TRUE(pamsim::grid_edges_of(random, sweep.points[3]).empty());
}

TEST_F(SweepReportTest, BestScenarioKeepsTheBaseAndSetsThePoint) {
  const pamsim::SweepSummary sweep = synthetic_summary(dir_);
  const pamsim::PointSummary* best = pamsim::best_point(sweep, "peak_drop_deg");
  ASSERT_NE(best, nullptr);
  const fs::path out = dir_ / "elsewhere" / "deeper";
  fs::create_directories(out);
  const std::string text = pamsim::point_scenario_toml(sweep, *best, out.string(), "# header\n");
  write_text(out / "best.toml", text);
  const pamsim::Scenario sc = pamsim::load_scenario((out / "best.toml").string(), {});
  const pamsim::Scenario base = pamsim::load_scenario(kDropMass, {});
  const auto* reflex = sc.controller_config<pamsim::StretchReflexScenarioConfig>();
  ASSERT_NE(reflex, nullptr);
  EXPECT_DOUBLE_EQ(reflex->reflex.v_thr_m_s, 50.0e-3);  // the file's 50 mm/s, in SI
  EXPECT_DOUBLE_EQ(reflex->reflex.k_pa_s_per_m, 0.002e9);
  EXPECT_EQ(fs::weakly_canonical(sc.model_file), fs::weakly_canonical(base.model_file));
  EXPECT_EQ(sc.duration_s, base.duration_s);
  EXPECT_EQ(text.rfind("# header\n", 0), 0u);
}

// a case's name is any string: in table.md it stays one cell (a '|' would end the cell, a
// backslash escape the next character, a line break end the row)
// The best few, in the criterion's order; each point's cell on the grid (first axis slowest)
TEST_F(SweepReportTest, BestPointsAreRankedAndEachPointHasItsGridCell) {
  const pamsim::SweepSummary sweep = synthetic_summary(dir_);
  // point 0 mistrips, point 5 has a diverged seed: the others by their mean drop, 11 + p
  std::vector<std::int64_t> ranked;
  for (const pamsim::PointSummary* p : pamsim::best_points(sweep, "peak_drop_deg", 10)) {
    ranked.push_back(p->point);
  }
  EXPECT_EQ(ranked, (std::vector<std::int64_t>{1, 2, 3, 4}));
  ASSERT_EQ(pamsim::best_points(sweep, "peak_drop_deg", 2).size(), 2u);
  EXPECT_EQ(pamsim::best_points(sweep, "peak_drop_deg", 1).front(),
            pamsim::best_point(sweep, "peak_drop_deg"));
  for (std::int64_t p = 0; p < 6; ++p) {
    const auto [ix, iy] = pamsim::grid_cell_of(sweep, p);
    EXPECT_EQ(ix, static_cast<std::size_t>(p / 3)) << p;  // v_thr: 2 levels
    EXPECT_EQ(iy, static_cast<std::size_t>(p % 3)) << p;  // k: 3 levels
  }
}

// The page's data, read back as its script reads them: every point with its statistics, the
// cells' points, the replayed flagged, a replay line for the others
TEST_F(SweepReportTest, ThePagesDataAreThePointsStatistics) {
  const pamsim::SweepSummary sweep = synthetic_summary(dir_);
  pamsim::SweepPage page;
  page.sweep = &sweep;
  page.metric = "peak_drop_deg";
  page.heat_metrics = {"peak_drop_deg"};
  page.best = pamsim::best_points(sweep, "peak_drop_deg", 1);
  page.replayed = page.best;
  page.charts[1] = {pamsim::LineChart{"joint", "time [s]", "angle_deg", {}}};
  page.first_trial = {{2, 6}};
  page.db_path = "sweep.db";
  const std::string html = pamsim::sweep_report_html(page);
  const std::string open = "<script type=\"application/json\" id=\"page-data\">";
  const std::size_t from = html.find(open) + open.size();
  const nlohmann::json data =
      nlohmann::json::parse(html.substr(from, html.find("</script>", from) - from));
  ASSERT_EQ(data["points"].size(), 6u);
  const int m = sweep.metric_index("peak_drop_deg");
  EXPECT_EQ(data["points"][2]["metrics"][m][0].get<double>(), 13.0);  // 12, 13, 14
  EXPECT_EQ(data["points"][2]["metrics"][m][1].get<double>(), 1.0);
  EXPECT_TRUE(data["points"][1]["replayed"].get<bool>());
  EXPECT_FALSE(data["points"][2]["replayed"].get<bool>());
  EXPECT_EQ(data["points"][2]["replay"], "pamsim replay sweep.db --trial 6");
  EXPECT_EQ(data["maps"]["map-peak_drop_deg"]["cells"]["1,0"], nlohmann::json::array({3}));
  std::size_t cells = 0;
  for (std::size_t at = html.find("class=\"cell"); at != std::string::npos;
       at = html.find("class=\"cell", at + 1)) {
    ++cells;
  }
  EXPECT_EQ(cells, 6u);
  EXPECT_NE(html.find("id=\"point-1\""), std::string::npos);  // its trials' section
}

TEST(MarkdownCellTest, APipeABackslashAndALineBreakStayInOneCell) {
  EXPECT_EQ(pamsim::markdown_cell("light, high gain"), "light, high gain");
  EXPECT_EQ(pamsim::markdown_cell("a|b\\c\nd"), "a\\|b\\\\c d");
}

}  // namespace
