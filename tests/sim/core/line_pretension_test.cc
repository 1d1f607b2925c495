// line_pretension_test.cc: the lines' pre-tension as a scenario key
// (model.antagonist_deformation_mm: the calibration solved again when the model is bound) and
// a line's break load (muscles.<m>.line_strength_MPa). Against the calibration file that
// `pamsim calibrate` wrote, the closed form of a line's section, the balance of the arm's
// torques at rest as MuJoCo and the muscles' force law compute them, and both validation
// protocols refusing a rig whose line would break.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "base/units.h"
#include "sim/scenario_errors.h"
#include "sim/core/muscle_law.h"
#include "sim/core/trial_lines.h"
#include "sim/validate/length_estimation.h"
#include "sim/validate/reaching.h"
#include "sim/cli_util.h"

namespace pamsim {
namespace {

using pamsim_test::kScenarios;

const std::string kPassive = kScenarios + "drop_mass_passive.toml";
const std::string kKey = "model.antagonist_deformation_mm";

TrialModel bound(const std::vector<std::string>& overrides, Scenario* sc) {
  *sc = load_scenario(kPassive, overrides);
  return load_trial_model(*sc);
}

TEST(LinePretensionTest, TheFilesOwnPretensionGivesTheFilesLines) {
  // models/arm_2pam_plant_calibration.toml was written with antagonist_deformation_mm = 1
  Scenario as_written, solved;
  const TrialModel a = bound({}, &as_written);
  const TrialModel b = bound({kKey + "=1"}, &solved);
  ASSERT_EQ(a.muscles.size(), 2u);
  for (std::size_t k = 0; k < 2; ++k) {
    EXPECT_NEAR(b.muscles[k].line_length_m, a.muscles[k].line_length_m, 1e-11) << k;
  }
  EXPECT_FALSE(same_trial_model(as_written, solved)) << "the key changes the model";
}

TEST(LinePretensionTest, TheAntagonistSitsThatFarPastItsFreeLengthAndTheArmIsAtRest) {
  for (double mm : {0.5, 6.0}) {
    SCOPED_TRACE(mm);
    Scenario sc;
    const TrialModel tm = bound({kKey + "=" + std::to_string(mm)}, &sc);
    MjDataPtr d = detail::start_state(sc, tm);
    const BoundMuscle& anta = tm.muscles[1];
    const MuscleSpec& spec = sc.muscles[anta.spec];
    ASSERT_DOUBLE_EQ(spec.command.at(0.0), 0.4e6) << "the calibration's pressure";
    const double pam_length_m = d->actuator_length[anta.actuator] - anta.line_length_m;
    EXPECT_NEAR(pam_length_m - plant_free_length(spec, 0.4e6), units::mm_to_m(mm), 1e-9);
    // at rest: the muscles' torques (their force law, through the callback) balance gravity
    const int dof = tm.joint.dof;
    EXPECT_NEAR(d->qfrc_actuator[dof] - d->qfrc_bias[dof], 0.0, 1e-6) << "N m";
    // and it stays there: 0.2 s of MuJoCo steps at the held pressures move it by under 0.01 deg
    const double start = d->qpos[tm.joint.qpos];
    for (int i = 0; i < 200; ++i) mj_step(tm.model.get(), d.get());
    EXPECT_NEAR(d->qpos[tm.joint.qpos], start, units::deg_to_rad(0.01));
  }
}

TEST(LinePretensionTest, BadValuesAndMissingCalibrationsAreRefusedByKey) {
  using pamsim_test::error_of;
  for (const char* bad : {"0", "-1", "100.5", "nan", "\"tight\""}) {
    const std::string message = error_of(kPassive, {kKey + "=" + bad});
    EXPECT_NE(message.find(kKey), std::string::npos) << bad << ": " << message;
  }
  // a scenario without a calibration, a muscle that gives its own line, a pre-tension the
  // antagonist's plant cannot reach
  EXPECT_NE(error_of(kScenarios + "hopping.toml", {kKey + "=3"}).find("needs model.calibration"),
            std::string::npos);
  EXPECT_NE(error_of(kPassive, {kKey + "=3", "muscles.agonist.line_mm=300"}).find(kKey),
            std::string::npos);
  try {  // calibrate solves the lines by its own options: the key would be ignored
    load_scenario_for_calibration(kPassive, {kKey + "=3"});
    ADD_FAILURE() << "calibrate took " << kKey;
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("give --antagonist-deformation-mm"), std::string::npos);
  }
  const std::string too_far = error_of(kPassive, {kKey + "=90"});
  EXPECT_NE(too_far.find(kKey), std::string::npos) << too_far;
  EXPECT_EQ(too_far.find("nan"), std::string::npos) << too_far;
}

TEST(LinePretensionTest, ALinesBreakLoadIsItsStrengthTimesItsSection) {
  const Scenario sc = load_scenario(
      kPassive, {"muscles.agonist.line_diameter_mm=0.285", "muscles.agonist.line_modulus_MPa=2000",
                 "muscles.agonist.line_strength_MPa=920"});
  const double radius = 0.285e-3 / 2;
  EXPECT_NEAR(sc.muscles[0].line_break_n, 920e6 * M_PI * radius * radius, 1e-9);
  EXPECT_TRUE(std::isnan(sc.muscles[1].line_break_n)) << "none given: it does not break";
  // a strength needs a line with a section; bad values are refused by key
  using pamsim_test::error_of;
  EXPECT_NE(error_of(kPassive, {"muscles.agonist.line_strength_MPa=900"})
                .find("muscles.agonist.line_strength_MPa needs an extensible line"),
            std::string::npos);
  for (const char* bad : {"0", "-5", "nan"}) {
    EXPECT_NE(error_of(kPassive, {"muscles.agonist.line_diameter_mm=0.3",
                                  "muscles.agonist.line_modulus_MPa=2000",
                                  std::string("muscles.agonist.line_strength_MPa=") + bad})
                  .find("line_strength_MPa"),
              std::string::npos)
        << bad;
  }
}

// pamsim run with a line too weak for the drop: the tension metrics give its peak pull in per
// cent of its break load (strength x section, the closed form), and the run warns, in one
// line naming the key, but runs (it is the validation that refuses such a rig)
TEST(LinePretensionTest, RunNamesALineThatBreaksAndItsLoadInPerCent) {
  const std::filesystem::path out = pamsim_test::fresh_dir("line_breaks_run");
  const pamsim_test::CliResult r = pamsim_test::run_pamsim(
      "run scenarios/drop_mass_passive.toml --no-plot --out " + out.string() +
      " --set sim.duration_s=1.5 --set 'metrics=[\"drop\", \"tension\"]'"
      " --set muscles.agonist.line_diameter_mm=0.285 --set muscles.agonist.line_modulus_MPa=2000"
      " --set muscles.agonist.line_strength_MPa=100");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("warning: "), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("muscles.agonist.line_strength_MPa: its line breaks"), std::string::npos)
      << r.err;
  std::ifstream in(out / "summary.json");
  const nlohmann::json s = nlohmann::json::parse(in);
  const double break_n = 100e6 * M_PI * 0.285e-3 * 0.285e-3 / 4;
  const double peak = s["peak_tension_ago_N"].get<double>();
  EXPECT_GT(peak, break_n) << "the drop pulls past 6.4 N";
  EXPECT_NEAR(s["line_break_load_ago_pct"].get<double>(), 100.0 * peak / break_n, 1e-9);
  EXPECT_FALSE(s.contains("line_break_load_anta_pct")) << "no strength given: no break load";
}

TEST(LinePretensionTest, TheReachingProtocolRefusesARigWhoseLineBreaks) {
  // Japanese No. 3 nylon (0.285 mm, 6 kg) against the antagonist's 85 N at the ramps' start,
  // then a 0.5 mm line of the same material, which holds it
  ValidationOptions options;
  options.threads = 2;
  const std::string thin = "muscles.antagonist.line_diameter_mm=0.285";
  options.overrides = {thin, "muscles.antagonist.line_modulus_MPa=2000",
                       "muscles.antagonist.line_strength_MPa=920"};
  const ReachingValidationSpec spec =
      load_reaching_validation(kScenarios + "validate_reaching.toml", {"trials=1"});
  try {
    run_reaching_validation(spec, options);
    ADD_FAILURE() << "the thin line did not break";
  } catch (const InputError& e) {
    EXPECT_EQ(e.parts().key, "muscles.antagonist.line_strength_MPa") << e.what();
    EXPECT_NE(std::string(e.what()).find("58.69"), std::string::npos) << e.what();
  }
  options.overrides.front() = "muscles.antagonist.line_diameter_mm=0.5";
  EXPECT_EQ(run_reaching_validation(spec, options).trials.size(), 1u);
}

TEST(LinePretensionTest, TheLengthProtocolRefusesARigWhoseLineTheWeightBreaks) {
  // 10 kg (98 N) on a 0.3 mm nylon line (65 N at 920 MPa); 5 kg (49 N) it holds
  const std::vector<std::string> thin = {"muscles.pam.line_diameter_mm=0.3",
                                         "muscles.pam.line_modulus_MPa=2000",
                                         "muscles.pam.line_strength_MPa=920"};
  ValidationOptions options;
  options.threads = 2;
  options.overrides = thin;
  options.out_dir = pamsim_test::fresh_dir("line_breaks_length").string();
  const std::string file = kScenarios + "validate_length_estimation.toml";
  try {
    run_length_validation(load_length_validation(file, {"A"}, {"weights_kg=[10.0]"}), options);
    ADD_FAILURE() << "the line held 10 kg";
  } catch (const InputError& e) {
    EXPECT_EQ(e.parts().key, "muscles.pam.line_strength_MPa") << e.what();
  }
  EXPECT_EQ(
      run_length_validation(load_length_validation(file, {"A"}, {"weights_kg=[5.0]"}), options)
          .rows.size(),
      3u);
}

}  // namespace
}  // namespace pamsim
