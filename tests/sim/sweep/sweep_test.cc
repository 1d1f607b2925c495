// sweep_test.cc: sweep definitions (grid order, linear and log ranges, Latin hypercube
// strata, exact values), the results database (round trip, refused duplicates and other
// sweeps), shards and the runner's checks; sweep_report_test.cc has the report.
#include <gtest/gtest.h>

#include "base/format.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <set>
#include <sstream>
#include <string>

#include "sim/cli_util.h"
#include "base/input_error.h"
#include "reflex/stretch_reflex_controller.h"
#include "sim/scenario/scenario_file.h"
#include "sim/cli/progress.h"
#include "sim/sweep/report.h"
#include "sim/sweep/results_db.h"
#include "sim/sweep/sweep.h"
#include "sim/sweep/sweep_runner.h"
#include "sim/test_paths.h"

namespace {

namespace fs = std::filesystem;
using pamsim::AxisValue;
using pamsim::InputError;
using pamsim::ResultsDb;
using pamsim::SweepDefinition;
using pamsim_test::fresh_dir;
using pamsim_test::write_text;

using pamsim_test::kDropMass;

SweepDefinition sweep_from(const fs::path& dir, const std::string& body) {
  const fs::path file = dir / "sweep.toml";
  write_text(file, "base = \"" + kDropMass + "\"\n" + body);
  return pamsim::load_sweep(file.string());
}

class SweepTest : public ::testing::Test {
 protected:
  fs::path dir_ = fresh_dir("sweep_unit");
};

TEST_F(SweepTest, GridIsRowMajorWithTheFirstAxisSlowest) {
  const SweepDefinition s =
      sweep_from(dir_,
                 "seeds = 3\n[[axis]]\nkey = \"reflex.v_thr_mm_s\"\nvalues = [50.0, 60.0]\n"
                 "[[axis]]\nkey = \"reflex.sensor\"\nvalues = [\"model\", \"fiber\", \"model\"]\n");
  ASSERT_EQ(s.points(), 6);
  EXPECT_EQ(s.trials(), 18);
  EXPECT_EQ(s.value(0, 0).number, 50.0);
  EXPECT_EQ(s.value(2, 0).number, 50.0);
  EXPECT_EQ(s.value(3, 0).number, 60.0);
  EXPECT_EQ(s.value(1, 1).text, "fiber");
  EXPECT_EQ(s.value(4, 1).text, "fiber");
  // every point sees the same seeds: base seed 1, then 2, 3
  EXPECT_EQ(s.seed_of(0), 1u);
  EXPECT_EQ(s.seed_of(5), 3u);
  EXPECT_EQ(s.seed_of(6), 1u);
  const auto o = s.overrides(4);
  EXPECT_EQ(o.back(), "reflex.sensor='fiber'");  // a TOML literal string
  EXPECT_EQ(o[o.size() - 2], "reflex.v_thr_mm_s=60.0");
}

TEST_F(SweepTest, MaxTrialsCapsPointsTimesSeedsAndRaisingItLetsTheSweepThrough) {
  const std::string body =
      "seeds = 3\n[[axis]]\nkey = \"reflex.v_thr_mm_s\"\nvalues = [50.0, 60.0]\n";
  EXPECT_THROW(sweep_from(dir_, "max_trials = 5\n" + body), InputError);
  EXPECT_EQ(sweep_from(dir_, "max_trials = 6\n" + body).trials(), 6);
  // the cap is not part of the experiment: raising it keeps a database resumable
  EXPECT_EQ(sweep_from(dir_, "max_trials = 6\n" + body).canonical_json(),
            sweep_from(dir_, body).canonical_json());
}

TEST_F(SweepTest, RangesHitTheirEndsExactlyAndLogRangesAreGeometric) {
  const SweepDefinition s =
      sweep_from(dir_,
                 "[[axis]]\nkey = \"reflex.v_thr_mm_s\"\nfrom = 10.0\nto = 200.0\ncount = 20\n"
                 "[[axis]]\nkey = \"reflex.k_MPa_s_per_mm\"\nfrom = 0.0001\nto = 0.01\ncount = 5\n"
                 "scale = \"log\"\n[fixed.sim]\nduration_s = 1.5\n");
  const auto& v = s.axes[0].values;
  const auto& k = s.axes[1].values;
  ASSERT_EQ(v.size(), 20u);
  ASSERT_EQ(k.size(), 5u);
  EXPECT_EQ(v.front().number, 10.0);
  EXPECT_EQ(v.back().number, 200.0);
  EXPECT_DOUBLE_EQ(v[1].number - v[0].number, 10.0);
  EXPECT_EQ(k.front().number, 0.0001);
  EXPECT_EQ(k.back().number, 0.01);
  for (std::size_t i = 1; i < k.size(); ++i) {
    EXPECT_NEAR(k[i].number / k[i - 1].number, std::sqrt(10.0), 1e-9);
  }
  EXPECT_EQ(k[2].toml(), "0.001");  // tidy levels, exact as written
  EXPECT_EQ(s.fixed, std::vector<std::string>{"sim.duration_s=1.5"});
}

TEST_F(SweepTest, AxisValuesRoundTripExactlyThroughToml) {
  for (double x : {0.1, 1.0 / 3.0, 1e-300, 123456789.125, -2.5e17, 20.0}) {
    AxisValue a;
    a.number = x;
    const std::string text = a.toml();
    EXPECT_EQ(std::strtod(text.c_str(), nullptr), x) << text;
    EXPECT_NE(text.find_first_of(".e"), std::string::npos) << text << " must stay a float";
  }
}

TEST_F(SweepTest, LatinHypercubePutsOnePointInEveryStratumOfEveryAxis) {
  const std::string body =
      "design = \"lhs\"\nsamples = 16\ndesign_seed = 7\n"
      "[[axis]]\nkey = \"reflex.v_thr_mm_s\"\nfrom = 20.0\nto = 180.0\n"
      "[[axis]]\nkey = \"reflex.k_MPa_s_per_mm\"\nfrom = 0.0001\nto = 0.01\nscale = \"log\"\n";
  const SweepDefinition s = sweep_from(dir_, body);
  ASSERT_EQ(s.points(), 16);
  std::set<int> v_strata, k_strata;
  for (std::int64_t p = 0; p < 16; ++p) {
    const double u_v = (s.value(p, 0).number - 20.0) / 160.0;
    const double u_k = std::log(s.value(p, 1).number / 0.0001) / std::log(100.0);
    ASSERT_TRUE(u_v >= 0 && u_v < 1 && u_k >= 0 && u_k < 1);
    v_strata.insert(static_cast<int>(u_v * 16));
    k_strata.insert(static_cast<int>(u_k * 16));
  }
  EXPECT_EQ(v_strata.size(), 16u);
  EXPECT_EQ(k_strata.size(), 16u);
  // the design is a function of its seed
  EXPECT_EQ(sweep_from(dir_, body).canonical_json(), s.canonical_json());
  const SweepDefinition other =
      sweep_from(dir_, body.substr(0, body.find("design_seed")) + "design_seed = 8\n" +
                           body.substr(body.find("[[axis]]")));
  EXPECT_NE(other.value(0, 0).number, s.value(0, 0).number);
}

TEST_F(SweepTest, RandomDesignStaysInsideItsRanges) {
  const SweepDefinition s =
      sweep_from(dir_,
                 "design = \"random\"\nsamples = 50\n[[axis]]\nkey = \"reflex.v_thr_mm_s\"\n"
                 "from = 30.0\nto = 90.0\n");
  ASSERT_EQ(s.points(), 50);
  double lo = 1e9, hi = -1e9;
  for (std::int64_t p = 0; p < 50; ++p) {
    lo = std::min(lo, s.value(p, 0).number);
    hi = std::max(hi, s.value(p, 0).number);
  }
  EXPECT_GE(lo, 30.0);
  EXPECT_LT(hi, 90.0);
  EXPECT_GT(hi - lo, 30.0);  // spread over the range, not one value
}

TEST_F(SweepTest, TheDefinitionIsTheExperimentNotTheFileName) {
  const std::string body = "[[axis]]\nkey = \"reflex.v_thr_mm_s\"\nvalues = [50.0]\n";
  const SweepDefinition a = sweep_from(dir_, body);
  const fs::path other = dir_ / "renamed.toml";
  fs::copy_file(dir_ / "sweep.toml", other);
  EXPECT_EQ(pamsim::load_sweep(other.string()).canonical_json(), a.canonical_json());
  EXPECT_NE(sweep_from(dir_, "seeds = 2\n" + body).canonical_json(), a.canonical_json());
}

// A database written by a pamsim whose summaries held other metrics (an older version, or
// a base scenario whose metric sets changed) is another sweep: resuming it would mix rows.
TEST_F(SweepTest, ResumeRefusesADatabaseWithOtherMetrics) {
  const SweepDefinition s =
      sweep_from(dir_, "[[axis]]\nkey = \"reflex.v_thr_mm_s\"\nvalues = [50.0, 60.0]\n");
  const std::string path = (dir_ / "m.db").string();
  { ResultsDb db = ResultsDb::create(path, s); }
  SweepDefinition older = s;
  older.metric_names.pop_back();
  try {
    ResultsDb::open_to_resume(path, older);
    ADD_FAILURE() << "a database of other metrics was resumed";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("its metrics differs"), std::string::npos) << e.what();
  }
  EXPECT_NO_THROW(ResultsDb::open_to_resume(path, s));
}

TEST_F(SweepTest, DatabaseRefusesDuplicateTrialsAndKeepsTheBatchAtomic) {
  const SweepDefinition s =
      sweep_from(dir_, "seeds = 2\n[[axis]]\nkey = \"reflex.v_thr_mm_s\"\nvalues = [50.0, 60.0]\n");
  const std::string path = (dir_ / "r.db").string();
  ResultsDb db = ResultsDb::create(path, s);
  EXPECT_THROW(ResultsDb::create(path, s), InputError);
  pamsim::TrialRecord a;
  a.trial = 1;
  a.point = 0;
  a.seed_index = 1;
  a.summary.seed = 2;
  a.summary.metrics = {{"peak_drop_deg", 7.5}};
  db.insert(s, {a});
  EXPECT_EQ(db.trial_count(), 1);
  pamsim::TrialRecord b = a;
  b.trial = 2;
  EXPECT_THROW(db.insert(s, {b, a}), std::runtime_error);  // a again: the whole batch rolls back
  EXPECT_EQ(db.trial_count(), 1);
  const std::vector<bool> finished = db.finished_trials(s.trials());
  EXPECT_EQ(finished, (std::vector<bool>{false, true, false, false}));
}

TEST_F(SweepTest, FailedTrialsStoreNoMetricsAndLeftoverWalFilesAreRefused) {
  const SweepDefinition s =
      sweep_from(dir_, "[[axis]]\nkey = \"reflex.v_thr_mm_s\"\nvalues = [50.0]\n");
  const std::string path = (dir_ / "f.db").string();
  {
    ResultsDb db = ResultsDb::create(path, s);
    pamsim::TrialRecord r;
    r.summary.status = "failed";
    r.summary.message = "no model";
    db.insert(s, {r});
    const auto columns = db.trial_columns();
    const auto peak = std::find(columns.begin(), columns.end(), "peak_drop_deg") - columns.begin();
    const auto mistrips = std::find(columns.begin(), columns.end(), "mistrips") - columns.begin();
    int rows = 0;
    db.for_each_trial([&](const std::vector<pamsim::DbValue>& row) {
      EXPECT_EQ(row[peak].kind, pamsim::DbValue::Kind::kNull);
      EXPECT_EQ(row[mistrips].kind, pamsim::DbValue::Kind::kNull);
      ++rows;
    });
    EXPECT_EQ(rows, 1);
  }
  // a WAL without its database (the database deleted after a kill) is not adopted
  const std::string other = (dir_ / "g.db").string();
  write_text(other + "-wal", "stale");
  EXPECT_THROW(ResultsDb::create(other, s), InputError);
  EXPECT_FALSE(fs::exists(other));
}

TEST_F(SweepTest, RunnerRejectsZeroThreads) {
  const SweepDefinition s =
      sweep_from(dir_, "[[axis]]\nkey = \"reflex.v_thr_mm_s\"\nvalues = [50.0]\n");
  ResultsDb db = ResultsDb::create((dir_ / "z.db").string(), s);
  pamsim::SweepRunOptions options;
  options.threads = 0;
  EXPECT_THROW(pamsim::run_sweep(s, db, options), InputError);
}

TEST(SweepShardTest, ShardsPartitionTheTrialsEvenlyWhateverTheCounts) {
  for (std::int64_t count : {1, 2, 3, 7, 64}) {
    for (std::int64_t total : {0, 1, 5, 32, 1000, 1001}) {
      std::vector<int> owners(static_cast<std::size_t>(total), 0);
      std::int64_t smallest = total, largest = 0;
      for (std::int64_t index = 0; index < count; ++index) {
        const pamsim::SweepShard shard{index, count};
        std::int64_t held = 0;
        for (std::int64_t t = 0; t < total; ++t) {
          if (shard.holds(t)) {
            ++owners[static_cast<std::size_t>(t)];
            ++held;
          }
        }
        EXPECT_EQ(shard.trials_of(total), held) << index << "/" << count << " of " << total;
        smallest = std::min(smallest, held);
        largest = std::max(largest, held);
      }
      for (int owner : owners) EXPECT_EQ(owner, 1) << count << " shards of " << total;
      EXPECT_LE(largest - smallest, 1) << count << " shards of " << total;
    }
  }
}

TEST(SweepShardTest, ParsesIOverNAndRefusesEverythingElse) {
  const pamsim::SweepShard s = pamsim::parse_sweep_shard("2/5", "--shard");
  EXPECT_EQ(s.index, 2);
  EXPECT_EQ(s.count, 5);
  EXPECT_EQ(s.text(), "2/5");
  EXPECT_TRUE(pamsim::parse_sweep_shard("0/1", "--shard").whole());
  for (const char* bad : {"", "5/5", "-1/5", "5", "0/0", "x/5", "1/5.0", "+1/5", " 1/5", "1/5/2"}) {
    EXPECT_THROW(pamsim::parse_sweep_shard(bad, "--shard"), InputError) << "'" << bad << "'";
  }
}

TEST(ProgressTest, DurationsReadAsClockTime) {
  EXPECT_EQ(pamsim::format_duration(0), "0:00");
  EXPECT_EQ(pamsim::format_duration(83), "1:23");
  EXPECT_EQ(pamsim::format_duration(3723), "1:02:03");
  EXPECT_EQ(pamsim::format_duration(NAN), "--:--");
}

}  // namespace
