// reference_trajectory_test.cc: short trials of the shipped drops against their reference
// trajectories (tests/reference/*.csv), column by column, so that a change to the physics,
// the sensors' noise stream or the log's columns is seen, and the failure names what moved:
// the column, the first time it left its tolerance, both values, and how many columns moved.
//
// The tolerance: each value within 1e-6 of its column's largest magnitude in the reference
// (a 0/1 column exactly; an angle of 10 deg within 1e-5 deg). The solvers' last bits (CVODE's
// tolerances, a reordered sum) stay inside it; a change of any physical or sensed quantity at
// the fifth digit does not. Bit-for-bit repeatability is the determinism tests' job.
//
// A deliberate change writes the references again and says in its commit what moved and why:
//   for s in drop_mass drop_mass_ideal drop_mass_fiber drop_mass_passive; do
//     pamsim run scenarios/$s.toml --set sim.duration_s=1.5 --set drop.time_s=0.3 --force
//       --out /tmp/ref_$s && cp /tmp/ref_$s/trajectory.csv tests/reference/$s.csv   (one line)
//   done
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "base/atomic_file.h"
#include "sim/core/runner.h"
#include "sim/io/outputs.h"
#include "sim/io/recording_csv.h"
#include "sim/scenario/scenario_file.h"

namespace pamsim {
namespace {

constexpr double kRelativeToColumn = 1e-6;

// the trial of `scenario` shortened as the references were, read back as its CSV
Recording short_trial(const std::string& scenario) {
  const Scenario sc = load_scenario(std::string(PAMSIM_SOURCE_DIR) + "/scenarios/" + scenario,
                                    {"sim.duration_s=1.5", "drop.time_s=0.3"});
  const TrialResult r = run_trial(load_trial_model(sc), sc, sc.seed);
  EXPECT_EQ(r.summary.status, "ok") << r.summary.message;
  const std::string path =
      (std::filesystem::temp_directory_path() / ("pamsim_reference_" + scenario + ".csv")).string();
  write_file_atomically(path, trajectory_to_csv(r.trajectory));
  Recording trial = read_recording_csv(path);
  std::filesystem::remove(path);
  return trial;
}

// "" if `trial` matches `reference` within the tolerance; else what moved, one line a column
std::string differences(const Recording& trial, const Recording& reference) {
  std::ostringstream out;
  if (trial.channels != reference.channels) out << "the columns differ\n";
  // the same time grid (times are written as their exact decimals, 1.15, where references
  // made before may hold 1.1500000000000001: the same grid)
  bool same_times = trial.time_s.size() == reference.time_s.size();
  for (std::size_t i = 0; same_times && i < trial.time_s.size(); ++i) {
    same_times = std::fabs(trial.time_s[i] - reference.time_s[i]) <= 1e-9;
  }
  if (!same_times) out << "the times differ\n";
  if (!out.str().empty()) return out.str();
  int moved = 0;
  for (std::size_t c = 0; c < reference.channels.size(); ++c) {
    const std::vector<double>& want = reference.samples[c];
    const std::vector<double>& got = trial.samples[c];
    double largest = 0.0;
    for (double v : want) largest = std::max(largest, std::isnan(v) ? 0.0 : std::fabs(v));
    const double tolerance = kRelativeToColumn * largest;
    for (std::size_t i = 0; i < want.size(); ++i) {
      const bool both_empty = std::isnan(want[i]) && std::isnan(got[i]);
      if (both_empty || std::fabs(got[i] - want[i]) <= tolerance) continue;
      out << reference.channels[c] << " at t = " << reference.time_s[i] << " s: " << got[i]
          << ", reference " << want[i] << " (tolerance " << tolerance << ")\n";
      ++moved;
      break;
    }
  }
  if (moved > 0) out << moved << " of " << reference.channels.size() << " columns moved\n";
  return out.str();
}

TEST(ReferenceTrajectoryTest, ToleranceSeesAChangeAtTheFifthDigitAndNamesIt) {
  Recording reference;
  reference.channels = {"angle_deg", "reflex_agonist"};
  reference.time_s = {0.0, 0.01};
  reference.samples = {{10.0, 12.0}, {0.0, 1.0}};
  Recording trial = reference;
  trial.samples[0][1] = 12.0 + 1e-7;  // the solvers' last bits
  EXPECT_EQ(differences(trial, reference), "");
  trial.samples[0][1] = 12.0012;  // the fifth digit
  EXPECT_EQ(differences(trial, reference),
            "angle_deg at t = 0.01 s: 12.0012, reference 12 (tolerance 1.2e-05)\n"
            "1 of 2 columns moved\n");
  trial = reference;
  trial.channels[1] = "reflex_antagonist";
  EXPECT_EQ(differences(trial, reference), "the columns differ\n");
}

class ShortDropTest : public ::testing::TestWithParam<const char*> {};

TEST_P(ShortDropTest, MatchesItsReferenceColumnByColumn) {
  const std::string name = GetParam();
  const Recording reference =
      read_recording_csv(std::string(PAMSIM_SOURCE_DIR) + "/tests/reference/" + name + ".csv");
  EXPECT_EQ(differences(short_trial(name + ".toml"), reference), "") << name;
}

// the hardware drop, the ideal plant (drop_mass.toml before the physical plants), the fiber
// sensor's reflex, and the passive arm
// Times are the step counts' exact decimals (1150 steps of 1 ms: 1.15, not MuJoCo's added-up
// 1.1500000000000001), in the log and in the metrics that are times.
TEST(ReferenceTrajectoryTest, TimesAreTheirExactDecimals) {
  const Scenario sc = load_scenario(std::string(PAMSIM_SOURCE_DIR) + "/scenarios/drop_mass.toml",
                                    {"sim.duration_s=1.5", "drop.time_s=0.3"});
  const TrialResult r = run_trial(load_trial_model(sc), sc, sc.seed);
  const std::size_t time = r.trajectory.column("time_s");
  for (std::size_t row = 0; row < r.trajectory.rows(); ++row) {
    ASSERT_EQ(r.trajectory.at(row, time), static_cast<double>(row) / 100.0) << row;  // 10 ms
  }
  for (const char* name : {"impact_time_s", "min_angle_time_s", "first_trigger_time_s"}) {
    const double t = r.summary.metric(name);
    EXPECT_EQ(t, std::round(t * 1000.0) / 1000.0) << name << " " << t;  // whole steps
  }
  EXPECT_EQ(r.summary.metric("sim_time_s"), 1.5);
}

INSTANTIATE_TEST_SUITE_P(ShippedDrops, ShortDropTest,
                         ::testing::Values("drop_mass", "drop_mass_ideal", "drop_mass_fiber",
                                           "drop_mass_passive"));

}  // namespace
}  // namespace pamsim
