// sweep_randomize_test.cc: [[randomize]] in sweep files: the three
// distributions against their moments (the truncated normal against its closed-form mean),
// draws that depend on the seed index and randomize_seed alone (the same arms at every point,
// bit-identical on 1 or 2 threads and in two shards), the drawn values stored with each trial
// and replayed, and every bad table refused by its key.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <random>
#include <string>
#include <vector>

#include "base/format.h"
#include "base/input_error.h"
#include "sim/core/metrics.h"
#include "sim/cli_util.h"
#include "sim/scenario/randomize.h"
#include "sim/sweep/results_db.h"
#include "sim/sweep/sweep.h"
#include "sim/sweep/sweep_runner.h"
#include "sim/test_paths.h"

namespace pamsim {
namespace {

namespace fs = std::filesystem;

using pamsim_test::kDropMass;

// A sweep of drop_mass.toml, 1.3 s long: `top` its top-level keys, `tables` the rest.
SweepDefinition sweep_from(const fs::path& dir, const std::string& top, const std::string& tables) {
  const fs::path file = dir / "sweep.toml";
  pamsim_test::write_text(file, "base = \"" + kDropMass + "\"\n" + top +
                                    "[fixed.sim]\n"
                                    "duration_s = 1.3\n[fixed.drop]\ntime_s = 0.3\n" +
                                    tables);
  return load_sweep(file.string());
}

const std::string kAxis = "[[axis]]\nkey = \"reflex.v_thr_mm_s\"\nvalues = [50.0, 70.0]\n";
const std::string kDraws = "[[randomize]]\nkey = \"" + pamsim_test::kAgonistWall +
                           "\"\ndistribution = \"normal\"\n"
                           "mean = 2.0\nstddev = 0.1\nmin = 1.8\nmax = 2.3\n"
                           "[[randomize]]\nkey = \"pneumatics.chamber.tube_dead_volume_cm3\"\n"
                           "distribution = \"uniform\"\nfrom = 10.0\nto = 15.0\n";

struct Moments {
  double mean = 0, sd = 0, below_median = 0;
};

Moments moments_of(const Randomization& r, int n, double median = 0) {
  std::mt19937_64 rng(7);
  double sum = 0, sum2 = 0, below = 0;
  for (int i = 0; i < n; ++i) {
    const double v = r.draw(rng);
    EXPECT_TRUE(v >= r.min && v <= r.max) << v;
    sum += v;
    sum2 += v * v;
    below += v < median ? 1 : 0;
  }
  const double mean = sum / n;
  return {mean, std::sqrt(sum2 / n - mean * mean), below / n};
}

TEST(RandomizeTest, EachDistributionHasItsMoments) {
  const int n = 40000;
  Randomization u{"k", Distribution::kUniform, 2.0, 5.0};
  const Moments mu = moments_of(u, n);
  EXPECT_NEAR(mu.mean, 3.5, 4 * 3 / std::sqrt(12.0 * n));
  EXPECT_NEAR(mu.sd, 3 / std::sqrt(12.0), 0.01);
  Randomization g{"k", Distribution::kNormal, 1.0, 0.5};
  const Moments mg = moments_of(g, n);
  EXPECT_NEAR(mg.mean, 1.0, 4 * 0.5 / std::sqrt(n));
  EXPECT_NEAR(mg.sd, 0.5, 0.01);
  Randomization l{"k", Distribution::kLogNormal, 3.0, 0.2};
  const Moments ml = moments_of(l, n, 3.0);
  EXPECT_NEAR(ml.below_median, 0.5, 4 * 0.5 / std::sqrt(n));
  EXPECT_NEAR(ml.mean, 3.0 * std::exp(0.02), 0.01);  // E = median exp(sigma^2 / 2)
  EXPECT_DOUBLE_EQ(l.kept_share(), 1.0);
}

// A normal truncated to [m - 0.5 s, m + 2 s]: mean m + s (phi(a) - phi(b)) / (Phi(b) - Phi(a)).
TEST(RandomizeTest, TheTruncatedNormalHasItsClosedFormMean) {
  Randomization t{"k", Distribution::kNormal, 10.0, 2.0, 9.0, 14.0};
  const auto phi = [](double z) { return std::exp(-z * z / 2) / std::sqrt(2 * M_PI); };
  const auto cdf = [](double z) { return 0.5 * std::erfc(-z / std::sqrt(2.0)); };
  const double kept = cdf(2.0) - cdf(-0.5);
  EXPECT_NEAR(t.kept_share(), kept, 1e-12);
  const double mean = 10.0 + 2.0 * (phi(-0.5) - phi(2.0)) / kept;
  EXPECT_NEAR(moments_of(t, 40000).mean, mean, 0.02);
}

TEST(RandomizeTest, DrawsDependOnTheSeedIndexAndTheSeedAlone) {
  const fs::path dir = pamsim_test::fresh_dir("randomize_draws");
  const SweepDefinition s = sweep_from(dir, "seeds = 3\n", kAxis + kDraws);
  ASSERT_EQ(s.trials(), 6);
  EXPECT_EQ(s.draws(0), s.draws(3)) << "the same arms at every point";
  EXPECT_EQ(s.draws(2), s.draws(5));
  EXPECT_NE(s.draws(0), s.draws(1));
  const SweepDefinition other = sweep_from(dir, "seeds = 3\nrandomize_seed = 2\n", kAxis + kDraws);
  EXPECT_NE(other.draws(0), s.draws(0));
  EXPECT_NE(other.canonical_json(), s.canonical_json());
  const std::vector<std::string> o = s.trial_overrides(4);
  EXPECT_EQ(o[o.size() - 2].rfind(pamsim_test::kAgonistWall + "=", 0), 0u) << o[o.size() - 2];
  EXPECT_EQ(o[o.size() - 3], "reflex.v_thr_mm_s=70.0");
  // a sweep without draws describes itself as before [[randomize]] existed
  EXPECT_EQ(sweep_from(dir, "", kAxis).canonical_json().find("randomize"), std::string::npos);
}

// Rows of a database in trial order, every column as text (timing aside).
std::vector<std::string> rows_of(const std::string& path) {
  const ResultsDb db = ResultsDb::open_existing(path);
  const std::vector<std::string> columns = db.trial_columns();
  std::vector<std::string> rows;
  db.for_each_trial([&](const std::vector<DbValue>& cells) {
    std::string row;
    for (std::size_t c = 0; c < cells.size(); ++c) {
      if (is_timing_metric(columns[c])) continue;
      row += (cells[c].kind == DbValue::Kind::kNumber ? format_shortest(cells[c].number)
                                                      : cells[c].text) +
             ";";
    }
    rows.push_back(row);
  });
  return rows;
}

TEST(RandomizeTest, TheDrawnValuesAreStoredAndTheSameOnAnyThreadCountOrShard) {
  const fs::path dir = pamsim_test::fresh_dir("randomize_runs");
  const SweepDefinition s = sweep_from(dir, "seeds = 3\n", kAxis + kDraws);
  auto run = [&](const std::string& name, int threads, SweepShard shard) {
    const std::string path = (dir / name).string();
    ResultsDb db = ResultsDb::create(path, s, shard);
    SweepRunOptions options;
    options.threads = threads;
    options.shard = shard;
    run_sweep(s, db, options);
    return path;
  };
  const std::vector<std::string> one = rows_of(run("one.db", 1, {}));
  EXPECT_EQ(rows_of(run("two.db", 2, {})), one);
  const std::vector<std::string> a = rows_of(run("a.db", 1, {0, 2}));
  const std::vector<std::string> b = rows_of(run("b.db", 1, {1, 2}));
  ASSERT_EQ(a.size() + b.size(), one.size());
  for (std::size_t t = 0; t < one.size(); ++t) EXPECT_EQ(t % 2 ? b[t / 2] : a[t / 2], one[t]);
  // the columns hold the draws
  const ResultsDb db = ResultsDb::open_existing((dir / "one.db").string());
  const std::vector<std::string> columns = db.trial_columns();
  const auto wall =
      std::find(columns.begin(), columns.end(), pamsim_test::kAgonistWall) - columns.begin();
  ASSERT_LT(static_cast<std::size_t>(wall), columns.size());
  for (std::int64_t t = 0; t < s.trials(); ++t) {
    EXPECT_EQ(db.trial_row(t)[static_cast<std::size_t>(wall)].number, s.draws(t)[0]) << t;
  }
}

TEST(RandomizeTest, AReplayedTrialRunsItsDrawnValues) {
  const fs::path dir = pamsim_test::fresh_dir("randomize_replay");
  const fs::path file = dir / "sweep.toml";
  pamsim_test::write_text(file, "base = \"" + kDropMass +
                                    "\"\nseeds = 2\n[fixed.sim]\n"
                                    "duration_s = 1.3\n[fixed.drop]\ntime_s = 0.3\n" +
                                    kAxis + kDraws);
  const std::string db = (dir / "s.db").string();
  ASSERT_EQ(pamsim_test::run_pamsim("sweep " + file.string() + " --db " + db).exit_code, 0);
  const pamsim_test::CliResult replay = pamsim_test::run_pamsim(
      "replay " + db + " --trial 3 --no-plot --out " + (dir / "t3").string());
  ASSERT_EQ(replay.exit_code, 0) << replay.err;
  EXPECT_NE(replay.err.find("the replay equals the stored trial"), std::string::npos) << replay.err;
  const std::string resolved = pamsim_test::read_file(dir / "t3" / "scenario.toml");
  const SweepDefinition s = load_sweep(file.string());
  EXPECT_NE(resolved.find("tube_dead_volume_cm3 = " + format_shortest(s.draws(3)[1])),
            std::string::npos)
      << resolved;
}

TEST(RandomizeTest, TheShippedRobustnessSweepDrawsInsideItsRanges) {
  const SweepDefinition s =
      load_sweep(std::string(PAMSIM_SOURCE_DIR) + "/scenarios/sweep_robustness.toml");
  EXPECT_EQ(s.trials(), 200);
  ASSERT_EQ(s.randomize.size(), 10u);
  for (std::int64_t t = 0; t < s.seeds; ++t) {
    const std::vector<double> v = s.draws(t);
    for (std::size_t k = 0; k < v.size(); ++k) {
      EXPECT_GE(v[k], s.randomize[k].a) << s.randomize[k].key;
      EXPECT_LT(v[k], s.randomize[k].b) << s.randomize[k].key;
    }
  }
}

TEST(RandomizeTest, BadTablesAreRefusedByTheirKey) {
  const fs::path dir = pamsim_test::fresh_dir("randomize_bad");
  const std::string head = "[[randomize]]\nkey = \"" + pamsim_test::kAgonistWall + "\"\n";
  for (const auto& [body, says] : std::vector<std::pair<std::string, std::string>>{
           {head + "from = 1.0\nto = 2.0\n", "randomize[0].distribution is required"},
           {head + "distribution = \"beta\"\n",
            "randomize[0].distribution is \"beta\", allowed \"uniform\" | \"normal\""},
           {head + "distribution = \"uniform\"\nfrom = 2.0\n", "randomize[0].to is required"},
           {head + "distribution = \"uniform\"\nfrom = 2.0\nto = 2.0\n",
            "randomize[0].from must be below to"},
           {head + "distribution = \"uniform\"\nfrom = 1.0\nto = nan\n",
            "randomize[0].to must be finite"},
           {head + "distribution = \"uniform\"\nfrom = 1.0\nto = 2.0\nmin = 1.0\n",
            "randomize[0].min is not a key of a uniform draw"},
           {head + "distribution = \"normal\"\nmean = 2.0\nstddev = 0.0\n",
            "randomize[0].stddev must be in (0, inf), got 0"},
           {head + "distribution = \"normal\"\nmean = 2.0\nsd = 0.1\n",
            "randomize[0].sd is not a key of this table (key, distribution, from"},
           {head + "distribution = \"normal\"\nmean = 2.0\nstddev = 0.1\nmin = 2.5\nmax = 2.4\n",
            "randomize[0].min must be below max"},
           {head + "distribution = \"normal\"\nmean = 2.0\nstddev = 0.1\nmin = 2.4\n",
            "keep 0.003"},
           {head + "distribution = \"lognormal\"\nmedian = -1.0\nsigma = 0.1\n",
            "randomize[0].median must be in (0, inf), got -1"},
           {"[[randomize]]\ndistribution = \"uniform\"\nfrom = 1.0\nto = 2.0\n",
            "randomize[0].key is required"},
           {"[[randomize]]\nkey = \"seed\"\ndistribution = \"uniform\"\nfrom = 1.0\nto = 2.0\n",
            "randomize[0].key cannot be \"seed\""},
           {head + "distribution = \"uniform\"\nfrom = 1.0\nto = 2.0\n" + head +
                "distribution = \"uniform\"\nfrom = 1.0\nto = 2.0\n",
            "randomize names " + pamsim_test::kAgonistWall + " twice"},
           {"[[randomize]]\nkey = \"reflex.v_thr_mm_s\"\ndistribution = \"uniform\"\nfrom = "
            "1.0\nto = 2.0\n",
            "randomize sets reflex.v_thr_mm_s, which axis[0] sets too"},
           {"[[randomize]]\nkey = \"drop.time_s\"\ndistribution = \"uniform\"\nfrom = 0.1\nto = "
            "0.2\n",
            "randomize sets drop.time_s, which [fixed] sets too"},  // sweep_from's [fixed.drop]
           {"randomize_seed = 3\n!", "randomize_seed is for files with [[randomize]]"},
           {"randomize_seed = -1\n!" + head + "distribution = \"uniform\"\nfrom = 1.0\nto = 2.0\n",
            "randomize_seed must be >= 0"},
           {head + "distribution = \"uniform\"\nfrom = -2.0\nto = -1.0\n",
            "seed index 0 draws " + pamsim_test::kAgonistWall},
           {"[[randomize]]\nkey = \"reflex.colour\"\ndistribution = \"uniform\"\nfrom = 1.0\nto = "
            "2.0\n",
            "reflex.colour"}}) {
    SCOPED_TRACE(body);
    try {
      const std::size_t bang = body.find('!');  // top-level keys before it
      if (bang == std::string::npos)
        sweep_from(dir, "", kAxis + body);
      else
        sweep_from(dir, body.substr(0, bang), kAxis + body.substr(bang + 1));
      ADD_FAILURE() << "accepted";
    } catch (const InputError& e) {
      const std::string what = e.what();
      EXPECT_NE(what.find(says), std::string::npos) << what;
      EXPECT_EQ(what.find('\n'), std::string::npos) << what;
    }
  }
}

}  // namespace
}  // namespace pamsim
