// identify_runs_test.cc: the global search's independent runs (identify_file.h's `runs`) and
// what they let the verdict say. Runs whose polished ends agree (cost within 10 %, every
// determined parameter within 2 standard errors) settle the search; runs that end apart mean
// the search, not the model, is why a recording is not explained, and the verdict says so
// instead of blaming the model. On the example arm: a search cut short on purpose did not
// settle; two full runs find the wall and settle; a recording read 60 ms late is still one
// the model does not explain; a run with a stall stop ends when its cost stops falling.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include "sim/cli_util.h"
#include "sim/identify_test_arm.h"
#include "sim/optimize/identify.h"
#include "sim/optimize/identify_outputs.h"
#include "sim/optimize/identify_uncertainty.h"

namespace pamsim {
namespace {

namespace fs = std::filesystem;

// the antagonist's wall from the steps recording (`delay_rows` late) with the search `search`
IdentifyResult identify_wall_by_runs(const fs::path& dir, const std::string& search,
                                     std::size_t delay_rows = 0) {
  record_arm(dir / "steps.csv", kSteps, delay_rows);
  pamsim_test::write_text(
      dir / "id.toml",
      "base = \"" + kArm + "\"\noverrides = [\"sim.duration_s=2\"]\n" + search +
          "[[parameter]]\nkey = \"muscles.antagonist.plant.geometry.wall_thickness_mm\"\n"
          "from = 2.0\nto = 4.0\n[[recording]]\nfile = \"steps.csv\"\nset = ['" +
          kSteps + "']\n");
  const IdentifyDefinition def = load_identify_definition((dir / "id.toml").string());
  IdentifyDb db = IdentifyDb::create((dir / "id.db").string(), def);
  IdentifyRunOptions options;
  options.threads = 2;
  return run_identify(def, db, options);
}

const SearchParameter kWall{"muscles.antagonist.plant.geometry.wall_thickness_mm", 2.0, 4.0, false};

// a result of two runs' ends and a further start, built by hand: the result's wall 2.7 mm
// (0.35 of the box) +- 0.05 at cost 100, the second run's end at `second_cost` and `second_u`
IdentifyResult two_runs(double second_cost, double second_u) {
  IdentifyResult r;
  IdentifiedParameter wall;
  wall.parameter = kWall;
  wall.value = 2.7;
  wall.std_error = 0.05;
  r.parameters = {wall};
  r.starts = {{{0.5}, {0.35}, 100.0, true, 0},
              {{0.2}, {second_u}, second_cost, true, 1},
              {{0.9}, {0.9}, 900.0, true, -1}};  // a further start: never counted
  r.best_start = 0;
  return r;
}

TEST(IdentifyRunsTest, RunsAgreeWithinTheirCostAndTwoStandardErrors) {
  IdentifyDefinition def;
  def.parameters = {kWall};
  EXPECT_EQ(judge_settled(def, two_runs(105.0, 0.375)), SearchSettled::kSettled)
      << "5 % costlier, 1 standard error apart";
  EXPECT_EQ(judge_settled(def, two_runs(105.0, 0.425)), SearchSettled::kNotSettled)
      << "3 standard errors apart";
  EXPECT_EQ(judge_settled(def, two_runs(115.0, 0.35)), SearchSettled::kNotSettled)
      << "15 % costlier";
  // near a cost of 0 the margin is chi-square's 3.84, not 10 %
  IdentifyResult tiny = two_runs(3.0, 0.35);
  tiny.starts[0].cost = 0.001;
  EXPECT_EQ(judge_settled(def, tiny), SearchSettled::kSettled);
  // a parameter the recordings do not determine may end anywhere
  IdentifyDefinition two = def;
  two.parameters.push_back({"bodies.ball.mass_kg", 0.1, 0.4, false});
  IdentifyResult free = two_runs(105.0, 0.375);
  free.parameters.push_back(free.parameters[0]);
  free.parameters[1].parameter = two.parameters[1];
  free.parameters[1].identifiable = false;
  free.starts[0].end.push_back(0.1);
  free.starts[1].end.push_back(0.9);
  free.starts[2].end.push_back(0.5);
  EXPECT_EQ(judge_settled(two, free), SearchSettled::kSettled);
  // one run: nothing to compare
  IdentifyResult one = two_runs(105.0, 0.35);
  one.starts.resize(1);
  EXPECT_EQ(judge_settled(def, one), SearchSettled::kNotChecked);
}

TEST(IdentifyRunsTest, AnUnexplainedFitOfUnsettledRunsBlamesTheSearchInOneLine) {
  IdentifyResult r = two_runs(400.0, 0.6);
  ChannelFit fit;
  fit.recording = "steps";
  fit.channel = "angle_deg";
  fit.rmse_after = 2.0;
  fit.noise_floor = 0.1;
  fit.explained = false;
  r.fits = {fit};
  r.settled = SearchSettled::kSettled;
  EXPECT_EQ(distrust_reason(r), "the model does not explain the recordings");
  EXPECT_EQ(unexplained_channels(r).at(0).rfind("the model does not explain recording steps", 0),
            0u);
  r.settled = SearchSettled::kNotSettled;
  EXPECT_EQ(distrust_reason(r), "the search did not settle");
  EXPECT_EQ(unexplained_channels(r),
            std::vector<std::string>{"the search did not settle: its 2 runs ended at costs 100, "
                                     "400; run with more runs (runs = 3) or generations"});
  r.fits[0].explained = true;
  EXPECT_EQ(distrust_reason(r), "") << "explained: nothing to distrust, settled or not";
  EXPECT_TRUE(unexplained_channels(r).empty());
}

TEST(IdentifyRunsTest, ASearchCutShortDidNotSettleAndTheModelIsNotBlamed) {
  const fs::path dir = pamsim_test::fresh_dir("identify_runs_short");
  const IdentifyResult r = identify_wall_by_runs(
      dir, "runs = 2\ngenerations = 1\npopulation = 5\npolish_iterations = 0\n");
  ASSERT_EQ(r.starts.size(), 2u);
  EXPECT_EQ(r.starts[0].run, 0);
  EXPECT_EQ(r.starts[1].run, 1);
  ASSERT_EQ(r.fits.size(), 1u);
  ASSERT_FALSE(r.fits[0].explained) << r.fits[0].rmse_after << " vs " << r.fits[0].noise_floor;
  EXPECT_EQ(r.settled, SearchSettled::kNotSettled);
  const std::vector<std::string> lines = unexplained_channels(r);
  ASSERT_EQ(lines.size(), 1u);
  EXPECT_EQ(lines[0].rfind("the search did not settle: its 2 runs ended at costs ", 0), 0u)
      << lines[0];
  const IdentifyDefinition def = load_identify_definition((dir / "id.toml").string());
  const std::string md = identify_markdown(def, r);
  EXPECT_NE(md.find("not to be trusted: the search did not settle"), std::string::npos);
  EXPECT_EQ(md.find("does not explain"), std::string::npos);
}

TEST(IdentifyRunsTest, TwoFullRunsFindTheWallAndSettle) {
  const IdentifyResult r =
      identify_wall_by_runs(pamsim_test::fresh_dir("identify_runs_full"),
                            "runs = 2\ngenerations = 2\npopulation = 6\npolish_iterations = 10\n");
  ASSERT_EQ(r.starts.size(), 2u);
  EXPECT_EQ(r.settled, SearchSettled::kSettled)
      << r.starts[0].cost << " at " << r.starts[0].end[0] << ", " << r.starts[1].cost << " at "
      << r.starts[1].end[0] << "; se " << r.parameters[0].std_error << " plain "
      << r.parameters[0].std_error_plain;
  ASSERT_EQ(r.fits.size(), 1u);
  EXPECT_TRUE(r.fits[0].explained);
  EXPECT_NEAR(r.parameters[0].value, 2.7, std::max(3 * r.parameters[0].std_error, 0.01));
}

TEST(IdentifyRunsTest, ARecordingReadLateIsStillOneTheModelDoesNotExplain) {
  const IdentifyResult r = identify_wall_by_runs(
      pamsim_test::fresh_dir("identify_runs_late"),
      "runs = 2\ngenerations = 2\npopulation = 6\npolish_iterations = 10\n", 6);  // 60 ms
  EXPECT_EQ(r.settled, SearchSettled::kSettled);
  const std::vector<std::string> lines = unexplained_channels(r);
  ASSERT_EQ(lines.size(), 1u);
  EXPECT_EQ(lines[0].rfind("the model does not explain recording steps (angle_deg)", 0), 0u)
      << lines[0];
}

TEST(IdentifyRunsTest, ARunEndsWhenItsCostStallsAndSaysSo) {
  const fs::path dir = pamsim_test::fresh_dir("identify_runs_stall");
  const IdentifyResult r =
      identify_wall_by_runs(dir,
                            "runs = 2\ngenerations = 60\npopulation = 5\nstall_generations = 3\n"
                            "polish_iterations = 10\n");
  ASSERT_EQ(r.run_generations.size(), 2u);
  for (unsigned g : r.run_generations) {
    EXPECT_GE(g, 3u);
    EXPECT_LT(g, 60u) << "one wall is found in far fewer generations";
  }
  EXPECT_EQ(r.settled, SearchSettled::kSettled)
      << r.starts[0].cost << " at " << r.starts[0].end[0] << " after " << r.run_generations[0]
      << ", " << r.starts[1].cost << " at " << r.starts[1].end[0] << " after "
      << r.run_generations[1] << "; se " << r.parameters[0].std_error;
  const IdentifyDefinition def = load_identify_definition((dir / "id.toml").string());
  EXPECT_EQ(global_search_text(def, r),
            "2 runs: " + std::to_string(r.run_generations[0]) + " generations of 5, " +
                std::to_string(r.run_generations[1]) +
                " of 10; a run ends after 3 generations without progress, or at 60");
}

}  // namespace
}  // namespace pamsim
