// cli_merge_test.cc: a sweep run in shards (`pamsim sweep --shard I/N`) and merged (`pamsim
// merge`) as a cluster user would: three shards merged export exactly what one machine
// exports; a shard killed midway finishes with --resume without repeating a trial; merge
// reports duplicates and missing trials and refuses parts that do not belong together; every
// malformed --shard gets one line and exit 2; the Slurm scripts under scripts/slurm work.
#include <fcntl.h>
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <sqlite3.h>
#include <sys/file.h>
#include <unistd.h>

#include <filesystem>
#include <set>
#include <string>
#include <vector>

#include "sim/cli_util.h"
#include "sim/sweep/results_db.h"
#include "sim/sweep_process.h"

namespace {

namespace fs = std::filesystem;
using pamsim_test::freeze;
using pamsim_test::fresh_dir;
using pamsim_test::interruptible_sweep;
using pamsim_test::kInterruptibleTrials;
using pamsim_test::line_count;
using pamsim_test::lines_of;
using pamsim_test::read_file;
using pamsim_test::ReapOnExit;
using pamsim_test::run_pamsim;
using pamsim_test::spawn_sweep;
using pamsim_test::wait_for_trials;
using pamsim_test::write_text;

const std::string kSmoke = "scenarios/sweep_smoke.toml";

// The trial numbers stored in `db`, in order.
std::vector<std::int64_t> trials_in(const std::string& db) {
  std::vector<std::int64_t> trials;
  pamsim::ResultsDb::open_existing(db).for_each_trial([&](const std::vector<pamsim::DbValue>& row) {
    trials.push_back(static_cast<std::int64_t>(row[0].number));
  });
  return trials;
}

// `path`, with whatever an earlier run of the test left there removed (and its -wal, -shm).
std::string fresh_file(const std::string& path) {
  for (const char* suffix : {"", "-wal", "-shm", ".csv"}) fs::remove(path + suffix);
  return path;
}

// Runs `sql` on the database file `db` (to make a part that does not belong).
void execute_sql(const std::string& db, const std::string& sql) {
  sqlite3* handle = nullptr;
  ASSERT_EQ(sqlite3_open(db.c_str(), &handle), SQLITE_OK);
  char* err = nullptr;
  const int rc = sqlite3_exec(handle, sql.c_str(), nullptr, nullptr, &err);
  const std::string why = err ? err : "";
  sqlite3_free(err);
  sqlite3_close(handle);
  ASSERT_EQ(rc, SQLITE_OK) << why;
}

// The smoke sweep on one machine and as three shards (each shard's database in `dir`),
// made once for all the tests of one CTest run: CTest runs each test in its own process, so
// the first to come makes them under a lock and the others, children of the same CTest and
// of the same pamsim binary, find them made (each test then writes only files of its own).
class ShardedSmokeSweep : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    const auto built = fs::last_write_time(PAMSIM_BINARY).time_since_epoch().count();
    dir_ =
        new fs::path(fs::path(::testing::TempDir()) /
                     ("sweep_shards_" + std::to_string(::getppid()) + "_" + std::to_string(built)));
    fs::create_directories(*dir_);
    const int lock = ::open((*dir_ / ".lock").c_str(), O_CREAT | O_RDWR | O_CLOEXEC, 0644);
    ASSERT_GE(lock, 0);
    ASSERT_EQ(::flock(lock, LOCK_EX), 0);
    if (!fs::exists(*dir_ / ".made")) make_sweeps();
    ::close(lock);  // (releases the lock)
  }
  static void make_sweeps() {
    const auto whole = run_pamsim("sweep " + kSmoke + " --threads 2 --db " + db("whole"));
    ASSERT_EQ(whole.exit_code, 0) << whole.err;
    ASSERT_EQ(run_pamsim("export " + db("whole") + " --csv " + db("whole") + ".csv").exit_code, 0);
    for (int i = 0; i < 3; ++i) {
      const auto r = run_pamsim("sweep " + kSmoke + " --threads 2 --shard " + std::to_string(i) +
                                "/3 --out " + dir_->string());
      ASSERT_EQ(r.exit_code, 0) << r.err;
    }
    write_text(*dir_ / ".made", "");
  }
  static void TearDownTestSuite() { delete dir_; }
  static std::string db(const std::string& name) { return (*dir_ / (name + ".db")).string(); }
  static std::string shard(int i) {
    return (*dir_ / ("sweep.shard-" + std::to_string(i) + "-of-3.db")).string();
  }
  static fs::path* dir_;
};
fs::path* ShardedSmokeSweep::dir_ = nullptr;

TEST_F(ShardedSmokeSweep, EachShardHoldsExactlyItsTrials) {
  std::vector<int> seen(32, 0);
  for (int i = 0; i < 3; ++i) {
    const std::vector<std::int64_t> trials = trials_in(shard(i));
    EXPECT_EQ(trials.size(), i < 2 ? 11u : 10u) << "shard " << i;  // 32 = 11 + 11 + 10
    for (std::int64_t t : trials) {
      EXPECT_EQ(t % 3, i) << "trial " << t << " in shard " << i;
      ++seen[static_cast<std::size_t>(t)];
    }
    EXPECT_EQ(pamsim::ResultsDb::open_existing(shard(i)).meta("shard"), std::to_string(i) + "/3");
  }
  for (int t = 0; t < 32; ++t) EXPECT_EQ(seen[t], 1) << "trial " << t;
}

TEST_F(ShardedSmokeSweep, MergedShardsExportExactlyWhatOneMachineExports) {
  const std::string merged = fresh_file(db("merged"));
  const auto r = run_pamsim("merge " + merged + " " + shard(2) + " " + shard(0) + " " + shard(1));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.out, merged + "\n");
  EXPECT_NE(r.err.find("32 trials into " + merged + " (of 32)"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("missing"), std::string::npos) << r.err;
  ASSERT_EQ(run_pamsim("export " + merged + " --csv " + merged + ".csv").exit_code, 0);
  EXPECT_EQ(read_file(merged + ".csv"), read_file(db("whole") + ".csv"));
  // a merged database is a whole sweep: resuming it runs nothing, and it names its parts
  const auto resumed = run_pamsim("sweep " + kSmoke + " --resume --db " + merged);
  EXPECT_EQ(resumed.exit_code, 0) << resumed.err;
  EXPECT_NE(resumed.err.find("0 trials run"), std::string::npos) << resumed.err;
  const pamsim::ResultsDb m = pamsim::ResultsDb::open_existing(merged);
  EXPECT_EQ(m.meta("shard"), "");
  EXPECT_NE(m.meta("merged_from").find("sweep.shard-2-of-3.db"), std::string::npos);
  // every shard's run is recorded with its build, not only the first part's (and the
  // resume above, which ran nothing, after them)
  const nlohmann::json runs = nlohmann::json::parse(m.meta("invocations"));
  std::set<std::string> parts;
  for (const auto& run : runs) {
    if (run.contains("part")) parts.insert(run.at("part").get<std::string>());
  }
  EXPECT_EQ(parts, (std::set<std::string>{shard(0), shard(1), shard(2)}));
  ASSERT_EQ(runs.size(), 4u);
  EXPECT_EQ(runs.back().at("trials_run"), 0);
  EXPECT_FALSE(m.meta("git_commit").empty());
  // merging never overwrites
  const std::string before = read_file(merged);
  const auto again = run_pamsim("merge " + merged + " " + shard(0));
  EXPECT_EQ(again.exit_code, 2);
  EXPECT_EQ(line_count(again.err), 1) << again.err;
  EXPECT_NE(again.err.find("already exists"), std::string::npos) << again.err;
  EXPECT_EQ(read_file(merged), before);
}

TEST_F(ShardedSmokeSweep, DuplicatesAreKeptOnceAndMissingTrialsReportedThenResumed) {
  const std::string partial = fresh_file(db("partial"));
  const auto r = run_pamsim("merge " + partial + " " + shard(0) + " " + shard(1) + " " + shard(0));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("22 trials into " + partial + " (of 32)"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("11 trials were in more than one part"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("10 trials are missing (in no part), first: 2 5 8 11"), std::string::npos)
      << r.err;
  EXPECT_NE(r.err.find("--db " + partial + " --resume"), std::string::npos) << r.err;
  // the resume the message suggests runs exactly the missing shard's trials
  const auto resumed = run_pamsim("sweep " + kSmoke + " --threads 2 --resume --db " + partial);
  ASSERT_EQ(resumed.exit_code, 0) << resumed.err;
  EXPECT_NE(resumed.err.find("10 trials run"), std::string::npos) << resumed.err;
  ASSERT_EQ(run_pamsim("export " + partial + " --csv " + partial + ".csv").exit_code, 0);
  EXPECT_EQ(read_file(partial + ".csv"), read_file(db("whole") + ".csv"));
}

TEST_F(ShardedSmokeSweep, MergeRefusesPartsThatDoNotBelongTogether) {
  struct Case {
    const char* name;
    const char* sql;  // what makes a copy of shard 1 not belong
    const char* message;
  };
  const Case cases[] = {
      {"version", "UPDATE meta SET value = '0.0.1' WHERE key = 'pamsim_version'",
       "was made by pamsim 0.0.1"},
      {"definition", "UPDATE meta SET value = '{}' WHERE key = 'definition'",
       "holds another sweep definition"},
      {"outside", "UPDATE trials SET trial = 32 WHERE trial = 31", "holds trial 32, outside"},
      {"differs", "UPDATE trials SET peak_drop_deg = peak_drop_deg + 1 WHERE trial = 1",
       "trial 1 differs from the same trial in an earlier part"},
      {"format", "UPDATE meta SET value = 'x' WHERE key = 'format'", "not a pamsim sweep database"},
  };
  for (const Case& c : cases) {
    const std::string part = fresh_file(db(std::string("bad_") + c.name));
    fs::copy_file(shard(1), part);
    ASSERT_NO_FATAL_FAILURE(execute_sql(part, c.sql));
    const std::string out = fresh_file(db(std::string("out_") + c.name));
    // "differs" needs the true trial 1 first
    const std::string parts =
        std::string(c.name) == "differs" ? shard(1) + " " + part : shard(0) + " " + part;
    const auto r = run_pamsim("merge " + out + " " + parts);
    EXPECT_EQ(r.exit_code, 2) << c.name << ": " << r.err;
    EXPECT_EQ(line_count(r.err), 1) << c.name << ": " << r.err;
    EXPECT_NE(r.err.find(part + ": "), std::string::npos) << c.name << ": " << r.err;
    EXPECT_NE(r.err.find(c.message), std::string::npos) << c.name << ": " << r.err;
    EXPECT_FALSE(fs::exists(out)) << c.name;
  }
  const auto missing = run_pamsim("merge " + db("out_missing") + " " + db("absent"));
  EXPECT_EQ(missing.exit_code, 2);
  EXPECT_NE(missing.err.find(db("absent") + ": no such sweep database"), std::string::npos)
      << missing.err;
  const auto itself = run_pamsim("merge " + shard(0) + " " + shard(0));
  EXPECT_EQ(itself.exit_code, 2);
  EXPECT_NE(itself.err.find("is the output too"), std::string::npos) << itself.err;
}

TEST_F(ShardedSmokeSweep, AShardDatabaseResumesOnlyAsThatShard) {
  const std::string copy = fresh_file(db("shard1_copy"));
  fs::copy_file(shard(1), copy);
  for (const std::string& wrong :
       {std::string(""), std::string(" --shard 2/3"), std::string(" --shard 1/4")}) {
    const auto r = run_pamsim("sweep " + kSmoke + " --resume --db " + copy + wrong);
    EXPECT_EQ(r.exit_code, 2) << wrong << ": " << r.err;
    EXPECT_EQ(line_count(r.err), 1) << r.err;
    EXPECT_NE(r.err.find("holds shard 1/3"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("--shard 1/3"), std::string::npos) << r.err;
  }
  const auto whole =
      run_pamsim("sweep " + kSmoke + " --resume --db " + db("whole") + " --shard 0/3");
  EXPECT_EQ(whole.exit_code, 2);
  EXPECT_NE(whole.err.find("holds the whole sweep, not shard 0/3"), std::string::npos) << whole.err;
}

// The Slurm scripts as Slurm runs them: each array task with its SLURM_* variables, then the
// merge job.
TEST_F(ShardedSmokeSweep, SlurmScriptsRunTheShardsAndMergeThem) {
  const fs::path out = *dir_ / "slurm";
  fs::remove_all(out);
  const std::string in_source =
      std::string("cd ") + PAMSIM_SOURCE_DIR + " && PAMSIM=" + PAMSIM_BINARY + " ";
  for (int i = 0; i < 3; ++i) {
    const std::string task = in_source + "SLURM_ARRAY_TASK_ID=" + std::to_string(i) +
                             " SLURM_ARRAY_TASK_COUNT=3 SLURM_ARRAY_TASK_MIN=0 "
                             "SLURM_CPUS_PER_TASK=2 bash scripts/slurm/shard.sbatch " +
                             kSmoke + " " + out.string() + " 3 > /dev/null 2>&1";
    ASSERT_EQ(std::system(task.c_str()), 0) << task;
  }
  // shard 1 resubmitted alone (--array=1): it resumes its finished database, runs nothing
  const std::string again = in_source +
                            "SLURM_ARRAY_TASK_ID=1 SLURM_ARRAY_TASK_COUNT=1 "
                            "SLURM_ARRAY_TASK_MIN=1 bash scripts/slurm/shard.sbatch " +
                            kSmoke + " " + out.string() + " 3 2>&1 | grep -q '0 trials run'";
  EXPECT_EQ(std::system(again.c_str()), 0) << again;
  // a task that is not a shard (an array past SHARDS-1) is refused
  const std::string past = in_source + "SLURM_ARRAY_TASK_ID=3 bash scripts/slurm/shard.sbatch " +
                           kSmoke + " " + out.string() + " 3 > /dev/null 2>&1";
  EXPECT_NE(std::system(past.c_str()), 0);
  const std::string merge =
      in_source + "bash scripts/slurm/merge.sbatch " + out.string() + " 3 > /dev/null 2>&1";
  ASSERT_EQ(std::system(merge.c_str()), 0);
  const std::string merged = (out / "sweep.db").string();
  ASSERT_EQ(run_pamsim("export " + merged + " --csv " + merged + ".csv").exit_code, 0);
  EXPECT_EQ(read_file(merged + ".csv"), read_file(db("whole") + ".csv"));
}

TEST(CliShardTest, MalformedShardsAreRefusedWithOneLine) {
  const fs::path dir = fresh_dir("sweep_bad_shard");
  for (const char* shard : {"3/3", "-1/3", "1", "0/0", "a/2", "1/b", "1/2x", "/2", "1/", "0/-2",
                            "1 /2", "99999999999999999999/3"}) {
    const auto r =
        run_pamsim("sweep " + kSmoke + " --out " + dir.string() + " --shard '" + shard + "'");
    EXPECT_EQ(r.exit_code, 2) << shard << ": " << r.err;
    EXPECT_EQ(line_count(r.err), 1) << shard << ": " << r.err;
    EXPECT_NE(r.err.find("--shard must be I/N with 0 <= I < N, got '" + std::string(shard) + "'"),
              std::string::npos)
        << r.err;
  }
  EXPECT_TRUE(fs::is_empty(dir));
}

TEST(CliShardTest, AShardKilledMidwayFinishesWithResumeWithoutRepeats) {
  const fs::path dir = fresh_dir("shard_kill");
  const fs::path sweep = interruptible_sweep(dir);
  const std::int64_t shard_trials = kInterruptibleTrials / 2;  // shard 1/2: the odd trials
  const std::string db = (dir / "shard1.db").string();
  const pid_t pid = spawn_sweep(sweep, db, {"--shard", "1/2"});
  ASSERT_GT(pid, 0);
  ReapOnExit reap{pid};
  ASSERT_GT(wait_for_trials(db, shard_trials / 2, pid), 0) << "the shard ended too early";
  ASSERT_NO_FATAL_FAILURE(freeze(pid));
  ASSERT_LT(pamsim::ResultsDb::open_existing(db).trial_count(), shard_trials) << "too late";
  ASSERT_EQ(::kill(pid, SIGKILL), 0);
  ASSERT_EQ(::waitpid(pid, nullptr, 0), pid);
  reap.release();

  const auto resumed = run_pamsim("sweep " + sweep.string() +
                                  " --threads 2 --resume --shard 1/2 "
                                  "--db " +
                                  db);
  ASSERT_EQ(resumed.exit_code, 0) << resumed.err;
  const std::vector<std::int64_t> trials = trials_in(db);
  ASSERT_EQ(trials.size(), static_cast<std::size_t>(shard_trials));
  for (std::size_t k = 0; k < trials.size(); ++k) EXPECT_EQ(trials[k], 2 * k + 1);

  // with the other shard, merged: the uninterrupted sweep
  const std::string other = (dir / "shard0.db").string();
  ASSERT_EQ(run_pamsim("sweep " + sweep.string() + " --shard 0/2 --db " + other).exit_code, 0);
  const std::string merged = (dir / "merged.db").string();
  const auto m = run_pamsim("merge " + merged + " " + other + " " + db);
  ASSERT_EQ(m.exit_code, 0) << m.err;
  EXPECT_EQ(m.err.find("more than one part"), std::string::npos) << m.err;
  const std::string ref = (dir / "ref.db").string();
  ASSERT_EQ(run_pamsim("sweep " + sweep.string() + " --threads 2 --db " + ref).exit_code, 0);
  ASSERT_EQ(run_pamsim("export " + ref + " --csv " + ref + ".csv").exit_code, 0);
  ASSERT_EQ(run_pamsim("export " + merged + " --csv " + merged + ".csv").exit_code, 0);
  EXPECT_EQ(read_file(merged + ".csv"), read_file(ref + ".csv"));
  EXPECT_EQ(lines_of(read_file(merged + ".csv")).size(), 1u + kInterruptibleTrials);
}

}  // namespace
