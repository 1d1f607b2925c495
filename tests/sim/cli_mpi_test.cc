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

#include "cli_util.h"
#include "sim/sweep/results_db.h"
#include "sweep_process.h"

namespace {

namespace fs = std::filesystem;
using pamsim_test::fresh_dir;
using pamsim_test::interruptible_sweep;
using pamsim_test::kInterruptibleTrials;
using pamsim_test::line_count;
using pamsim_test::read_file;
using pamsim_test::ReapOnExit;
using pamsim_test::run_pamsim;
using pamsim_test::wait_for_trials;

#ifdef PAMSIM_MPIEXEC
// Open MPI refuses root unless told (CI runs as root); --oversubscribe: 3 ranks on 2 cores.
const std::string kMpirun = std::string("OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 ") +
                            PAMSIM_MPIEXEC + " --oversubscribe -np 3";
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
  EXPECT_EQ(r.out, mpi + "\n");   // rank 0 alone reports
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

// The pid of the pamsim process that is rank `rank` of the job marked with `marker`, or -1.
pid_t rank_pid(const std::string& marker, int rank) {
  for (const auto& entry : fs::directory_iterator("/proc")) {
    const std::string name = entry.path().filename().string();
    if (name.find_first_not_of("0123456789") != std::string::npos) continue;
    const std::string env = read_file(entry.path() / "environ");
    const std::string exe = read_file(entry.path() / "cmdline");
    if (exe.rfind(PAMSIM_BINARY, 0) != 0) continue;
    if (env.find(marker + '\0') == std::string::npos) continue;
    if (env.find("OMPI_COMM_WORLD_RANK=" + std::to_string(rank) + '\0') == std::string::npos) continue;
    return static_cast<pid_t>(std::stol(name));
  }
  return -1;
}

TEST_F(CliMpiTest, AKilledRankEndsTheJobAndResumeFinishesWithoutRepeats) {
  const fs::path dir = fresh_dir("mpi_kill");
  const fs::path sweep = interruptible_sweep(dir);
  const std::string ref = (dir / "ref.db").string(), db = (dir / "killed.db").string();
  ASSERT_EQ(run_pamsim("sweep " + sweep.string() + " --threads 2 --db " + ref).exit_code, 0);
  ASSERT_EQ(run_pamsim("export " + ref + " --csv " + ref + ".csv").exit_code, 0);

  const std::string marker = "PAMSIM_MPI_TEST=" + std::to_string(::getpid());
  const pid_t job = ::fork();
  if (job == 0) {
    const std::string cmd = marker + " " + kMpirun + " " + PAMSIM_BINARY + " sweep " +
                            sweep.string() + " --db " + db + " > " + db + ".log 2>&1";
    ::execl("/bin/sh", "sh", "-c", cmd.c_str(), static_cast<char*>(nullptr));
    ::_exit(127);
  }
  ASSERT_GT(job, 0);
  ReapOnExit reap{job};
  ASSERT_GT(wait_for_trials(db, kInterruptibleTrials / 3, job), 0) << read_file(db + ".log");
  const pid_t worker = rank_pid(marker, 1);
  ASSERT_GT(worker, 0) << "rank 1 not found";
  ASSERT_EQ(::kill(worker, SIGKILL), 0);
  int status = 0;
  ASSERT_EQ(::waitpid(job, &status, 0), job);
  reap.release();
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) != 0) << read_file(db + ".log");
  EXPECT_NE(read_file(db + ".log").find("rank 1"), std::string::npos)   // mpirun names it
      << read_file(db + ".log");
  const std::int64_t kept = pamsim::ResultsDb::open_existing(db).trial_count();
  EXPECT_GE(kept, kInterruptibleTrials / 3);
  EXPECT_LT(kept, kInterruptibleTrials) << "killed too late to test a resume";

  const auto resumed = run_pamsim("sweep " + sweep.string() + " --resume --db " + db, kMpirun);
  ASSERT_EQ(resumed.exit_code, 0) << resumed.err;
  EXPECT_NE(resumed.err.find(std::to_string(kInterruptibleTrials - kept) + " trials run"),
            std::string::npos) << resumed.err;
  ASSERT_EQ(run_pamsim("export " + db + " --csv " + db + ".csv").exit_code, 0);
  EXPECT_EQ(read_file(db + ".csv"), read_file(ref + ".csv"));
}

#endif  // PAMSIM_MPIEXEC

}  // namespace
