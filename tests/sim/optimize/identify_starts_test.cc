// identify_starts_test.cc: the polish from several starts (identify_file.h's `starts`). A
// start that ends more than chi-square(1)'s 3.84 above the result's cost is reported as a
// local minimum, one that ends as low elsewhere as a minimum the recordings do not single
// out, and one at the result's end not at all; on the example arm, the result is the lowest
// of the starts' ends, and the first start (the global search's best point) ends where a
// single-start run ends, bit for bit.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include "sim/cli_util.h"
#include "sim/identify_test_arm.h"
#include "sim/optimize/identify.h"
#include "sim/optimize/identify_outputs.h"

namespace pamsim {
namespace {

namespace fs = std::filesystem;

IdentifyDefinition two_walls() {
  IdentifyDefinition def;
  def.parameters = {{"muscles.agonist.plant.geometry.wall_thickness_mm", 1.0, 3.0, false},
                    {"muscles.antagonist.plant.geometry.wall_thickness_mm", 2.0, 4.0, false}};
  return def;
}

TEST(IdentifyStartsTest, ALocalMinimumAndAnEqualMinimumElsewhereAreEachOneLine) {
  const IdentifyDefinition def = two_walls();
  IdentifyResult r;
  r.starts = {{{0.5, 0.5}, {0.2, 0.5}, 10.0, true},     // the result
              {{0.9, 0.1}, {0.8, 0.5}, 20.0, true},     // 10 above it: a local minimum
              {{0.1, 0.9}, {0.2, 0.9}, 11.0, true},     // 1 above it, elsewhere: not unique
              {{0.3, 0.3}, {0.2, 0.505}, 10.5, true}};  // 0.005 of the box away: the same end
  r.best_start = 0;
  const std::vector<std::string> lines = start_warnings(def, r);
  ASSERT_EQ(lines.size(), 2u);
  EXPECT_EQ(lines[0],
            "the polish's start 2 of 4 ended in a local minimum: cost 20 against the "
            "result's 10 (start 1), at muscles.agonist.plant.geometry."
            "wall_thickness_mm = 2.6 against 1.4");
  EXPECT_EQ(lines[1].rfind("the polish's start 3 of 4 ended as low at another point: cost 11", 0),
            0u)
      << lines[1];
  EXPECT_NE(lines[1].find("antagonist.plant.geometry.wall_thickness_mm = 3.8 against 3"),
            std::string::npos)
      << lines[1];
  // with the result's standard errors, the distance is counted in them, among the
  // parameters the recordings determine (the second is not: it is never named)
  r.parameters.resize(2);
  r.parameters[0].std_error = 0.1;
  r.parameters[1].identifiable = false;
  EXPECT_EQ(start_warnings(def, r)[0].substr(start_warnings(def, r)[0].find(", at ")),
            ", at muscles.agonist.plant.geometry.wall_thickness_mm = 2.6 against 1.4 "
            "(12 standard errors)");
  EXPECT_EQ(start_warnings(def, r).size(), 1u)
      << "start 3 differs only in the undetermined wall: the same minimum";
  r.starts[1].converged = false;
  EXPECT_NE(start_warnings(def, r)[0].find("start 2 of 4 stopped without converging"),
            std::string::npos);
  r.starts.resize(1);
  EXPECT_TRUE(start_warnings(def, r).empty()) << "one start: nothing to compare";
}

TEST(IdentifyStartsTest, TheGlobalSearchIsNamedAsItRan) {
  IdentifyDefinition def = two_walls();
  def.generations = 0;
  EXPECT_EQ(global_search_text(def, IdentifyResult{}), "none: generations = 0");
  def.generations = 6;
  def.population = 8;
  def.runs = 1;
  def.stall_generations = 0;
  EXPECT_EQ(global_search_text(def, IdentifyResult{}), "6 generations of 8")
      << "one run of a fixed length, as files before the runs were";
}

TEST(IdentifyStartsTest, FewerStartsThanAskedIsOneLineWithItsReason) {
  IdentifyDefinition def = two_walls();
  def.starts = 3;
  IdentifyResult r;
  r.starts = {{{0.5, 0.5}, {0.2, 0.5}, 10.0, true}};
  def.generations = 0;
  ASSERT_EQ(start_warnings(def, r).size(), 1u);
  EXPECT_EQ(start_warnings(def, r)[0],
            "starts = 3 asked, 1 run: without a global search (generations = 0) the polish "
            "starts from the middle of the box alone");
  def.generations = 2;
  r.starts.push_back({{0.9, 0.1}, {0.2, 0.5}, 10.0, true});
  ASSERT_EQ(start_warnings(def, r).size(), 1u);
  EXPECT_EQ(start_warnings(def, r)[0].rfind("starts = 3 asked, 2 run: the global search's "
                                            "points held no more that lie 0.1 of the box apart",
                                            0),
            0u)
      << start_warnings(def, r)[0];
  r.interrupted = true;
  EXPECT_TRUE(start_warnings(def, r).empty()) << "an interrupted run resumes with every start";
  r.interrupted = false;
  def.starts = 2;
  EXPECT_TRUE(start_warnings(def, r).empty());
}

// The wall fitted from `starts` starts to the 2 s step recording dir/steps.csv.
IdentifyResult fit_from(const fs::path& dir, int starts) {
  const fs::path file = dir / ("id" + std::to_string(starts) + ".toml");
  pamsim_test::write_text(
      file, "base = \"" + kArm +
                "\"\noverrides = [\"sim.duration_s=2\"]\nruns = 1\ngenerations = 2\n"
                "population = 6\npolish_iterations = 10\nstarts = " +
                std::to_string(starts) +
                "\n"
                "[[parameter]]\nkey = \"muscles.antagonist.plant.geometry.wall_thickness_mm\"\n"
                "from = 2.0\nto = 4.0\n"
                "[[recording]]\nfile = \"steps.csv\"\nset = ['" +
                kSteps + "']\n");
  const IdentifyDefinition def = load_identify_definition(file.string());
  IdentifyDb db = IdentifyDb::create((dir / ("id" + std::to_string(starts) + ".db")).string(), def);
  IdentifyRunOptions options;
  options.threads = 2;
  return run_identify(def, db, options);
}

TEST(IdentifyStartsTest, TheResultIsTheLowestEndAndTheFirstStartEndsAsASingleStartDoes) {
  const fs::path dir = pamsim_test::fresh_dir("identify_starts");
  record_arm(dir / "steps.csv", kSteps);
  const IdentifyResult one = fit_from(dir, 1);
  const IdentifyResult three = fit_from(dir, 3);
  ASSERT_EQ(one.starts.size(), 1u);
  ASSERT_GE(three.starts.size(), 2u) << "twelve CMA-ES points hold starts 0.1 apart";
  EXPECT_EQ(three.starts[0].start, one.starts[0].start);
  EXPECT_EQ(three.starts[0].end, one.starts[0].end);
  EXPECT_EQ(three.starts[0].cost, one.cost_final);
  double lowest = three.starts[0].cost;
  for (const PolishEnd& e : three.starts) lowest = std::min(lowest, e.cost);
  EXPECT_EQ(three.cost_final, lowest);
  EXPECT_EQ(three.unit, three.starts[three.best_start].end);
  for (std::size_t k = 1; k < three.starts.size(); ++k) {
    EXPECT_GE(std::abs(three.starts[k].start[0] - three.starts[0].start[0]), 0.1);
  }
}

}  // namespace
}  // namespace pamsim
