// sweep_process.h: helpers for tests that run `pamsim sweep` as a user would: short sweep
// files on the drop-mass scenario, a sweep in the background that a test can wait for, stop
// (SIGSTOP), kill and reap, and the lines of an exported CSV.
#pragma once

#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "cli_util.h"
#include "sim/sweep/results_db.h"
#include "sim/test_paths.h"

namespace pamsim_test {

namespace fs = std::filesystem;

// A sweep file on the drop-mass scenario with short trials and the given extra text.
inline std::string short_sweep(const std::string& body) {
  return "base = \"" + kDropMass + "\"\n" + body +
         "\n[fixed.sim]\nduration_s = 0.8\n[fixed.drop]\ntime_s = 0.2\n";
}

inline std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::stringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

// Waits until `db` holds at least `n` trials (or the process has exited); returns the count.
inline std::int64_t wait_for_trials(const std::string& db, std::int64_t n, pid_t pid) {
  for (int i = 0; i < 20000; ++i) {
    if (fs::exists(db)) {
      try {
        const std::int64_t stored = pamsim::ResultsDb::open_existing(db).trial_count();
        if (stored >= n) return stored;
      } catch (const std::exception&) {  // mid-creation: try again
      }
    }
    if (::waitpid(pid, nullptr, WNOHANG) == pid) return -1;
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  return -1;
}

// Kills and reaps the sweep at the end of a test that failed before it did (an ASSERT in the
// middle would otherwise leave it stopped for good); release() once the test reaped it.
struct ReapOnExit {
  pid_t pid;
  ~ReapOnExit() {
    if (pid <= 0) return;
    ::kill(pid, SIGKILL);
    ::waitpid(pid, nullptr, 0);
  }
  void release() { pid = -1; }
};

// Stops `pid` with SIGSTOP and waits until it is stopped: what it has stored stays as it is
// while the test looks (no race with a sweep that goes on, or ends, meanwhile).
inline void freeze(pid_t pid) {
  ASSERT_EQ(::kill(pid, SIGSTOP), 0);
  int status = 0;
  ASSERT_EQ(::waitpid(pid, &status, WUNTRACED), pid);
  ASSERT_TRUE(WIFSTOPPED(status)) << "the sweep ended before it could be stopped";
}

// `pamsim sweep SWEEP --threads 2 --db DB` in the background, output discarded; its pid.
// `extra` arguments follow.
inline pid_t spawn_sweep(const fs::path& sweep, const std::string& db,
                         const std::vector<std::string>& extra = {}) {
  std::vector<std::string> args = {PAMSIM_BINARY, "sweep", sweep.string(), "--threads", "2",
                                   "--db",        db};
  args.insert(args.end(), extra.begin(), extra.end());
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  const pid_t pid = ::fork();
  if (pid == 0) {
    if (!::freopen("/dev/null", "w", stderr) || !::freopen("/dev/null", "w", stdout)) ::_exit(126);
    ::execv(PAMSIM_BINARY, argv.data());
    ::_exit(127);
  }
  return pid;
}

// 3 x 4 x `seeds` short trials (120 by default): long enough to stop in the middle
inline fs::path interruptible_sweep(const fs::path& dir, int seeds = 10) {
  const fs::path sweep = dir / "sweep.toml";
  write_text(sweep, short_sweep("seeds = " + std::to_string(seeds) +
                                "\n[[axis]]\nkey = \"reflex.v_thr_mm_s\"\n"
                                "values = [40.0, 70.0, 100.0]\n[[axis]]\n"
                                "key = \"reflex.k_MPa_s_per_mm\"\nfrom = 0.0005\nto = 0.004\n"
                                "count = 4\nscale = \"log\"\n"));
  return sweep;
}
constexpr int kInterruptibleTrials = 3 * 4 * 10;

}  // namespace pamsim_test
