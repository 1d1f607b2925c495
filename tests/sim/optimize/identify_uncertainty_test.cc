// identify_uncertainty_test.cc: how sure `pamsim identify` says it is, on the example arm
// whose antagonist's wall is 2.7 mm where the model says 3.0 (a recording of its angle
// at 50 Hz, made by pamsim): with a recording the model can explain, the channel is judged
// explained, the wall's 95 % interval contains the truth and the HAC error is given beside
// the plain one; with the same recording seen through an unmodelled 60 ms sensor delay, the
// report says the model does not explain it, names the recording and the channel, and marks
// the standard errors as not to be trusted; a noise floor the file gives replaces the
// recording's own, and the file's interval level scales the intervals by its normal quantile.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include "base/no_value.h"
#include "sim/identify_test_arm.h"
#include "sim/optimize/identify.h"
#include "sim/optimize/identify_outputs.h"
#include "sim/optimize/identify_uncertainty.h"
#include "sim/scenario/scenario_file.h"

namespace pamsim {
namespace {

namespace fs = std::filesystem;

// the wall identified from the recording `delay_rows` late; `top` and `recording` add keys to
// the file's top and its [[recording]]
IdentifyResult identify_wall(const fs::path& dir, std::size_t delay_rows,
                             const std::string& top = "", const std::string& recording = "") {
  record_arm(dir / "steps.csv", kSteps, delay_rows);
  pamsim_test::write_text(
      dir / "id.toml",
      top + "base = \"" + kArm +
          "\"\noverrides = [\"sim.duration_s=2\"]\nruns = 1\ngenerations = 2\n"
          "population = 6\npolish_iterations = 10\n[[parameter]]\n"
          "key = \"muscles.antagonist.plant.geometry.wall_thickness_mm\"\nfrom = 2.0\nto = 4.0\n"
          "[[recording]]\nfile = \"steps.csv\"\nset = ['" +
          kSteps + "']\n" + recording);
  const IdentifyDefinition def = load_identify_definition((dir / "id.toml").string());
  IdentifyDb db = IdentifyDb::create((dir / "id.db").string(), def);
  IdentifyRunOptions options;
  options.threads = 2;
  return run_identify(def, db, options);
}

TEST(IdentifyUncertaintyTest, AnExplainedRecordingGivesAnIntervalAroundTheTruth) {
  const IdentifyResult r = identify_wall(pamsim_test::fresh_dir("uncertainty_explained"), 0);
  ASSERT_EQ(r.parameters.size(), 1u);
  const IdentifiedParameter& wall = r.parameters[0];
  ASSERT_TRUE(wall.identifiable);
  EXPECT_LE(wall.interval_lo, 2.7);
  EXPECT_GE(wall.interval_hi, 2.7);
  EXPECT_GT(wall.std_error, 0.0);
  EXPECT_GT(wall.std_error_plain, 0.0);
  ASSERT_EQ(r.fits.size(), 1u);
  EXPECT_TRUE(r.fits[0].explained) << r.fits[0].rmse_after << " vs " << r.fits[0].noise_floor;
  EXPECT_TRUE(unexplained_channels(r).empty());
}

TEST(IdentifyUncertaintyTest, AnUnmodelledSensorDelayIsReportedAsNotExplained) {
  const fs::path dir = pamsim_test::fresh_dir("uncertainty_delayed");
  const IdentifyResult r = identify_wall(dir, 6);  // 60 ms late
  ASSERT_EQ(r.fits.size(), 1u);
  EXPECT_FALSE(r.fits[0].explained) << r.fits[0].rmse_after << " vs " << r.fits[0].noise_floor;
  const std::vector<std::string> lines = unexplained_channels(r);
  ASSERT_EQ(lines.size(), 1u);
  EXPECT_EQ(lines[0].rfind("the model does not explain recording steps (angle_deg): RMS ", 0), 0u)
      << lines[0];
  IdentifyDefinition def = load_identify_definition((dir / "id.toml").string());
  const std::string md = identify_markdown(def, r);
  EXPECT_NE(md.find("not to be trusted"), std::string::npos);
  EXPECT_EQ(identify_warnings(def, r).front(),
            lines[0] + "; the standard errors are not to be trusted");
  EXPECT_NE(identify_fits_csv(r).find(",0\n"), std::string::npos) << identify_fits_csv(r);
}

}  // namespace
}  // namespace pamsim

namespace pamsim {
namespace {

// the file's noise floor replaces the recording's own, its level sets the intervals'
TEST(IdentifyUncertaintyTest, AGivenNoiseFloorAndIntervalLevelAreUsed) {
  const fs::path dir = pamsim_test::fresh_dir("uncertainty_given");
  const IdentifyResult wide = identify_wall(dir, 6);
  const IdentifyResult given = identify_wall(pamsim_test::fresh_dir("uncertainty_given2"), 6,
                                             "interval = 0.5\n", "noise = { angle_deg = 1.0 }\n");
  ASSERT_EQ(given.fits.size(), 1u);
  EXPECT_EQ(given.fits[0].noise_floor, 1.0);
  EXPECT_TRUE(given.fits[0].explained) << "1.9 deg of RMS is within 3 floors of 1 deg";
  // each interval is value +- z se on the wall's linear scale: z = 1.96 at the default 95 %,
  // 0.6745 at the file's 50 % (the floor also weighs the residuals, so the two fits differ)
  const IdentifiedParameter& a = wide.parameters[0];
  const IdentifiedParameter& b = given.parameters[0];
  EXPECT_NEAR((a.interval_hi - a.interval_lo) / (2.0 * a.std_error), 1.959963984540054, 1e-9);
  EXPECT_NEAR((b.interval_hi - b.interval_lo) / (2.0 * b.std_error), 0.6744897501960817, 1e-9);
}

// the warnings a user must not miss, from a result built by hand
TEST(IdentifyUncertaintyTest, NoConvergenceAndABoundAreWarnings) {
  IdentifyDefinition def;
  def.polish_iterations = 10;
  IdentifyResult r;
  IdentifiedParameter wall;
  wall.parameter.key = "muscles.antagonist.plant.geometry.wall_thickness_mm";
  wall.parameter.from = 2.0;
  wall.parameter.to = 4.0;
  wall.value = 4.0;
  wall.at_bound = true;
  r.parameters.push_back(wall);
  r.polish_converged = false;
  r.polish_iterations = 10;
  const std::vector<std::string> warnings = identify_warnings(def, r);
  ASSERT_EQ(warnings.size(), 2u);
  EXPECT_EQ(warnings[0],
            "the polish stopped after 10 iterations without converging "
            "(polish_iterations = 10): the point may not be the minimum");
  EXPECT_EQ(warnings[1],
            "muscles.antagonist.plant.geometry.wall_thickness_mm = 4 sits at a "
            "bound of its range [2, 4]: widen it, or the value is not identified");
  r.polish_converged = true;
  r.parameters[0].at_bound = false;
  EXPECT_TRUE(identify_warnings(def, r).empty());
}

// a channel with too few samples for its noise floor is not judged: unknown, not explained,
// and a warning says how to judge it
TEST(IdentifyUncertaintyTest, TooFewSamplesToEstimateTheNoiseIsUnknown) {
  const std::vector<double> recorded = {0.0, 1.0, 0.5, 2.0, 1.5, 3.0, 2.5, 4.0, 3.5};
  ChannelFit fit;
  fit.recording = "sparse";
  fit.channel = "angle_deg";
  fit.after = std::vector<double>(recorded.size(), 1.0);
  fit.rmse_after = 1.0;
  judge_channel(recorded, kNaN, 3.0, &fit);
  EXPECT_TRUE(std::isnan(fit.noise_floor)) << "seven second differences are too few";
  EXPECT_FALSE(fit.judged);
  EXPECT_FALSE(fit.explained);
  IdentifyResult r;
  r.fits.push_back(fit);
  EXPECT_TRUE(unexplained_channels(r).empty()) << "unknown is not \"does not explain\"";
  const std::vector<std::string> warnings = identify_warnings(IdentifyDefinition{}, r);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_EQ(warnings[0],
            "recording sparse (angle_deg) has too few samples to estimate its "
            "noise: whether the model explains it is unknown (give noise = { "
            "angle_deg = ... })");
  EXPECT_NE(identify_fits_csv(r).find(",\n"), std::string::npos) << "explained: empty";
  judge_channel(recorded, 0.5, 3.0, &fit);  // a given floor judges it
  EXPECT_TRUE(fit.judged);
  EXPECT_TRUE(fit.explained) << "1 <= 3 x 0.5";
  judge_channel(recorded, 0.5, 1.5, &fit);  // the file's explained_noise_factor = 1.5
  EXPECT_FALSE(fit.explained) << "1 > 1.5 x 0.5";
}

}  // namespace
}  // namespace pamsim
