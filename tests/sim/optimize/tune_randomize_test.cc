// tune_randomize_test.cc: robust tuning: a tuning file's [[randomize]]
// tables give each evaluation's k-th seed its own drawn arm, the same arm at every point the
// optimiser tries (so points differ by their parameters, not by their draws); the draws are
// part of the stored definition and read back from it; a drawn key that is also a parameter,
// or the noise scale, is refused.
#include <gtest/gtest.h>

#include <sqlite3.h>

#include <map>
#include <set>
#include <string>

#include <nlohmann/json.hpp>

#include "base/input_error.h"
#include "sim/cli_util.h"
#include "sim/optimize/tune.h"
#include "sim/optimize/tune_db.h"
#include "sim/optimize/tuning_file.h"
#include "sim/test_paths.h"

namespace pamsim {
namespace {

using pamsim_test::kScenarios;

// The ideal arm without drop or reflex for 0.6 s: where it ends depends on the basket's mass
// (drawn) and not on the pressure sensor's bias (the parameter), which only the estimate sees.
std::string robust_tuning(const std::string& dir, const std::string& extra) {
  const std::string text =
      "base = \"" + kScenarios +
      "drop_mass_ideal.toml\"\n"
      "overrides = [\"sim.duration_s=0.6\", \"drop.time_s=0.3\", \"drop.enabled=false\", "
      "\"reflex.enabled=false\"]\n"
      "algorithm = \"cmaes\"\ngenerations = 1\npopulation = 6\nseed = 3\nseeds = 3\n"
      "noise_scales = [0.0]\nheld_out_seeds = 0\nrandomize_seed = 5\n"
      "[[parameter]]\nkey = \"sensors.pressure_bias_MPa\"\nfrom = -0.05\nto = 0.03\n"
      "[[objective]]\nmetric = \"length_est_rmse_pct\"\n"
      "[[randomize]]\nkey = \"bodies.basket.mass_kg\"\ndistribution = \"uniform\"\n"
      "from = 0.05\nto = 0.15\n" +
      extra;
  const std::string path = dir + "/robust.toml";
  pamsim_test::write_text(path, text);
  return path;
}

// final_angle_deg of every stored trial, by evaluation and seed
std::map<int, std::map<std::uint64_t, double>> final_angles(const std::string& db_path) {
  sqlite3* db = nullptr;
  EXPECT_EQ(sqlite3_open_v2(db_path.c_str(), &db, SQLITE_OPEN_READONLY, nullptr), SQLITE_OK);
  sqlite3_stmt* st = nullptr;
  sqlite3_prepare_v2(db, "SELECT evaluation, seed, metrics FROM trials", -1, &st, nullptr);
  std::map<int, std::map<std::uint64_t, double>> out;
  while (sqlite3_step(st) == SQLITE_ROW) {
    const auto metrics =
        nlohmann::json::parse(reinterpret_cast<const char*>(sqlite3_column_text(st, 2)));
    out[sqlite3_column_int(st, 0)][static_cast<std::uint64_t>(sqlite3_column_int64(st, 1))] =
        metrics.at("final_angle_deg").get<double>();
  }
  sqlite3_finalize(st);
  sqlite3_close(db);
  return out;
}

TEST(TuneRandomizeTest, EveryPointTriedSeesTheSameDrawnArms) {
  const std::string dir = pamsim_test::fresh_dir("tune_randomize").string();
  const TuneDefinition def = load_tune_definition(robust_tuning(dir, ""));
  ASSERT_EQ(def.randomize.size(), 1u);
  TuneDb db = TuneDb::create(dir + "/tune.db", def);
  TuneRunOptions o;
  o.threads = 2;
  const TuneRunResult r = run_tune(def, db, o);
  ASSERT_EQ(r.history.size(), 12u);  // the initial population and one generation
  const auto angles = final_angles(dir + "/tune.db");
  ASSERT_EQ(angles.size(), 12u);
  const std::map<std::uint64_t, double>& first = angles.begin()->second;
  ASSERT_EQ(first.size(), 3u);
  for (const auto& [evaluation, by_seed] : angles) EXPECT_EQ(by_seed, first) << evaluation;
  std::set<double> arms;
  for (const auto& [seed, angle] : first) arms.insert(angle);
  EXPECT_EQ(arms.size(), 3u) << "each seed its own arm";
  // without the draws every seed ends where the nominal basket puts the arm
  const std::string plain_dir = pamsim_test::fresh_dir("tune_randomize_plain").string();
  std::string plain = pamsim_test::read_file(robust_tuning(plain_dir, ""));
  plain = plain.substr(0, plain.find("[[randomize]]"));
  plain.replace(plain.find("randomize_seed = 5\n"), 19, "");
  pamsim_test::write_text(plain_dir + "/plain.toml", plain);
  const TuneDefinition nominal = load_tune_definition(plain_dir + "/plain.toml");
  TuneDb plain_db = TuneDb::create(plain_dir + "/tune.db", nominal);
  run_tune(nominal, plain_db, o);
  std::set<double> nominal_ends;
  const auto nominal_angles = final_angles(plain_dir + "/tune.db");
  for (const auto& [seed, angle] : nominal_angles.begin()->second) nominal_ends.insert(angle);
  EXPECT_EQ(nominal_ends.size(), 1u);
  EXPECT_EQ(arms.count(*nominal_ends.begin()), 0u);
}

TEST(TuneRandomizeTest, TheDrawsArePartOfTheStoredDefinition) {
  const std::string dir = pamsim_test::fresh_dir("tune_randomize_json").string();
  const TuneDefinition def = load_tune_definition(robust_tuning(dir, ""));
  const std::string json = def.canonical_json();
  EXPECT_NE(json.find("bodies.basket.mass_kg"), std::string::npos);
  const TuneDefinition back = tune_definition_from_json(json, def.file, "db");
  EXPECT_EQ(back.canonical_json(), json);
  EXPECT_EQ(back.randomize_seed, 5u);
}

TEST(TuneRandomizeTest, ADrawnParameterOrNoiseScaleIsRefused) {
  const std::string dir = pamsim_test::fresh_dir("tune_randomize_bad").string();
  for (const auto& [extra, says] : std::vector<std::pair<std::string, std::string>>{
           {"[[randomize]]\nkey = \"sensors.pressure_bias_MPa\"\ndistribution = \"uniform\"\n"
            "from = 0.0\nto = 0.01\n",
            "draws sensors.pressure_bias_MPa, which is a parameter too"},
           {"[[randomize]]\nkey = \"sensors.noise_scale\"\ndistribution = \"uniform\"\n"
            "from = 0.0\nto = 1.0\n",
            "cannot draw sensors.noise_scale"},
           {"[[randomize]]\nkey = \"bodies.arm.mass_kg\"\ndistribution = \"uniform\"\n"
            "from = -1.0\nto = 0.0\n",
            "the draws of seed index 0"}}) {
    SCOPED_TRACE(extra);
    try {
      load_tune_definition(robust_tuning(dir, extra));
      ADD_FAILURE() << "accepted";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(says), std::string::npos) << e.what();
    }
  }
}

}  // namespace
}  // namespace pamsim
