// identify_offsets_test.cc: the channels' offsets projected out of the global search
// (identify_offsets.h). Against closed forms: the projected offset of a channel recorded as
// the model's reading plus a constant is the mean of recorded minus simulated (the least-
// squares constant), clamped to its range; and on an arm whose encoder reads 1.2 deg high, a
// short CMA-ES ends more than 10x lower with the offset projected than searching it, the
// offset at its least-squares value; a stopped run resumed is the uninterrupted one; and the
// default population counts the parameters CMA-ES moves.
#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "sim/cli_util.h"
#include "sim/identify_test_arm.h"
#include "sim/optimize/identify.h"
#include "sim/optimize/identify_offsets.h"
#include "sim/optimize/identify_residuals.h"

namespace pamsim {
namespace {

namespace fs = std::filesystem;

// The true arm's (wall 2.7 mm) `column` under kSine, plus `offset`, every second 10 ms row.
void record_with_offset(const fs::path& file, const std::string& column, double offset) {
  const Scenario sc =
      load_scenario(kArm, {"muscles.antagonist.plant.geometry.wall_thickness_mm=2.7",
                           "sim.duration_s=2", "seed=7", kSine});
  const TrialResult t = run_trial(load_trial_model(sc), sc, sc.seed, true);
  const std::size_t c = t.trajectory.column(column);
  std::string csv = "time_s," + column + "\n";
  for (std::size_t row = 0; row < t.trajectory.rows(); row += 2) {
    csv += format_shortest(t.trajectory.at(row, 0)) + "," +
           format_shortest(t.trajectory.at(row, c) + offset) + "\n";
  }
  pamsim_test::write_text(file, csv);
}

// The antagonist's wall and `column`'s offset in [-lo_hi, lo_hi], fitted to one recording
// made with `offset`; `top` adds top-level lines.
IdentifyDefinition wall_and_offset(const fs::path& dir, const std::string& column, double offset,
                                   double lo_hi, const std::string& top = "") {
  record_with_offset(dir / "sine.csv", column, offset);
  pamsim_test::write_text(
      dir / "id.toml", top + "\nbase = \"" + kArm +
                           "\"\noverrides = [\"sim.duration_s=2\"]\n"
                           "[[parameter]]\nkey = "
                           "\"muscles.antagonist.plant.geometry.wall_thickness_mm\"\nfrom = 2.0\n"
                           "to = 4.0\n[[parameter]]\nkey = \"channel." +
                           column + ".offset\"\nfrom = " + format_shortest(-lo_hi) +
                           "\nto = " + format_shortest(lo_hi) +
                           "\n"
                           "[[recording]]\nfile = \"sine.csv\"\nset = ['" +
                           kSine + "']\n");
  return load_identify_definition((dir / "id.toml").string());
}

// mean(recorded - simulated) at `values` (the offset's among them ignored: set to 0)
double mean_difference(const IdentifyDefinition& def, std::vector<double> values) {
  values[1] = 0.0;
  const IdentifyRecording& r = def.recordings[0];
  const SimulatedRecording sim = simulate_recording(def, r, def.overrides_at(r, values));
  const std::vector<double> simulated = sample_channels(def, r, sim, values)[0];
  const std::vector<double>& recorded = r.data.samples[r.channels[0]];
  double sum = 0.0;
  for (std::size_t k = 0; k < recorded.size(); ++k) sum += recorded[k] - simulated[k];
  return sum / static_cast<double>(recorded.size());
}

TEST(IdentifyOffsetsTest, TheProjectedOffsetIsTheMeanDifferenceWithinItsRange) {
  const fs::path dir = pamsim_test::fresh_dir("identify_offsets_mean");
  for (const double recorded_offset : {1.7, 9.0}) {  // inside [-5, 5], then beyond it
    const IdentifyDefinition def = wall_and_offset(dir, "force_meas_anta_N", recorded_offset, 5.0);
    fs::remove(dir / "id.db");
    IdentifyDb db = IdentifyDb::create((dir / "id.db").string(), def);
    IdentifyResiduals residuals(def, db, 2);
    const OffsetProjection projection(def, residuals);
    ASSERT_EQ(projection.searched(), std::vector<std::size_t>{0}) << "the wall alone is searched";
    const std::vector<double> unit = projection.embed({0.4});  // a wall of 2.8 mm
    EXPECT_EQ(unit, (std::vector<double>{0.4, 0.5}));
    const std::vector<double> projected = projection.project(unit, residuals.at(unit, "test"));
    const std::vector<double> values = residuals.values_at(projected);
    EXPECT_EQ(projected[0], 0.4);
    const double expected = std::min(5.0, mean_difference(def, values));
    EXPECT_NEAR(values[1], expected, 1e-9) << recorded_offset;
    if (recorded_offset > 5.0) {
      EXPECT_EQ(projected[1], 1.0) << "clamped to its bound";
    }
    // off: the offset is searched like any parameter
    IdentifyDefinition off = def;
    off.profile_offsets = false;
    EXPECT_EQ(OffsetProjection(off, residuals).searched().size(), 2u);
  }
}

TEST(IdentifyOffsetsTest, AShortGlobalSearchEndsLowerWithTheOffsetProjected) {
  const fs::path dir = pamsim_test::fresh_dir("identify_offsets_search");
  const std::string search = "runs = 1\ngenerations = 3\npopulation = 6\npolish_iterations = 0";
  const IdentifyDefinition on = wall_and_offset(dir, "angle_deg", 1.2, 2.0, search);
  const IdentifyDefinition off =
      wall_and_offset(dir, "angle_deg", 1.2, 2.0, search + "\nprofile_offsets = false");
  IdentifyRunOptions o;
  o.threads = 2;
  IdentifyDb db_on = IdentifyDb::create((dir / "on.db").string(), on);
  IdentifyDb db_off = IdentifyDb::create((dir / "off.db").string(), off);
  const IdentifyResult projected = run_identify(on, db_on, o);
  const IdentifyResult searched = run_identify(off, db_off, o);
  EXPECT_LT(projected.cost_global, 0.1 * searched.cost_global)
      << projected.cost_global << " against " << searched.cost_global;
  const std::vector<double> values = parameter_values(on, projected.unit);
  EXPECT_NEAR(values[1], mean_difference(on, values), 1e-9) << "the least-squares offset";
}

// CMA-ES's population where the file gives none: the larger of 8 and Hansen's
// 4 + floor(3 ln m), m the parameters it moves (the projected offsets not counted).
TEST(IdentifyOffsetsTest, TheDefaultPopulationGrowsWithTheParametersSearched) {
  const auto with = [](int scenario_keys, int offsets, bool profile) {
    IdentifyDefinition def;
    def.profile_offsets = profile;
    for (int i = 0; i < scenario_keys + offsets; ++i) {
      def.parameters.push_back({"k" + std::to_string(i), 0.0, 1.0, false});
      ChannelParameter c;
      if (i >= scenario_keys) c = {ChannelParameter::Kind::kOffset, "angle_deg"};
      def.channel_parameters.push_back(c);
    }
    return default_population(def);
  };
  EXPECT_EQ(with(5, 0, true), 8u) << "4 + floor(3 ln 5) = 8";
  EXPECT_EQ(with(1, 3, true), 8u) << "never below 8";
  EXPECT_EQ(with(7, 3, true), 9u) << "4 + floor(5.84)";
  EXPECT_EQ(with(10, 10, true), 10u) << "the ten offsets set aside: 4 + floor(6.91)";
  EXPECT_EQ(with(10, 10, false), 12u) << "searched too: 4 + floor(3 ln 20) = 4 + 8";
  EXPECT_EQ(with(0, 3, true), 8u) << "nothing to search";
}

// Each search point is two stored residual vectors (the search's, the projected): a run
// stopped within the search and resumed ends where the uninterrupted one does, bit for bit.
TEST(IdentifyOffsetsTest, AStoppedRunResumedIsTheUninterruptedOne) {
  const fs::path dir = pamsim_test::fresh_dir("identify_offsets_resume");
  const IdentifyDefinition def =
      wall_and_offset(dir, "angle_deg", 1.2, 2.0,
                      "runs = 1\ngenerations = 3\npopulation = 6\npolish_iterations = 5");
  IdentifyRunOptions o;
  o.threads = 2;
  const auto run = [&](const std::string& db_name, bool resume, IdentifyRunOptions options) {
    const std::string path = (dir / db_name).string();
    IdentifyDb db = resume ? IdentifyDb::open_to_resume(path, def) : IdentifyDb::create(path, def);
    return run_identify(def, db, options);
  };
  const IdentifyResult whole = run("whole.db", false, o);
  std::atomic<bool> stop{false};
  IdentifyRunOptions stopping = o;
  stopping.stop = &stop;
  stopping.on_progress = [&](const std::string&, std::int64_t n) {
    if (n == 5) stop = true;
  };
  ASSERT_TRUE(run("part.db", false, stopping).interrupted);
  const IdentifyResult resumed = run("part.db", true, o);
  ASSERT_FALSE(resumed.interrupted);
  EXPECT_EQ(resumed.unit, whole.unit) << "bit for bit";
  EXPECT_EQ(resumed.cost_global, whole.cost_global);
}

}  // namespace
}  // namespace pamsim
