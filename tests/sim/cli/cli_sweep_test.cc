// cli_sweep_test.cc: `pamsim sweep`, `export` and `report` as a user runs them: the same
// export on 1 and 2 threads; a sweep killed with SIGKILL and resumed exports exactly what an
// uninterrupted one does; a diverging trial is stored and the sweep goes on; bad sweep files
// give one line, a non-zero exit and no database (cli_sweep_bad_input_test.cc); the best
// setting runs as a scenario.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <set>
#include <string>
#include <thread>
#include <vector>

#include "sim/cli_util.h"
#include "sim/sweep_process.h"
#include "sim/sweep/results_db.h"
#include "sim/sweep/sweep.h"

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
using pamsim_test::short_sweep;
using pamsim_test::spawn_sweep;
using pamsim_test::wait_for_trials;
using pamsim_test::write_text;

TEST(CliSweepTest, SmokeSweepExportsTheSameCsvOnOneAndTwoThreads) {
  const fs::path dir = fresh_dir("sweep_threads");
  for (int threads : {1, 2}) {
    const std::string db = (dir / ("t" + std::to_string(threads) + ".db")).string();
    const auto r = run_pamsim("sweep scenarios/sweep_smoke.toml --threads " +
                              std::to_string(threads) + " --db " + db);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const auto e = run_pamsim("export " + db + " --csv " + db + ".csv");
    ASSERT_EQ(e.exit_code, 0) << e.err;
  }
  const std::string one = read_file(dir / "t1.db.csv");
  const std::string two = read_file(dir / "t2.db.csv");
  EXPECT_EQ(one, two);
  // "-" is standard output, the same bytes; a FIFO is written through and stays a FIFO
  const auto piped = run_pamsim("export " + (dir / "t1.db").string() + " --csv -");
  ASSERT_EQ(piped.exit_code, 0) << piped.err;
  EXPECT_EQ(piped.out, one);
  const fs::path fifo = dir / "fifo";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  const std::string reader = "cat " + fifo.string() + " > " + (dir / "from_fifo").string() + " & " +
                             PAMSIM_BINARY + " export " + (dir / "t1.db").string() + " --csv " +
                             fifo.string() + " 2> /dev/null; status=$?; wait; exit $status";
  EXPECT_EQ(std::system(reader.c_str()), 0);
  EXPECT_EQ(read_file(dir / "from_fifo"), one);
  EXPECT_TRUE(fs::is_fifo(fifo)) << "the FIFO was replaced by a file";

  // 4 x 4 points x 2 seeds, in trial order, every metric present, all ok
  const auto lines = lines_of(one);
  ASSERT_EQ(lines.size(), 1u + 32u);
  EXPECT_EQ(lines[0].rfind("trial,point,seed_index,seed,reflex.v_thr_mm_s,reflex.k_MPa_s_per_mm,"
                           "status,message,",
                           0),
            0u)
      << lines[0];
  for (const char* metric : {"peak_drop_deg", "mistrips", "recovery_time_s", "impact_time_s"}) {
    EXPECT_NE(lines[0].find(metric), std::string::npos) << metric;
  }
  EXPECT_EQ(lines[0].find("wall_time_s"), std::string::npos) << "timing is not exported by default";
  for (std::size_t t = 0; t < 32; ++t) {
    EXPECT_EQ(lines[t + 1].rfind(std::to_string(t) + ",", 0), 0u) << lines[t + 1];
    EXPECT_NE(lines[t + 1].find(",ok,"), std::string::npos) << lines[t + 1];
  }
}

TEST(CliSweepTest, SweepKilledHalfwayAndResumedEqualsTheUninterruptedOne) {
  const fs::path dir = fresh_dir("sweep_kill");
  const fs::path sweep = interruptible_sweep(dir);
  const int total = kInterruptibleTrials;

  // the reference, uninterrupted
  const std::string ref_db = (dir / "ref.db").string();
  ASSERT_EQ(run_pamsim("sweep " + sweep.string() + " --threads 2 --db " + ref_db).exit_code, 0);
  ASSERT_EQ(run_pamsim("export " + ref_db + " --csv " + ref_db + ".csv").exit_code, 0);

  // the same sweep, killed with SIGKILL once about half the trials are stored
  const std::string db = (dir / "killed.db").string();
  const pid_t pid = spawn_sweep(sweep, db);
  ASSERT_GT(pid, 0);
  ReapOnExit reap{pid};
  ASSERT_GT(wait_for_trials(db, total / 2, pid), 0) << "the sweep ended before half its trials";
  ASSERT_NO_FATAL_FAILURE(freeze(pid));
  const std::int64_t seen = pamsim::ResultsDb::open_existing(db).trial_count();
  ASSERT_LT(seen, total) << "stopped too late to test a resume";
  ASSERT_EQ(::kill(pid, SIGKILL), 0);
  int status = 0;
  ASSERT_EQ(::waitpid(pid, &status, 0), pid);
  reap.release();
  ASSERT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == SIGKILL);
  // every trial committed is there (one more if it was stopped inside a commit: the WAL
  // holds it before the index shows it, and recovery finds it); none is lost
  const std::int64_t after_kill = pamsim::ResultsDb::open_existing(db).trial_count();
  EXPECT_GE(after_kill, seen);
  EXPECT_LT(after_kill, total);

  // without --resume the database is refused; with it the rest runs
  const auto refused = run_pamsim("sweep " + sweep.string() + " --db " + db);
  EXPECT_EQ(refused.exit_code, 2);
  EXPECT_NE(refused.err.find("--resume"), std::string::npos) << refused.err;
  const auto resumed = run_pamsim("sweep " + sweep.string() + " --threads 2 --resume --db " + db);
  ASSERT_EQ(resumed.exit_code, 0) << resumed.err;
  ASSERT_EQ(run_pamsim("export " + db + " --csv " + db + ".csv").exit_code, 0);
  EXPECT_EQ(read_file(db + ".csv"), read_file(ref_db + ".csv"));
  EXPECT_EQ(lines_of(read_file(db + ".csv")).size(), 1u + total);
}

TEST(CliSweepTest, SigintStopsCleanlyWithExit130AndResumeFinishes) {
  const fs::path dir = fresh_dir("sweep_sigint");
  const fs::path sweep = interruptible_sweep(dir);
  const std::string db = (dir / "s.db").string();
  const pid_t pid = spawn_sweep(sweep, db);
  ASSERT_GT(pid, 0);
  ReapOnExit reap{pid};
  ASSERT_GT(wait_for_trials(db, kInterruptibleTrials / 3, pid), 0);
  ASSERT_NO_FATAL_FAILURE(freeze(pid));
  const std::int64_t before = pamsim::ResultsDb::open_existing(db).trial_count();
  ASSERT_LT(before, kInterruptibleTrials) << "stopped too late to test an interrupt";
  ASSERT_EQ(::kill(pid, SIGINT), 0);  // delivered when it runs again
  ASSERT_EQ(::kill(pid, SIGCONT), 0);
  int status = 0;
  ASSERT_EQ(::waitpid(pid, &status, 0), pid);
  reap.release();
  ASSERT_TRUE(WIFEXITED(status)) << "SIGINT must stop the sweep, not kill it";
  EXPECT_EQ(WEXITSTATUS(status), 130);
  // what had finished is stored (also trials finished but not yet committed when it was
  // stopped, so no upper bound but the total); the sweep did not run to the end
  const std::int64_t stored = pamsim::ResultsDb::open_existing(db).trial_count();
  EXPECT_GE(stored, before);
  EXPECT_LT(stored, kInterruptibleTrials);
  const auto resumed = run_pamsim("sweep " + sweep.string() + " --resume --db " + db);
  ASSERT_EQ(resumed.exit_code, 0) << resumed.err;
  EXPECT_NE(resumed.err.find(std::to_string(stored) + " stored before"), std::string::npos)
      << resumed.err;
  EXPECT_EQ(pamsim::ResultsDb::open_existing(db).trial_count(), kInterruptibleTrials);
}

TEST(CliSweepTest, ASecondWriterIsRefusedWhileASweepRuns) {
  const fs::path dir = fresh_dir("sweep_lock");
  const fs::path sweep = interruptible_sweep(dir);
  const std::string db = (dir / "s.db").string();
  const pid_t pid = spawn_sweep(sweep, db);
  ASSERT_GT(pid, 0);
  ReapOnExit reap{pid};
  ASSERT_GT(wait_for_trials(db, 1, pid), 0);
  // the first writer holds its lock, stopped, however long the second takes to start
  ASSERT_NO_FATAL_FAILURE(freeze(pid));
  const auto second = run_pamsim("sweep " + sweep.string() + " --resume --db " + db);
  ::kill(pid, SIGKILL);
  ::waitpid(pid, nullptr, 0);
  reap.release();
  EXPECT_EQ(second.exit_code, 2) << second.err;
  EXPECT_EQ(line_count(second.err), 1) << second.err;
  EXPECT_NE(second.err.find("another pamsim sweep is writing to it"), std::string::npos)
      << second.err;
  // the lock dies with its process: a resume now finishes the sweep
  const auto resumed = run_pamsim("sweep " + sweep.string() + " --resume --db " + db);
  EXPECT_EQ(resumed.exit_code, 0) << resumed.err;
  EXPECT_EQ(pamsim::ResultsDb::open_existing(db).trial_count(), kInterruptibleTrials);
}

TEST(CliSweepTest, DivergingTrialIsStoredAndTheSweepGoesOn) {
  const fs::path dir = fresh_dir("sweep_diverge");
  const fs::path sweep = dir / "sweep.toml";
  // the arm under a gravity of 1e13 m/s^2 goes unstable at the first step (MuJoCo's bad
  // acceleration); the second point is the shipped arm (no scenario value can diverge a
  // trial: an absurd gain such as 1e300 MPa s/mm is refused as read)
  const std::string arm = std::string(PAMSIM_SOURCE_DIR) + "/models/arm_2pam.xml";
  std::string xml = read_file(arm);
  xml.replace(xml.find("gravity=\"0 0 -9.81\""), 19, "gravity=\"0 0 -1e13\"");
  write_text(dir / "unstable.xml", xml);
  write_text(sweep, short_sweep("[[axis]]\nkey = \"model.file\"\nvalues = [\"" +
                                (dir / "unstable.xml").string() + "\", \"" + arm + "\"]\n"));
  const std::string db = (dir / "s.db").string();
  const auto r = run_pamsim("sweep " + sweep.string() + " --db " + db);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("1 diverged"), std::string::npos) << r.err;
  ASSERT_EQ(run_pamsim("export " + db + " --csv " + db + ".csv").exit_code, 0);
  const auto lines = lines_of(read_file(db + ".csv"));
  ASSERT_EQ(lines.size(), 3u);
  EXPECT_NE(lines[1].find(",diverged,"), std::string::npos) << lines[1];
  EXPECT_NE(lines[1].find("MuJoCo: bad acceleration"), std::string::npos) << lines[1];
  EXPECT_NE(lines[2].find(",ok,"), std::string::npos) << lines[2];
}

TEST(CliSweepTest, ResumeRefusesADatabaseOfAnotherSweep) {
  const fs::path dir = fresh_dir("sweep_other");
  const fs::path a = dir / "a.toml", b = dir / "b.toml";
  write_text(a, short_sweep("[[axis]]\nkey = \"reflex.v_thr_mm_s\"\nvalues = [50.0]\n"));
  write_text(b, short_sweep("[[axis]]\nkey = \"reflex.v_thr_mm_s\"\nvalues = [60.0]\n"));
  const std::string db = (dir / "a.db").string();
  ASSERT_EQ(run_pamsim("sweep " + a.string() + " --db " + db).exit_code, 0);
  const std::string before = read_file(db);
  const auto r = run_pamsim("sweep " + b.string() + " --resume --db " + db);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(line_count(r.err), 1) << r.err;
  EXPECT_NE(r.err.find("holds a different sweep (its axes differ"), std::string::npos) << r.err;
  EXPECT_EQ(read_file(db), before);
  // resuming a finished sweep runs nothing and keeps every trial
  const auto again = run_pamsim("sweep " + a.string() + " --resume --db " + db);
  EXPECT_EQ(again.exit_code, 0) << again.err;
  EXPECT_EQ(pamsim::ResultsDb::open_existing(db).trial_count(), 1);
}

TEST(CliSweepTest, ReportWritesHeatMapsAndABestSettingThatRuns) {
  const fs::path dir = fresh_dir("sweep_report");
  const std::string db = (dir / "smoke.db").string();
  ASSERT_EQ(run_pamsim("sweep scenarios/sweep_smoke.toml --db " + db).exit_code, 0);
  const fs::path out = dir / "report";
  const auto r = run_pamsim("report " + db + " --out " + out.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("criterion: smallest mean peak_drop_deg"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("best: point "), std::string::npos) << r.out;
  for (const char* f : {"points.csv", "heatmap_mistrip_rate.png", "heatmap_peak_drop_deg.png",
                        "heatmap_recovery_time_s.png", "best.toml"}) {
    EXPECT_GT(fs::file_size(out / f), 100u) << f;
  }
  EXPECT_EQ(lines_of(read_file(out / "points.csv")).size(), 1u + 16u);

  // the best setting runs as a scenario, from another folder than the sweep's
  const auto run =
      run_pamsim("run " + (out / "best.toml").string() + " --out " + (dir / "best_run").string());
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_TRUE(fs::exists(dir / "best_run" / "summary.json"));

  const auto bad = run_pamsim("report " + db + " --metric nope --out " + (dir / "bad").string());
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_NE(bad.err.find("--metric nope"), std::string::npos) << bad.err;
  EXPECT_FALSE(fs::exists(dir / "bad"));
  // the page: point 0 replayed beside the best; a point the sweep has not, refused in one line
  const auto page = run_pamsim("report " + db + " --html --html-points 0 --no-plot --out " +
                               (dir / "page").string());
  ASSERT_EQ(page.exit_code, 0) << page.err;
  EXPECT_NE(read_file(dir / "page" / "report.html").find("id=\"point-0\""), std::string::npos);
  const auto none =
      run_pamsim("report " + db + " --html --html-points 16 --out " + (dir / "none").string());
  EXPECT_EQ(none.exit_code, 2);
  EXPECT_EQ(line_count(none.err), 1) << none.err;
  EXPECT_NE(none.err.find("--html-points 16: not a stored point"), std::string::npos) << none.err;
  EXPECT_FALSE(fs::exists(dir / "none"));
}

TEST(CliSweepTest, IntegerBooleanAndStringAxesKeepTheirTypesIntoTheBestScenario) {
  const fs::path dir = fresh_dir("sweep_types");
  const fs::path sweep = dir / "sweep.toml";
  write_text(sweep,
             short_sweep("[[axis]]\nkey = \"sensors.pressure_adc_bits\"\nvalues = [10, 12]\n"
                         "[[axis]]\nkey = \"reflex.mode\"\nvalues = [\"follow\", \"latch\"]\n"
                         "[[axis]]\nkey = \"reflex.reciprocal_trigger_inhibition\"\n"
                         "values = [true, false]\n"));
  const std::string db = (dir / "s.db").string();
  const auto r = run_pamsim("sweep " + sweep.string() + " --db " + db);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const fs::path out = dir / "report";
  const auto rep = run_pamsim("report " + db + " --out " + out.string());
  ASSERT_EQ(rep.exit_code, 0) << rep.err;
  const auto points = lines_of(read_file(out / "points.csv"));
  ASSERT_EQ(points.size(), 1u + 8u);
  EXPECT_EQ(points[1].rfind("0,10,follow,true,", 0), 0u) << points[1];
  EXPECT_EQ(points[8].rfind("7,12,latch,false,", 0), 0u) << points[8];
  const std::string best = read_file(out / "best.toml");
  EXPECT_NE(best.find("pressure_adc_bits = 1"), std::string::npos) << best;  // 10 or 12
  EXPECT_EQ(best.find("pressure_adc_bits = 1.0"), std::string::npos) << best;
  const auto run =
      run_pamsim("run " + (out / "best.toml").string() + " --out " + (dir / "best_run").string());
  EXPECT_EQ(run.exit_code, 0) << run.err;
}

// A database that cannot be written: read by export and report as it stands, and a resume
// refused before any trial runs (it used to read as "not a pamsim sweep database", and a
// resume ran its trials before failing). As root, which writes anything, pamsim runs as
// nobody through setpriv(1).
TEST(CliSweepTest, ReadOnlyDatabaseIsReadAndItsResumeRefusedBeforeRunning) {
  const fs::path dir = fresh_dir("sweep_read_only");
  const fs::path ro = dir / "ro";
  fs::create_directories(ro);
  const fs::path sweep = dir / "sweep.toml";
  write_text(sweep, short_sweep("seeds = 2\n[[axis]]\nkey = \"reflex.v_thr_mm_s\"\n"
                                "values = [50.0, 70.0]\n"));
  const std::string full = (ro / "full.db").string(), part = (ro / "part.db").string();
  ASSERT_EQ(run_pamsim("sweep " + sweep.string() + " --db " + full).exit_code, 0);
  ASSERT_EQ(run_pamsim("export " + full + " --csv " + (dir / "ref.csv").string()).exit_code, 0);
  pamsim::ResultsDb::create(part, pamsim::load_sweep(sweep.string()));  // no trials yet

  const std::string as_reader =
      ::geteuid() == 0 ? "setpriv --reuid=65534 --regid=65534 --clear-groups" : "";
  if (!as_reader.empty() && run_pamsim("--version", as_reader).exit_code != 0) {
    GTEST_SKIP() << "user nobody cannot run " << PAMSIM_BINARY;
  }
  fs::permissions(dir, fs::perms::all);  // outputs go beside the read-only folder
  for (const std::string& f : {full, part})
    fs::permissions(f, fs::perms::owner_read | fs::perms::group_read | fs::perms::others_read);
  fs::permissions(ro, fs::perms::owner_read | fs::perms::owner_exec | fs::perms::group_read |
                          fs::perms::group_exec | fs::perms::others_read | fs::perms::others_exec);
  const std::string part_before = read_file(part);

  const auto exported =
      run_pamsim("export " + full + " --csv " + (dir / "ro.csv").string(), as_reader);
  EXPECT_EQ(exported.exit_code, 0) << exported.err;
  EXPECT_EQ(read_file(dir / "ro.csv"), read_file(dir / "ref.csv"));
  const auto report = run_pamsim("report " + full + " --out " + (dir / "rep").string(), as_reader);
  EXPECT_EQ(report.exit_code, 0) << report.err;
  EXPECT_TRUE(fs::exists(dir / "rep" / "points.csv"));

  const auto resume = run_pamsim("sweep " + sweep.string() + " --resume --db " + part, as_reader);
  EXPECT_EQ(resume.exit_code, 2) << resume.err;
  EXPECT_EQ(line_count(resume.err), 1) << resume.err;
  EXPECT_NE(resume.err.find(part + ": is read-only"), std::string::npos) << resume.err;
  EXPECT_EQ(read_file(part), part_before);
  fs::permissions(ro, fs::perms::owner_all);  // so that the folder can be cleaned up
}

// A --db that names a folder is refused before anything is made, and the folders made for a
// database that then cannot be made are removed again; they used to stay, empty.
TEST(CliSweepTest, ADatabaseThatCannotBeMadeLeavesNoFolder) {
  const fs::path dir = fresh_dir("sweep_no_folder");
  const auto r =
      run_pamsim("sweep scenarios/sweep_smoke.toml --db " + (dir / "new/deep/").string());
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_EQ(line_count(r.err), 1) << r.err;
  EXPECT_NE(r.err.find("is a folder; name the database file"), std::string::npos) << r.err;
  EXPECT_TRUE(fs::is_empty(dir));
  // a database that cannot be written in the folders made for it (a full disk: a 1 KiB
  // file-size limit, SIGXFSZ ignored) leaves none of them
  const auto full = run_pamsim(
      "sweep scenarios/sweep_smoke.toml --db " + (dir / "new" / "deeper" / "s.db").string(),
      "bash -c 'trap \"\" XFSZ; ulimit -f 1; exec \"$0\" \"$@\"'");
  EXPECT_NE(full.exit_code, 0) << full.err;
  EXPECT_EQ(line_count(full.err), 1) << full.err;
  EXPECT_NE(full.err.find((dir / "new" / "deeper" / "s.db").string() +
                          ": cannot create the sweep database ("),
            std::string::npos)
      << full.err;
  EXPECT_TRUE(fs::is_empty(dir)) << full.err;
}

TEST(CliSweepTest, ExportAndReportRefuseWhatIsNotASweepDatabase) {
  const fs::path dir = fresh_dir("sweep_not_db");
  write_text(dir / "junk.db", "not a database at all, just some text that is long enough\n");
  for (const std::string& args :
       {"export " + (dir / "junk.db").string() + " --csv " + (dir / "x.csv").string(),
        "export " + (dir / "absent.db").string() + " --csv " + (dir / "x.csv").string(),
        "report " + (dir / "junk.db").string(), "report " + (dir / "junk.db").string() + " --html",
        "report " + dir.string(), "report " + dir.string() + " --html"}) {
    const auto r = run_pamsim(args);
    EXPECT_EQ(r.exit_code, 2) << args << ": " << r.err;
    EXPECT_EQ(line_count(r.err), 1) << args << ": " << r.err;
  }
  EXPECT_FALSE(fs::exists(dir / "x.csv"));
  EXPECT_FALSE(fs::exists(dir / "absent.db"));
  EXPECT_FALSE(fs::exists(dir / "report.html"));
  // a folder whose provenance.json has fields of other types: its page still, said so
  const fs::path odd = dir / "odd";
  fs::create_directories(odd);
  write_text(odd / "table5.md", "| a |\n| --- |\n| 1 |\n");
  write_text(odd / "provenance.json", "{\"build\": \"x\", \"started_utc\": 3}\n");
  const auto page = run_pamsim("report " + odd.string() + " --html");
  ASSERT_EQ(page.exit_code, 0) << page.err;
  EXPECT_NE(read_file(odd / "report.html").find("not one pamsim wrote"), std::string::npos);
}

}  // namespace
