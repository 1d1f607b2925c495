// validate_test.cc: the papers' validation protocols (src/sim/validate/) on the shipped
// protocol files: the fits reproduce the plant's tensile data within the RMSE they report,
// the pulley's true length follows the hanging weight, the reaching task's slack episode is
// found where the antagonist's line goes slack, and the tables do not depend on the thread
// count.
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>
#include <stdexcept>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "base/input_error.h"
#include "base/units.h"
#include "sim/core/runner.h"
#include "sim/validate/length_estimation.h"
#include "sim/validate/reaching.h"
#include "sim/test_paths.h"

namespace pamsim {
namespace {

namespace fs = std::filesystem;
using pamsim_test::kScenarios;

std::string fresh_out(const std::string& name) {
  const fs::path dir =
      fs::path(::testing::TempDir()) / ("validate_" + name + "_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  return dir.string();
}

// PAM-B and PAM-D (rubber and silicone, the papers' Fig. 5 and 6), short dynamic trials
LengthValidationResult short_length_validation(const LengthValidationSpec& spec, int threads,
                                               const std::string& out) {
  ValidationOptions o;
  o.out_dir = out;
  o.threads = threads;
  o.overrides = {"sim.duration_s=6"};
  return run_length_validation(spec, o);
}

TEST(ValidateTest, FitsReproduceTheTensileDataWithinTheirReportedRmse) {
  const LengthValidationSpec spec =
      load_length_validation(kScenarios + "validate_length_estimation.toml", {"B", "D"});
  ASSERT_EQ(spec.pams.size(), 2u);
  EXPECT_EQ(spec.pams[0].name, "B");
  LengthValidationResult r = short_length_validation(spec, 2, fresh_out("fits"));
  ASSERT_EQ(r.fits.size(), 6u);
  for (const FittedLaw& f : r.fits) {
    SCOPED_TRACE(f.pam + " " + to_string(f.law));
    const std::vector<TensileRow>& rows = r.tensile[f.pam == "B" ? 0 : 1];
    double sum_sq = 0.0, f_max = 0.0;
    for (const TensileRow& row : rows) {
      const double e = spring_force(f.fit.model, units::mpa_to_pa(row.pressure_mpa),
                                    units::mm_to_m(row.deformation_mm)) -
                       row.force_n;
      sum_sq += e * e;
      f_max = std::max(f_max, row.force_n);
    }
    // the law evaluated on the data gives back the RMSE the fit reports (to 0.1 %: at the
    // free length the encoder's noise makes some d < 0, where the law pulls nothing and the
    // fit's polynomial a little), and the fit is good
    EXPECT_NEAR(std::sqrt(sum_sq / rows.size()), f.fit.rmse_n, 1e-3 * f.fit.rmse_n);
    EXPECT_GE(f.max_residual_n, f.fit.rmse_n);
    EXPECT_LT(f.fit.rmse_n, 0.1 * f_max);
    EXPECT_GT(f.fit.r2, 0.95);
    EXPECT_TRUE(fs::exists(f.params_file));
  }
  // the protocol's pressures (measured, with the sensor's noise): 0.4-0.8 MPa for B,
  // 0.2-0.6 MPa for D
  for (const auto& [index, lo, hi] :
       {std::tuple<int, double, double>{0, 0.4, 0.8}, {1, 0.2, 0.6}}) {
    double p_min = 1.0, p_max = 0.0;
    for (const TensileRow& row : r.tensile[index]) {
      p_min = std::min(p_min, row.pressure_mpa);
      p_max = std::max(p_max, row.pressure_mpa);
    }
    EXPECT_NEAR(p_min, lo, 0.005);
    EXPECT_NEAR(p_max, hi, 0.005);
  }
}

TEST(ValidateTest, PulleyTrueLengthFollowsTheHangingWeight) {
  const LengthValidationSpec spec =
      load_length_validation(kScenarios + "validate_length_estimation.toml", {"C"});
  LengthValidationResult r = short_length_validation(spec, 2, fresh_out("pulley"));
  ASSERT_EQ(r.rows.size(), 6u);  // 3 laws x 2 weights
  for (const DynamicRow& row : r.rows) {
    ASSERT_EQ(row.status, "ok");
    const Trajectory& tr = row.trajectory;
    const std::size_t pos = tr.column("position_mm"), len = tr.column("length_pam_mm");
    // the line is taut: the weight rises by what the PAM shortens
    const double sum0 = tr.at(0, pos) + tr.at(0, len);
    double travel = 0.0;
    for (std::size_t i = 0; i < tr.rows(); ++i) {
      EXPECT_NEAR(tr.at(i, pos) + tr.at(i, len), sum0, 1e-4) << "row " << i;
      travel = std::max(travel, std::fabs(tr.at(i, pos)));
    }
    EXPECT_GT(travel, 3.0) << "the sine moves the weight by millimetres";
    EXPECT_TRUE(std::isfinite(row.sim.max_pct) && std::isfinite(row.sim.rmse_pct));
    EXPECT_GT(row.sim.rmse_pct, 0.0);
    EXPECT_GE(row.sim.max_pct, row.sim.rmse_pct);
  }
  // the heavier weight stretches the muscle further (rows: law-major, 5 kg then 10 kg)
  for (std::size_t k = 0; k + 1 < r.rows.size(); k += 2) {
    ASSERT_EQ(r.rows[k].weight_kg, 5.0);
    ASSERT_EQ(r.rows[k + 1].weight_kg, 10.0);
    const Trajectory& light = r.rows[k].trajectory;
    const Trajectory& heavy = r.rows[k + 1].trajectory;
    const double l5 = light.at(0, light.column("length_pam_mm"));
    const double l10 = heavy.at(0, heavy.column("length_pam_mm"));
    EXPECT_GT(l10 - l5, 2.0) << "5 kg: " << l5 << " mm, 10 kg: " << l10 << " mm";
  }
}

TEST(ValidateTest, LengthTablesAreTheSameOnOneAndTwoThreads) {
  const LengthValidationSpec spec =
      load_length_validation(kScenarios + "validate_length_estimation.toml", {"A"});
  LengthValidationResult one = short_length_validation(spec, 1, fresh_out("t1"));
  LengthValidationResult two = short_length_validation(spec, 2, fresh_out("t2"));
  EXPECT_EQ(table3_csv(one), table3_csv(two));
  EXPECT_EQ(table3_markdown(one, spec), table3_markdown(two, spec));
}

// pams.<NAME>.plant.<field> (a --set or a bracket's draw) changes that PAM's plant for its
// tensile test and fits as for its trials; a wall too thick for the file's deformation is
// tested as far as it stretches; a change of a PAM not asked for is dropped, and a bad one
// names its key
TEST(ValidateTest, APlantChangeReachesTheTensileTestAndTheTrials) {
  const LengthValidationSpec spec =
      load_length_validation(kScenarios + "validate_length_estimation.toml", {"B"});
  std::vector<std::string> overrides = {"sim.duration_s=2",
                                        "pams.B.plant.geometry.wall_thickness_mm=1.59",
                                        "pams.A.plant.geometry.wall_thickness_mm=0.8"};
  const LengthValidationSpec drawn = with_plant_changes(spec, &overrides);
  EXPECT_EQ(overrides, std::vector<std::string>{"sim.duration_s=2"});
  ASSERT_EQ(drawn.pams.size(), 1u);
  EXPECT_EQ(drawn.pams[0].plant.avbdl.wall_thickness_m, 1.59e-3);
  EXPECT_EQ(drawn.pams[0].plant_changes,
            std::vector<std::string>{"geometry.wall_thickness_mm=1.59"});

  ValidationOptions o;
  o.out_dir = fresh_out("plant_change");
  o.overrides = {"sim.duration_s=2"};
  const LengthValidationResult plain = run_length_validation(spec, o);
  o.overrides.push_back("pams.B.plant.geometry.wall_thickness_mm=1.59");
  const LengthValidationResult thick = run_length_validation(spec, o);
  // the thick wall reaches about 10.7 mm at 0.4 MPa of the file's 25: the test stops there
  EXPECT_LT(thick.tensile[0].size(), plain.tensile[0].size());
  EXPECT_NE(thick.fits[0].fit.model.coef, plain.fits[0].fit.model.coef);
  EXPECT_NE(thick.rows[0].sim.rmse_pct, plain.rows[0].sim.rmse_pct);

  for (const auto& [set, says] : std::vector<std::pair<std::string, std::string>>{
           {"pams.Z.plant.geometry.wall_thickness_mm=1", "has no PAM Z"},
           {"pams.B.plnt.geometry.wall_thickness_mm=1", "only a plant's field"},
           {"pams.B.plant.geometry.wall_thickness_mm=-1",
            "pams.B.plant.geometry.wall_thickness_mm"},
           {"muscles.pam.plant.geometry.wall_thickness_mm=1", "pams.<NAME>.plant"}}) {
    o.overrides = {set};
    try {
      run_length_validation(spec, o);
      ADD_FAILURE() << set << " accepted";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(says), std::string::npos) << e.what();
    }
  }
}

Trajectory tension_log(const std::vector<double>& force_n) {
  Trajectory tr;
  tr.columns = {"time_s", "force_m_N"};
  for (std::size_t i = 0; i < force_n.size(); ++i) {
    tr.values.push_back(0.01 * static_cast<double>(i));
    tr.values.push_back(force_n[i]);
  }
  return tr;
}

// A slack episode: a line that was taut inside the window at zero tension for min_slack_s;
// slack from the start does not count, nor does a shorter dip.
TEST(ValidateTest, SlackEpisodeIsALongEnoughDropOfATautLine) {
  std::vector<double> f(100, 5.0);
  for (int i = 0; i < 20; ++i) f[i] = 0.0;    // slack at the start: not an episode
  f[40] = f[41] = 0.0;                        // a 20 ms dip: too short
  for (int i = 70; i < 100; ++i) f[i] = 0.0;  // the episode, from 0.70 s
  const Trajectory tr = tension_log(f);
  EXPECT_NEAR(slack_episode_start(tr, "m", 0.0, 0.99, 0.1), 0.70, 1e-12);
  EXPECT_TRUE(std::isnan(slack_episode_start(tr, "m", 0.0, 0.75, 0.1)));  // cut short
  EXPECT_TRUE(std::isnan(
      slack_episode_start(tension_log(std::vector<double>(50, 3.0)), "m", 0.0, 0.49, 0.1)));
}

// A gauge that reads nothing while its line pulls (the line has left the board) is an
// episode too, with its cause; a reading that merely dips, or a weak pull, is not.
TEST(ValidateTest, AGaugeThatStopsReadingUnderLoadIsAnEpisode) {
  Trajectory tr;
  tr.columns = {"time_s", "force_m_N", "force_meas_m_N"};
  for (int i = 0; i < 100; ++i) {
    const double f = 20.0;
    double meas = i < 60 ? 20.0 : 0.1;   // the gauge falls silent at 0.60 s
    if (i == 30 || i == 31) meas = 0.2;  // a 20 ms dropout: too short
    tr.values.insert(tr.values.end(), {0.01 * i, f, meas});
  }
  const SlackEpisode e = first_slack_episode(tr, "m", 0.0, 0.99, 0.1);
  EXPECT_NEAR(e.start_s, 0.60, 1e-12);
  EXPECT_EQ(e.cause, "gauge");
  // a pull under kPulledN that reads little is not a lost gauge
  for (std::size_t i = 0; i < tr.rows(); ++i) tr.values[3 * i + 1] = kPulledN - 1.0;
  EXPECT_TRUE(std::isnan(first_slack_episode(tr, "m", 0.0, 0.99, 0.1).start_s));
  // zero tension is slack, whatever the gauge reads
  for (std::size_t i = 60; i < tr.rows(); ++i) tr.values[3 * i + 1] = 0.0;
  EXPECT_EQ(first_slack_episode(tr, "m", 0.0, 0.99, 0.1).cause, "slack");
  // a gauge that lost its line before the window: unread from the window's first sample
  for (std::size_t i = 0; i < tr.rows(); ++i) tr.values[3 * i + 1] = 20.0;
  const SlackEpisode early = first_slack_episode(tr, "m", 0.65, 0.99, 0.1);
  EXPECT_NEAR(early.start_s, 0.65, 1e-12);
  EXPECT_EQ(early.cause, "gauge");
}

TEST(ValidateTest, ReachingFindsTheAntagonistsSlackAndIsThreadIndependent) {
  const ReachingValidationSpec spec =
      load_reaching_validation(kScenarios + "validate_reaching.toml");
  ValidationOptions o;
  o.threads = 2;
  const ReachingValidationResult r = run_reaching_validation(spec, o);
  ASSERT_EQ(r.scenario.muscles.size(), 2u);
  ASSERT_EQ(r.trials.size(), static_cast<std::size_t>(spec.trials));
  // the antagonist's line goes slack near the ramps' end in every trial (its pressure falls
  // toward 0.2 MPa as the arm rises); the slack episode starts where its tension is zero
  for (std::size_t k = 0; k < r.trials.size(); ++k) {
    const double s = r.slack_start_s[1][k];
    ASSERT_TRUE(std::isfinite(s)) << "trial " << k;
    EXPECT_GT(s, spec.window_start_s);
    EXPECT_LT(s, spec.window_end_s);
    const Trajectory& tr = r.trials[k].trajectory;
    const std::size_t t = tr.column("time_s"), force = tr.column("force_anta_N");
    for (std::size_t i = 0; i < tr.rows(); ++i) {
      if (tr.at(i, t) >= s && tr.at(i, t) < s + spec.min_slack_s) {
        EXPECT_LE(tr.at(i, force), 0.0);
      }
    }
  }
  // the agonist's line leaves its board where the paper's did, 2.7 s into the ramps (Sec.
  // IV-C): reaching.toml's lost_at_shortening_mm, within a tick of the datum's 4.70 s
  for (std::size_t k = 0; k < r.trials.size(); ++k) {
    EXPECT_NEAR(r.slack_start_s[0][k], spec.window_start_s + 2.7, 0.015) << "trial " << k;
  }
  // every "all" row filled, and both muscles' before / after; the antagonist's before starts
  // at its first taut sample, so before + after < all
  for (const ReachingRow& row : r.rows) {
    SCOPED_TRACE(row.muscle + " " + row.method + " " + row.part);
    if (row.part == "all") {
      EXPECT_EQ(row.samples, spec.trials * 1201);  // 2..14 s at 100 Hz, both ends
      EXPECT_TRUE(std::isfinite(row.sim.max_pct) && std::isfinite(row.sim.rmse_pct));
    } else {
      EXPECT_GT(row.samples, 0);
    }
  }
  const auto samples = [&](const char* part) {
    for (const ReachingRow& row : r.rows) {
      if (row.muscle == "antagonist" && row.method == "model" && row.part == part)
        return row.samples;
    }
    return -1;
  };
  EXPECT_LT(samples("before_slack") + samples("after_slack"), samples("all"));
  ValidationOptions single = o;
  single.threads = 1;
  const ReachingValidationResult r1 = run_reaching_validation(spec, single);
  EXPECT_EQ(table5_csv(r1), table5_csv(r));
  EXPECT_EQ(table5_markdown(r1, spec), table5_markdown(r, spec));
}

// Every protocol key with a bad value is refused by name.
TEST(ValidateTest, BadProtocolValuesNameTheirKey) {
  const std::string le = kScenarios + "validate_length_estimation.toml";
  for (const auto& [assignment, key] : std::vector<std::pair<std::string, std::string>>{
           {"weights_kg=[0.0]", "weights_kg"},
           {"weights_kg=[]", "weights_kg"},
           {"laws=[\"eq9\"]", "laws"},
           {"pams.A.pressures_MPa=[0.4, 0.5]", "pams.A.pressures_MPa"},
           {"pams.A.offset_MPa=1.5", "pams.A.offset_MPa"},
           {"pams.A.max_deformation_mm=1.0", "pams.A"},
           {"pams.A.bladder_diameter_mm=0.0", "pams.A.bladder_diameter_mm"},
           {"pams.A.paper.eq3=[1.0]", "pams.A.paper.eq3"},
           {"tensile.step_mm=-1", "pams.A"},
           {"tensile.seed=-1", "tensile.seed"},
           {"rig=\"missing.toml\"", ""}}) {
    SCOPED_TRACE(assignment);
    try {
      const LengthValidationSpec spec = load_length_validation(le, {}, {assignment});
      if (assignment.rfind("rig=", 0) == 0) {
        ValidationOptions o;
        o.out_dir = fresh_out("bad_rig");
        run_length_validation(spec, o);
      }
      ADD_FAILURE() << "accepted";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(key), std::string::npos) << e.what();
    }
  }
  const std::string re = kScenarios + "validate_reaching.toml";
  for (const auto& [assignment, key] : std::vector<std::pair<std::string, std::string>>{
           {"window_s=[5.0, 2.0]", "window_s"},
           {"min_slack_s=0.0", "min_slack_s"},
           {"trials=0", "trials"},
           {"paper.model_agonist=[1.0]", "paper.model_agonist"},
           {"paper.other_agonist=[1.0, 2.0]", "paper.other_agonist"}}) {
    SCOPED_TRACE(assignment);
    try {
      load_reaching_validation(re, {assignment});
      ADD_FAILURE() << "accepted";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(key), std::string::npos) << e.what();
    }
  }
}

// parallel_for: every index once, on any thread count; a job's exception comes back
TEST(ValidateTest, ParallelForRunsEachIndexOnceAndRethrows) {
  for (int threads : {1, 2, 5}) {
    std::vector<int> hits(37, 0);
    parallel_for(37, threads, [&](int k) { ++hits[k]; });
    EXPECT_EQ(std::count(hits.begin(), hits.end(), 1), 37) << threads;
  }
  EXPECT_THROW(parallel_for(10, 2,
                            [](int k) {
                              if (k == 7) throw std::runtime_error("job 7");
                            }),
               std::runtime_error);
  EXPECT_THROW(parallel_for(3, 0, [](int) {}), InputError);
  parallel_for(0, 2, [](int) { FAIL() << "no job for n = 0"; });
}

}  // namespace
}  // namespace pamsim
