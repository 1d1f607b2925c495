// paper_bands_test.cc: Table III and Table V of the paper (Yoshida and Hosoda) against the
// bands the shipped protocols give over their brackets (src/sim/validate/protocol_bands.h),
// each cell pinned to the paper by its band, with why it lies where it does. Ten rigs each,
// the protocols cut to the cells named (every band of docs/validation.md is 50 rigs of the
// whole table).
//   Table III, PAM-C, Eq. (3), 5 kg: the paper's RMSE 0.683 % lies inside the band: PAM-C's
//     thin 4 mm tube makes its latex wall (0.79-1.59 mm, stock walls) matter.
//   Table III, PAM-A, Eq. (3), 5 kg: the paper's 0.861 % lies above the band: its floor is
//     the fitted law's misfit to the plant on the rig, which no bracketed part moves; more
//     braid friction (an assumption of the plant file) moves it towards the paper.
//   Table III's other cells outside at 5 kg (50 rigs): PAM-A Eq. (4) and (5), PAM-D Eq. (3)
//     above, PAM-B Eq. (4) and PAM-D Eq. (5) below: the braid's friction and angle, the
//     plant files' assumptions, move each (docs/validation.md runs every one).
//   Table V (50 rigs, one trial each): the agonist's model cells (all, and after its line's
//     loss at the paper's 2.7 s) and both fiber cells lie inside their bands; the
//     antagonist's model cell (5.02 %) lies above by a factor of 1.5 or more: the arm's
//     antagonist within its tubing's tolerance of the tested one moves it by a percent at
//     most, and an antagonist softer than the one fitted (a nearly constant error, as the
//     paper's) is the mechanism no source sizes.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <unistd.h>
#include <utility>
#include <vector>

#include "sim/test_paths.h"
#include "sim/validate/protocol_bands.h"
#include "sim/validate/reaching.h"

namespace pamsim {
namespace {

using pamsim_test::kScenarios;

constexpr int kRigs = 10;

// The band of cell `name`: its finite RMSEs over the rigs
BandStats rmse_band(const Bands& bands, const std::string& name) {
  const auto& cells = bands.runs.cells;
  const auto at = std::find(cells.begin(), cells.end(), name);
  EXPECT_NE(at, cells.end()) << name;
  std::vector<double> rmse;
  for (const auto& rig : bands.runs.errors) rmse.push_back(rig[at - cells.begin()].rmse_pct);
  return band_stats(rmse);
}

ValidationOptions two_threads(const std::string& name) {
  ValidationOptions o;
  o.threads = 2;
  o.out_dir = (std::filesystem::path(::testing::TempDir()) /
               ("paper_bands_" + name + "_" + std::to_string(::getpid())))
                  .string();
  return o;
}

TEST(PaperBandsTest, TableThreeCellsSitInsideForPamCAndAboveForPamA) {
  const LengthValidationSpec spec = load_length_validation(
      kScenarios + "validate_length_estimation.toml", {"A", "C"}, {"weights_kg=[5.0]"});
  const Bands bands = run_length_bands(spec, two_threads("t3"), kRigs);
  EXPECT_EQ(bands.runs.refused_count(), 0);
  const BandStats c = rmse_band(bands, "PAM-C eq3 5 kg");
  EXPECT_EQ(c.n, kRigs);
  EXPECT_LE(c.min, 0.683);  // Table III, PAM-C, Eq. (3)
  EXPECT_GE(c.max, 0.683);
  const BandStats a = rmse_band(bands, "PAM-A eq3 5 kg");
  EXPECT_LT(a.max, 0.861);  // Table III, PAM-A, Eq. (3): above the band
  EXPECT_GT(a.min, 0.3);    // the misfit's floor, not a broken run
}

// Table V against the 50 rigs of validate_reaching.toml, one trial per rig: the agonist's
// cells and both fiber cells inside their 5-95 % ranges, the antagonist's model cell above its
// range by a factor of 1.5 at least
TEST(PaperBandsTest, TableFiveCellsSitInsideTheirBandsButTheAntagonistsModel) {
  const ReachingValidationSpec spec =
      load_reaching_validation(kScenarios + "validate_reaching.toml", {"trials=1"});
  const Bands bands = run_reaching_bands(spec, two_threads("t5"), 50);
  // the rigs that cannot exist, a line too thin for its pull (12 of 50 at bracket_seed 1)
  const int refused = bands.runs.refused_count();
  EXPECT_LE(refused, 15);
  for (const auto& [cell, paper] :
       std::vector<std::pair<std::string, double>>{{"agonist model all", 5.24},
                                                   {"agonist model after_slack", 5.94},
                                                   {"agonist fiber all", 0.888},
                                                   {"antagonist fiber all", 1.78}}) {
    const BandStats b = rmse_band(bands, cell);
    EXPECT_EQ(b.n, 50 - refused) << cell;
    EXPECT_LE(b.p5, paper) << cell;
    EXPECT_GE(b.p95, paper) << cell;
  }
  // the arm's antagonist within its tubing's tolerance of the tested one: far below the paper
  EXPECT_LT(1.5 * rmse_band(bands, "antagonist model all").p95, 5.02);
}

// The cell (muscle, method "model", part) of one protocol run with `overrides`
ErrorPct model_cell(const std::vector<std::string>& overrides, const std::string& muscle,
                    const std::string& part) {
  ValidationOptions options = two_threads("mechanism");
  options.overrides = overrides;
  const ReachingValidationResult r = run_reaching_validation(
      load_reaching_validation(kScenarios + "validate_reaching.toml", {"trials=1"}), options);
  for (const ReachingRow& row : r.rows) {
    if (row.muscle == muscle && row.method == "model" && row.part == part) return row.sim;
  }
  ADD_FAILURE() << "no cell " << muscle << " model " << part;
  return {};
}

TEST(PaperBandsTest, TheMissingMechanismsMoveTableFiveTowardsThePaper) {
  const ErrorPct antagonist = model_cell({}, "antagonist", "all");
  // the agonist's line lost at the paper's 2.7 s (reaching.toml), the lines tied 5 mm tight:
  // its error after the loss within a factor 1.5 of the paper's 5.94 %
  const ErrorPct after =
      model_cell({"model.antagonist_deformation_mm=5"}, "agonist", "after_slack");
  EXPECT_GT(after.rmse_pct, 5.94 / 1.5);
  EXPECT_LT(after.rmse_pct, 5.94 * 1.5);
  EXPECT_GT(after.rmse_pct, 3.0 * model_cell({}, "agonist", "after_slack").rmse_pct);
  // an antagonist softer than the one fitted: a larger error, nearly constant (RMSE / max
  // 0.86 in the paper)
  const ErrorPct softer =
      model_cell({"muscles.antagonist.plant.geometry.wall_thickness_mm=2.6"}, "antagonist", "all");
  EXPECT_GT(softer.rmse_pct, 1.5 * antagonist.rmse_pct);
  EXPECT_GT(softer.rmse_pct / softer.max_pct, 0.7);
}

// PAM-A's Eq. (3) RMSE at 5 kg on the pulley rig, its plant changed by `set`
double pam_a_eq3_rmse(std::vector<std::string> set) {
  LengthValidationSpec spec =
      with_plant_changes(load_length_validation(kScenarios + "validate_length_estimation.toml",
                                                {"A"}, {"weights_kg=[5.0]"}),
                         &set);
  const LengthValidationResult r = run_length_validation(spec, two_threads("t3_mechanism"));
  for (const DynamicRow& row : r.rows) {
    if (row.law == SpringLaw::kEq3) return row.sim.rmse_pct;
  }
  ADD_FAILURE() << "no Eq. (3) row";
  return 0.0;
}

TEST(PaperBandsTest, MoreBraidFrictionMovesPamATowardsThePaper) {
  // Table III, PAM-A, Eq. (3): 0.861 % in the paper, above the band; the braid's friction is
  // an assumption of the plant file
  const double shipped = pam_a_eq3_rmse({});
  const double rougher = pam_a_eq3_rmse({"pams.A.plant.friction.extension.A0_mm2=30"});
  EXPECT_GT(rougher, 1.2 * shipped);
  EXPECT_LT(rougher, 0.861);
}

}  // namespace
}  // namespace pamsim
