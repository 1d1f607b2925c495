// cli_mpi_test.cc: `mpirun -np 3 pamsim sweep` in a build with -DPAMSIM_MPI=ON, as a cluster
// user runs it: the same export as one process; a refused sweep ends every rank with one
// line; a worker rank killed midway ends the job, keeps what was committed, and --resume
// under mpirun finishes without repeating a trial. Skipped in a build without MPI.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>

#include "sim/cli_util.h"
#include "sim/sweep/results_db.h"
#include "sim/sweep_process.h"

namespace {

namespace fs = std::filesystem;
using pamsim_test::fresh_dir;
using pamsim_test::interruptible_sweep;
using pamsim_test::line_count;
using pamsim_test::read_file;
using pamsim_test::ReapOnExit;
using pamsim_test::run_pamsim;
using pamsim_test::wait_for_trials;

#ifdef PAMSIM_MPIEXEC
// Open MPI refuses root unless told (CI runs as root); --oversubscribe: 3 ranks on 2 cores.
const std::string kMpiEnv = "OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 ";
const std::string kMpiLaunch = std::string(PAMSIM_MPIEXEC) + " --oversubscribe -np 3";
const std::string kMpirun = kMpiEnv + kMpiLaunch;
#endif

class CliMpiTest : public ::testing::Test {
 protected:
  void SetUp() override {
#ifndef PAMSIM_MPIEXEC
    GTEST_SKIP() << "built without MPI (-DPAMSIM_MPI=ON)";
#endif
  }
};

#ifdef PAMSIM_MPIEXEC

TEST_F(CliMpiTest, ThreeRanksExportExactlyWhatOneProcessExports) {
  const fs::path dir = fresh_dir("mpi_smoke");
  const std::string one = (dir / "one.db").string(), mpi = (dir / "mpi.db").string();
  ASSERT_EQ(run_pamsim("sweep scenarios/sweep_smoke.toml --threads 2 --db " + one).exit_code, 0);
  const auto r = run_pamsim("sweep scenarios/sweep_smoke.toml --db " + mpi, kMpirun);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("on 2 MPI worker ranks"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("32 trials run"), std::string::npos) << r.err;
  EXPECT_EQ(r.out, mpi + "\n");  // rank 0 alone reports
  for (const std::string& db : {one, mpi}) {
    ASSERT_EQ(run_pamsim("export " + db + " --csv " + db + ".csv").exit_code, 0);
  }
  EXPECT_EQ(read_file(mpi + ".csv"), read_file(one + ".csv"));

  // a shard under MPI: the shard's trials only, the same as the single-process shard
  const std::string shard = (dir / "shard.db").string();
  const auto s = run_pamsim("sweep scenarios/sweep_smoke.toml --shard 1/3 --db " + shard, kMpirun);
  ASSERT_EQ(s.exit_code, 0) << s.err;
  EXPECT_EQ(pamsim::ResultsDb::open_existing(shard).trial_count(), 11);
}

TEST_F(CliMpiTest, ARefusedSweepEndsEveryRankWithOneLine) {
  const fs::path dir = fresh_dir("mpi_refused");
  const std::string db = (dir / "a.db").string();
  std::ofstream(db) << "not a database";
  const auto r = run_pamsim("sweep scenarios/sweep_smoke.toml --db " + db, kMpirun);
  EXPECT_NE(r.exit_code, 0);
  // one line from pamsim (mpirun adds its own note about the exit code)
  std::size_t lines = 0;
  for (std::size_t at = r.err.find("pamsim: "); at != std::string::npos;
       at = r.err.find("pamsim: ", at + 1)) {
    ++lines;
  }
  EXPECT_EQ(lines, 1u) << r.err;
  EXPECT_NE(r.err.find(db + ": already exists"), std::string::npos) << r.err;
  EXPECT_EQ(read_file(db), "not a database");
}

// Ranks that cannot read the sweep file (started in another folder, the file named relative
// to the source folder) say so through rank 0, which ends the job instead of waiting for them:
// with one such rank the other runs every trial; with none left, one line and exit 1.
TEST_F(CliMpiTest, RanksThatCannotReadTheSweepAreReportedAndTheJobEnds) {
  const fs::path dir = fresh_dir("mpi_unreadable");
  const std::string elsewhere = dir.string();
  for (const char* lost : {"2", "1|2"}) {
    const std::string db =
        (dir / (std::string(lost) == "2" ? "one_lost.db" : "all_lost.db")).string();
    // every rank starts in the source folder; the lost ones move away before running pamsim
    const std::string rank_cmd = std::string("sh -c 'case $OMPI_COMM_WORLD_RANK in ") + lost +
                                 ") cd " + elsewhere + ";; esac; exec " + PAMSIM_BINARY +
                                 " sweep scenarios/sweep_smoke.toml --threads 1 --db " + db + "'";
    const std::string cmd = std::string("cd ") + PAMSIM_SOURCE_DIR + " && " + kMpiEnv +
                            "timeout 120 " + kMpiLaunch + " " + rank_cmd + " > " + db + ".out 2> " +
                            db + ".err";
    const int status = std::system(cmd.c_str());
    const int code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    const std::string err = read_file(db + ".err");
    EXPECT_NE(code, 124) << lost << ": the job hung\n" << err;
    EXPECT_NE(err.find("rank 2 runs no trials: scenarios/sweep_smoke.toml"), std::string::npos)
        << err;
    if (std::string(lost) == "2") {
      EXPECT_EQ(code, 0) << err;
      EXPECT_EQ(pamsim::ResultsDb::open_existing(db).trial_count(), 32);
    } else {
      EXPECT_EQ(code, 1) << err;
      EXPECT_NE(err.find("pamsim: error: 2 of 2 worker ranks ran no trials (rank "),
                std::string::npos)
          << err;
      EXPECT_NE(err.find("0 of 32 trials stored; finish with: pamsim sweep "), std::string::npos)
          << err;
    }
  }
}

// The pid of the pamsim process that is rank `rank` of the job marked with `marker`, or -1.
pid_t rank_pid(const std::string& marker, int rank) {
  for (const auto& entry : fs::directory_iterator("/proc")) {
    const std::string name = entry.path().filename().string();
    if (name.find_first_not_of("0123456789") != std::string::npos) continue;
    const std::string env = read_file(entry.path() / "environ");
    const std::string exe = read_file(entry.path() / "cmdline");
    if (exe.rfind(PAMSIM_BINARY, 0) != 0) continue;
    if (env.find(marker + '\0') == std::string::npos) continue;
    if (env.find("OMPI_COMM_WORLD_RANK=" + std::to_string(rank) + '\0') == std::string::npos)
      continue;
    return static_cast<pid_t>(std::stol(name));
  }
  return -1;
}

TEST_F(CliMpiTest, AKilledRankEndsTheJobAndResumeFinishesWithoutRepeats) {
  const fs::path dir = fresh_dir("mpi_kill");
  const fs::path sweep = interruptible_sweep(dir, 30);  // 360 trials, one thread per worker
  const std::int64_t total = 3 * 4 * 30;
  const std::string ref = (dir / "ref.db").string(), db = (dir / "killed.db").string();
  ASSERT_EQ(run_pamsim("sweep " + sweep.string() + " --threads 2 --db " + ref).exit_code, 0);
  ASSERT_EQ(run_pamsim("export " + ref + " --csv " + ref + ".csv").exit_code, 0);

  const std::string marker = "PAMSIM_MPI_TEST=" + std::to_string(::getpid());
  const pid_t job = ::fork();
  if (job == 0) {
    const std::string cmd = marker + " " + kMpirun + " " + PAMSIM_BINARY + " sweep " +
                            sweep.string() + " --threads 1 --db " + db + " > " + db + ".log 2>&1";
    ::execl("/bin/sh", "sh", "-c", cmd.c_str(), static_cast<char*>(nullptr));
    ::_exit(127);
  }
  ASSERT_GT(job, 0);
  ReapOnExit reap{job};
  ASSERT_GT(wait_for_trials(db, total / 6, job), 0) << read_file(db + ".log");
  const pid_t worker = rank_pid(marker, 1);
  ASSERT_GT(worker, 0) << "rank 1 not found";
  ASSERT_EQ(::kill(worker, SIGKILL), 0);
  int status = 0;
  ASSERT_EQ(::waitpid(job, &status, 0), job);
  reap.release();
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) != 0) << read_file(db + ".log");
  EXPECT_NE(read_file(db + ".log").find("rank 1"), std::string::npos)  // mpirun names it
      << read_file(db + ".log");
  const std::int64_t kept = pamsim::ResultsDb::open_existing(db).trial_count();
  EXPECT_GE(kept, total / 6);
  EXPECT_LT(kept, total);  // what rank 1 held is lost for this run

  const auto resumed = run_pamsim("sweep " + sweep.string() + " --resume --db " + db, kMpirun);
  ASSERT_EQ(resumed.exit_code, 0) << resumed.err;
  EXPECT_NE(resumed.err.find(std::to_string(total - kept) + " trials run"), std::string::npos)
      << resumed.err;
  ASSERT_EQ(run_pamsim("export " + db + " --csv " + db + ".csv").exit_code, 0);
  EXPECT_EQ(read_file(db + ".csv"), read_file(ref + ".csv"));
}

#endif  // PAMSIM_MPIEXEC

}  // namespace
