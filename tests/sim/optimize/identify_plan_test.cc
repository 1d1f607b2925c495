// identify_plan_test.cc: `pamsim identify --plan` (identify_plan.h). The D-optimal gain and
// the standard deviations after against their closed forms for a linear model; on the example
// arm, a candidate that drops the ball determines its mass (which no recording sees) and
// ranks first, while one that never moves the ball leaves the mass exactly at its prior; a
// fitted recording whose trial fails is named as left out; and every bad [[candidate]] is one line
// naming its key, exit 2, nothing written.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include "sim/cli_util.h"
#include "sim/identify_test_arm.h"
#include "sim/optimize/identify.h"
#include "sim/optimize/identify_plan.h"

namespace pamsim {
namespace {

namespace fs = std::filesystem;

// y = a + b t with white noise of sd 1, the prior I: n samples at t = 0 carry
// F = n [[1, 0], [0, 0]]; n / 2 at t = -1 and n / 2 at t = +1 carry n I.
TEST(IdentifyPlanTest, TheGainAndStandardDeviationsAreTheLinearModelsClosedForms) {
  const double n = 50.0;
  const Eigen::MatrixXd prior = Eigen::MatrixXd::Identity(2, 2);
  Eigen::MatrixXd at_zero = Eigen::MatrixXd::Zero(2, 2);
  at_zero(0, 0) = n;
  const Eigen::MatrixXd spread = n * Eigen::MatrixXd::Identity(2, 2);
  const InformationGain a = information_gain(prior, at_zero);
  const InformationGain b = information_gain(prior, spread);
  EXPECT_NEAR(a.d_gain, 0.5 * std::log(1.0 + n), 1e-12);
  EXPECT_NEAR(b.d_gain, std::log(1.0 + n), 1e-12);
  EXPECT_NEAR(a.sd(0), 1.0 / std::sqrt(1.0 + n), 1e-12);
  EXPECT_NEAR(a.sd(1), 1.0, 1e-12) << "the slope keeps its prior: nothing at t = 0 sees it";
  EXPECT_NEAR(b.sd(1), 1.0 / std::sqrt(1.0 + n), 1e-12);
  // a correlated current information: the gain is the log-determinant ratio
  Eigen::MatrixXd now(2, 2);
  now << 4.0, 1.0, 1.0, 2.0;
  const InformationGain c = information_gain(now, at_zero);
  EXPECT_NEAR(c.d_gain, 0.5 * std::log((now + at_zero).determinant() / now.determinant()), 1e-12);
  EXPECT_NEAR(c.sd(1), std::sqrt((now + at_zero).inverse()(1, 1)), 1e-12);
}

const std::string kDrop =
    "[[candidate]]\nname = \"drop\"\nset = ['events.fall.action=\"release\"', "
    "'events.fall.body=\"ball\"', 'events.fall.when.at_s=0.5']\nchannels = [\"angle_deg\"]\n"
    "rate_hz = 50\n";
const std::string kStill =
    "[[candidate]]\nname = \"still\"\nchannels = [\"angle_deg\"]\nrate_hz = 50\n";

// The wall and the held ball's mass fitted to a 2 s step recording, with `candidates`.
std::string plan_file(const fs::path& dir, const std::string& candidates) {
  record_arm(dir / "steps.csv", kSteps);
  pamsim_test::write_text(
      dir / "id.toml",
      "base = \"" + kArm +
          "\"\noverrides = [\"sim.duration_s=2\"]\nruns = 1\ngenerations = 2\n"
          "population = 6\npolish_iterations = 10\n"
          "[[parameter]]\nkey = \"muscles.antagonist.plant.geometry.wall_thickness_mm\"\nfrom = "
          "2.0\nto = 4.0\n"
          "[[parameter]]\nkey = \"bodies.ball.mass_kg\"\nfrom = 0.1\nto = 0.4\n"
          "[[recording]]\nfile = \"steps.csv\"\nset = ['" +
          kSteps + "']\n" + candidates);
  return (dir / "id.toml").string();
}

TEST(IdentifyPlanTest, ADropDeterminesTheBallsMassAndStillnessLeavesItsPrior) {
  const fs::path dir = pamsim_test::fresh_dir("identify_plan");
  const IdentifyDefinition def = load_identify_definition(plan_file(dir, kStill + kDrop));
  ASSERT_EQ(def.candidates.size(), 2u);
  IdentifyDb db = IdentifyDb::create((dir / "id.db").string(), def);
  IdentifyRunOptions options;
  options.threads = 2;
  const IdentifyResult r = run_identify(def, db, options);
  const IdentifyPlan plan = plan_candidates(def, r, 2);
  ASSERT_EQ(plan.ranked.size(), 2u);
  EXPECT_TRUE(plan.failures.empty());
  EXPECT_EQ(plan.ranked[0].name, "drop");
  EXPECT_GT(plan.ranked[0].d_gain, plan.ranked[1].d_gain);
  // the mass: a prior of its whole range (0.3 kg) now, and after the still candidate
  EXPECT_NEAR(plan.sd_now[1], 0.3, 0.3 * 1e-6);
  EXPECT_NEAR(plan.ranked[1].sd_after[1], 0.3, 0.3 * 1e-6);
  EXPECT_LT(plan.ranked[0].sd_after[1], 0.01 * 0.3) << "the drop sees the mass";
  // the wall: the recording already determines it, and neither candidate makes it worse
  EXPECT_LT(plan.sd_now[0], 0.01 * 2.0);
  for (const PlannedCandidate& c : plan.ranked) EXPECT_LE(c.sd_after[0], plan.sd_now[0]);
  const std::vector<std::string> lines = plan_lines(plan);
  ASSERT_FALSE(lines.empty());
  EXPECT_EQ(lines[0].rfind("1. drop: information gain ", 0), 0u) << lines[0];
  EXPECT_NE(plan_markdown(plan).find("| `bodies.ball.mass_kg` | 0.3 | drop |"), std::string::npos)
      << plan_markdown(plan);
}

// A fitted recording whose trial fails when the plan differences it is named as left out of
// the current information (every gain is then overstated), not silently dropped.
TEST(IdentifyPlanTest, AFittedRecordingWhoseTrialFailsIsNamedAsLeftOut) {
  const fs::path dir = pamsim_test::fresh_dir("identify_plan_left_out");
  IdentifyDefinition def = load_identify_definition(plan_file(dir, kStill));
  IdentifyDb db = IdentifyDb::create((dir / "id.db").string(), def);
  IdentifyRunOptions options;
  options.threads = 2;
  const IdentifyResult r = run_identify(def, db, options);
  EXPECT_TRUE(plan_candidates(def, r, 2).left_out.empty());
  def.recordings[0].set.push_back("bodies.no_such_body.mass_kg=1");  // its trials now fail
  const IdentifyPlan plan = plan_candidates(def, r, 2);
  ASSERT_EQ(plan.left_out.size(), 1u);
  EXPECT_EQ(plan.left_out[0].rfind(def.recordings[0].name + ": ", 0), 0u) << plan.left_out[0];
  EXPECT_NE(plan.left_out[0].find("no_such_body"), std::string::npos) << plan.left_out[0];
  const std::vector<std::string> lines = plan_lines(plan);
  EXPECT_NE(lines.back().find("left out of the current information"), std::string::npos);
}

TEST(IdentifyPlanTest, BadCandidatesAreOneLineExitTwoAndNothingWritten) {
  const fs::path dir = pamsim_test::fresh_dir("identify_plan_bad");
  const std::string none = plan_file(dir, "");
  const std::string good = pamsim_test::read_file(none);
  const std::string still = "[[candidate]]\nname = \"still\"\n";
  std::string long_trials = good;  // 200 s trials
  long_trials.replace(long_trials.find("sim.duration_s=2\""), 17, "sim.duration_s=200\"");
  for (const auto& [text, says] : std::vector<std::pair<std::string, std::string>>{
           {good + still, "candidate[0].channels must name at least one channel"},
           {good + still + "channels = []\n",
            "candidate[0].channels must name at least one channel"},
           {good + "[[candidate]]\nchannels = [\"angle_deg\"]\n", "candidate[0].name"},
           {good + still + "channels = [\"angle_deg\"]\nrate_hz = 0\n",
            "candidate[0].rate_hz must be in (0, 10000] Hz, got 0"},
           {good + still + "channels = [\"angle_deg\"]\nduration_s = 3\n",
            "candidate[0].duration_s must be at most its scenario's sim.duration_s, 2 s, got 3"},
           {long_trials + still + "channels = [\"angle_deg\"]\nrate_hz = 10000\n",
            "candidate[0].rate_hz x duration_s gives 2000001 samples, more than the 1000000"},
           {good + still + "channels = [\"angle_rad\"]\nnoise = { angle_rad = 1 }\n",
            "candidate[0] (still): channel angle_rad is not a column"},
           {good + still + "channels = [\"p_meas_ago_MPa\"]\n",
            "candidate[0].noise gives no floor for p_meas_ago_MPa"},
           {good + still + "channels = [\"angle_deg\"]\nnoise = { angle_deg = 0 }\n",
            "candidate[0].noise.angle_deg must be a noise floor > 0"},
           {good + still + "channels = [\"angle_deg\", \"angle_deg\"]\n", "names angle_deg twice"},
           {good + still + "channels = [\"angle_deg\"]\n" + still + "channels = [\"angle_deg\"]\n",
            "candidate[1].name \"still\" is taken"},
           {good + still + "channels = [\"angle_deg\"]\nset = ['bodies.ball.mass_kg=0.2']\n",
            "set gives bodies.ball.mass_kg, a parameter"},
           {good, "--plan ranks the file's [[candidate]] experiments, and it has none"}}) {
    pamsim_test::expect_file_refused(dir, "identify", text, "--plan", says);
  }
}

}  // namespace
}  // namespace pamsim
