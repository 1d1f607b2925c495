// tune_test.cc: `pamsim tune` (src/sim/optimize/tune.h): the optimiser finds an optimum known
// from physics, an interrupted run resumed gives the uninterrupted run's result without
// evaluating anything twice, the same seed gives the same history, and bad tuning files are
// refused in one line with no database left.
#include "sim/optimize/tune_outputs.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <sqlite3.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include "sim/cli_util.h"
#include "base/input_error.h"
#include "sim/test_paths.h"

namespace pamsim {
namespace {

namespace fs = std::filesystem;
using pamsim_test::kScenarios;

// A pressure-sensor bias b shifts every Eq. (3) inversion: on the ideal plant without noise
// the length estimate is exact only at b = 0, so the estimate's RMS error has its minimum
// there. Short trials (0.6 s, no drop).
std::string bias_tuning(const std::string& dir, int generations) {
  const std::string text =
      "base = \"" + kScenarios + "drop_mass_ideal.toml\"\n" +
      "overrides = [\"sim.duration_s=0.6\", \"drop.time_s=0.3\", \"drop.enabled=false\", "
      "\"reflex.enabled=false\"]\n"
      "algorithm = \"cmaes\"\ngenerations = " +
      std::to_string(generations) +
      "\npopulation = 6\nseed = 3\nseeds = 1\nnoise_scales = [0.0]\n"
      "held_out_seeds = 0\n"
      "[[parameter]]\nkey = \"sensors.pressure_bias_MPa\"\n"
      "from = -0.05\nto = 0.03\n"
      "[[objective]]\nmetric = \"length_est_rmse_pct\"\n"
      "[[constraint]]\nmetric = \"length_est_max_error_pct\"\nmax = 100.0\n"
      "[[reference]]\nname = \"no bias\"\nvalues = [0.0]\n";
  const std::string path = dir + "/bias.toml";
  pamsim_test::write_text(path, text);
  return path;
}

std::string fresh(const std::string& name) {
  return pamsim_test::fresh_dir("tune_" + name).string();
}

TEST(TuneTest, CmaesFindsThePressureBiasThatMakesTheEstimateExact) {
  const std::string dir = fresh("bias");
  const TuneDefinition def = load_tune_definition(bias_tuning(dir, 10));
  TuneDb db = TuneDb::create(dir + "/tune.db", def);
  TuneRunOptions o;
  o.threads = 2;
  const TuneRunResult r = run_tune(def, db, o);
  ASSERT_EQ(r.history.size(), 6u * 11u);
  const TuneEvaluation* best = best_evaluation(r.history);
  ASSERT_NE(best, nullptr);
  EXPECT_EQ(best->violation, 0.0);
  EXPECT_NEAR(best->values[0], 0.0, 0.002) << "the bias that makes Eq. (3)'s inversion exact";
  // and far better than the worst point tried
  double worst = 0.0;
  for (const TuneEvaluation& e : r.history) worst = std::max(worst, e.objectives[0]);
  EXPECT_LT(best->objectives[0], 0.2 * worst);
}

TEST(TuneTest, AnInterruptedRunResumedEqualsAnUninterruptedOne) {
  const std::string dir = fresh("resume");
  const TuneDefinition def = load_tune_definition(bias_tuning(dir, 5));
  TuneRunOptions o;
  o.threads = 2;

  TuneDb whole = TuneDb::create(dir + "/whole.db", def);
  const TuneRunResult uninterrupted = run_tune(def, whole, o);

  // stop after 13 evaluations (mid-generation), then resume in a new handle
  TuneRunResult first, second;
  {
    TuneDb db = TuneDb::create(dir + "/parts.db", def);
    std::atomic<bool> stop{false};
    TuneRunOptions stopping = o;
    stopping.stop = &stop;
    stopping.on_evaluation = [&](std::int64_t, std::int64_t, bool cached) {
      static int fresh_evaluations = 0;
      if (!cached && ++fresh_evaluations >= 13) stop = true;
    };
    first = run_tune(def, db, stopping);
  }
  EXPECT_TRUE(first.interrupted);
  ASSERT_EQ(first.history.size(), 13u);
  {
    TuneDb db = TuneDb::open_to_resume(dir + "/parts.db", def);
    second = run_tune(def, db, o);
  }
  EXPECT_FALSE(second.interrupted);
  EXPECT_EQ(second.cached, 13) << "the stored evaluations answer the replay";
  ASSERT_EQ(second.history.size(), uninterrupted.history.size());
  for (std::size_t i = 0; i < second.history.size(); ++i) {
    EXPECT_EQ(second.history[i].index, uninterrupted.history[i].index);
    EXPECT_EQ(second.history[i].values, uninterrupted.history[i].values) << i;
    EXPECT_EQ(second.history[i].fitness, uninterrupted.history[i].fitness) << i;
  }
  EXPECT_EQ(tune_evaluations_csv(def, second.history),
            tune_evaluations_csv(def, uninterrupted.history));
  // a resume of another definition is refused
  const TuneDefinition other = load_tune_definition(bias_tuning(dir, 6));
  EXPECT_THROW(TuneDb::open_to_resume(dir + "/parts.db", other), InputError);
}

TEST(TuneTest, CliWritesItsOutputsAndReportReadsTheDatabase) {
  const std::string dir = fresh("cli");
  const std::string file = bias_tuning(dir, 2);
  const auto r = pamsim_test::run_pamsim("tune " + file + " --threads 2 --out " + dir + "/out");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  for (const char* f : {"tune.db", "best.toml", "evaluations.csv", "convergence.png"}) {
    EXPECT_TRUE(fs::exists(dir + "/out/" + f)) << f;
  }
  // best.toml runs as it is
  const auto run = pamsim_test::run_pamsim("run " + dir + "/out/best.toml --out " + dir + "/run");
  EXPECT_EQ(run.exit_code, 0) << run.err;
  // report regenerates the outputs from the database alone; over the tuning's own, only
  // with --force
  fs::remove(dir + "/out/best.toml");
  const auto refused = pamsim_test::run_pamsim("report " + dir + "/out/tune.db");
  EXPECT_EQ(refused.exit_code, 2);
  EXPECT_NE(refused.err.find("add --force"), std::string::npos) << refused.err;
  EXPECT_FALSE(fs::exists(dir + "/out/best.toml"));
  const auto rep = pamsim_test::run_pamsim("report " + dir + "/out/tune.db --force");
  EXPECT_EQ(rep.exit_code, 0) << rep.err;
  EXPECT_TRUE(fs::exists(dir + "/out/best.toml"));
  EXPECT_NE(rep.out.find("18 evaluations stored"), std::string::npos) << rep.out;
  // a second run into the same database is refused without --resume; with it, nothing runs
  EXPECT_NE(pamsim_test::run_pamsim("tune " + file + " --out " + dir + "/out").exit_code, 0);
  const auto again = pamsim_test::run_pamsim("tune " + file + " --resume --out " + dir + "/out");
  EXPECT_EQ(again.exit_code, 0) << again.err;
  EXPECT_NE(again.err.find("18 proposals answered from the database"), std::string::npos)
      << again.err;
}

// What a kill leaves (every evaluation committed before it, nothing after; one transaction
// per evaluation), made by deleting the last evaluations of a finished run, then resumed
// from the command line: the same evaluations and best setting as the uninterrupted run.
TEST(TuneTest, AKilledRunResumedFromTheCommandLineEqualsTheUninterruptedOne) {
  const std::string dir = fresh("kill");
  const std::string file = bias_tuning(dir, 3);
  ASSERT_EQ(pamsim_test::run_pamsim("tune " + file + " --out " + dir + "/whole").exit_code, 0);
  ASSERT_EQ(pamsim_test::run_pamsim("tune " + file + " --out " + dir + "/cut").exit_code, 0);
  {
    sqlite3* db = nullptr;
    ASSERT_EQ(sqlite3_open((dir + "/cut/tune.db").c_str(), &db), SQLITE_OK);
    ASSERT_EQ(sqlite3_exec(db,
                           "DELETE FROM trials WHERE evaluation >= 9;"
                           "DELETE FROM evaluations WHERE evaluation >= 9;",
                           nullptr, nullptr, nullptr),
              SQLITE_OK);
    sqlite3_close(db);
  }
  fs::remove(dir + "/cut/evaluations.csv");
  fs::remove(dir + "/cut/best.toml");
  const auto r = pamsim_test::run_pamsim("tune " + file + " --resume --out " + dir + "/cut");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("9 proposals answered"), std::string::npos) << r.err;
  EXPECT_EQ(pamsim_test::read_file(dir + "/cut/evaluations.csv"),
            pamsim_test::read_file(dir + "/whole/evaluations.csv"));
  EXPECT_EQ(pamsim_test::read_file(dir + "/cut/best.toml"),
            pamsim_test::read_file(dir + "/whole/best.toml"));
}

// NSGA-II on two objectives: a Pareto front in which no member dominates another, written as
// CSV and a figure
TEST(TuneTest, Nsga2WritesANonDominatedParetoFront) {
  const std::string dir = fresh("nsga2");
  std::string text = pamsim_test::read_file(bias_tuning(dir, 3));
  const auto swap = [&](const std::string& from, const std::string& to) {
    ASSERT_NE(text.find(from), std::string::npos) << from;
    text.replace(text.find(from), from.size(), to);
  };
  swap("algorithm = \"cmaes\"", "algorithm = \"nsga2\"");
  swap("population = 6", "population = 8");
  text += "[[objective]]\nmetric = \"length_est_max_error_pct\"\n";
  pamsim_test::write_text(dir + "/two.toml", text);
  const auto r =
      pamsim_test::run_pamsim("tune " + dir + "/two.toml --threads 2 --out " + dir + "/out");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(fs::exists(dir + "/out/pareto.png"));
  const TuneDb db = TuneDb::open_existing(dir + "/out/tune.db");
  const std::vector<TuneEvaluation> history = db.evaluations();
  // 8 x (3 + 1) calls; a point NSGA-II proposes twice is evaluated once
  EXPECT_GE(history.size(), 8u);
  EXPECT_LE(history.size(), 8u * 4u);
  const std::vector<const TuneEvaluation*> front = pareto_front(history);
  ASSERT_FALSE(front.empty());
  for (const TuneEvaluation* a : front) {
    for (const TuneEvaluation* b : front) {
      const bool dominated = b->fitness[0] <= a->fitness[0] && b->fitness[1] <= a->fitness[1] &&
                             (b->fitness[0] < a->fitness[0] || b->fitness[1] < a->fitness[1]);
      EXPECT_FALSE(dominated) << b->index << " dominates " << a->index;
    }
  }
  // and every feasible point off the front is dominated by one on it
  for (const TuneEvaluation& e : history) {
    if (e.violation != 0.0 || std::find(front.begin(), front.end(), &e) != front.end()) continue;
    bool dominated = false;
    for (const TuneEvaluation* f : front) {
      dominated |= f->fitness[0] <= e.fitness[0] && f->fitness[1] <= e.fitness[1] &&
                   (f->fitness[0] < e.fitness[0] || f->fitness[1] < e.fitness[1]);
    }
    EXPECT_TRUE(dominated) << "evaluation " << e.index;
  }
  const std::string csv = pamsim_test::read_file(dir + "/out/pareto.csv");
  EXPECT_EQ(pamsim_test::line_count(csv), static_cast<int>(front.size()) + 1);
}

TEST(TuneTest, BadTuningFilesAreOneLineAndLeaveNoDatabase) {
  const std::string dir = fresh("bad");
  const std::string good = pamsim_test::read_file(bias_tuning(dir, 2));
  struct Case {
    std::string from, to, says;
  };
  for (const Case& c : std::vector<Case>{
           {"from = -0.05\nto = 0.03", "from = 0.03\nto = -0.05", "parameter[0].from"},
           {"key = \"sensors.pressure_bias_MPa\"", "key = \"sensors.no_such_key\"", "no_such_key"},
           {"metric = \"length_est_rmse_pct\"", "metric = \"no_such_metric\"", "no_such_metric"},
           {"seeds = 1", "seeds = 0", "seeds"},
           {"population = 6", "population = 3", "population"},
           {"algorithm = \"cmaes\"", "algorithm = \"annealing\"", "algorithm"},
           {"to = 0.03", "to = 0.03\nscale = \"log\"", "parameter[0].from"},
           // an integer with no exact double (beyond 2^53): refused, not read through
           {"from = -0.05", "from = 9007199254740993", "parameter[0].from must be a number"},
           {"max = 100.0", "min = 5.0\nmax = 1.0", "constraint[0].min"},
           {"noise_scales = [0.0]", "noise_scales = [0.0, 0.0]", "noise_scales"},
           {"values = [0.0]", "values = [0.0, 1.0]", "reference[0].values"},
           {"values = [0.0]", "values = [5.0]", "reference[0]"},
           {"[[objective]]",
            "[[parameter]]\nkey = \"sensors.pressure_bias_MPa\"\nfrom = 0.0\nto = 0.01\n"
            "[[objective]]",
            "parameter[1].key names sensors.pressure_bias_MPa twice"}}) {
    std::string text = good;
    ASSERT_NE(text.find(c.from), std::string::npos) << c.from;
    text.replace(text.find(c.from), c.from.size(), c.to);
    pamsim_test::write_text(dir + "/case.toml", text);
    const auto r = pamsim_test::run_pamsim("tune " + dir + "/case.toml --out " + dir + "/out");
    EXPECT_EQ(r.exit_code, 2) << c.to;
    EXPECT_EQ(pamsim_test::line_count(r.err), 1) << c.to << ": " << r.err;
    EXPECT_NE(r.err.find(c.says), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(dir + "/out/tune.db")) << c.to;
  }
}

}  // namespace
}  // namespace pamsim
