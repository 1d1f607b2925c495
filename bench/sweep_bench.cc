// sweep_bench.cc: sweep throughput, the whole path of `pamsim sweep` (load each point's
// scenario, run its 3 s drop-mass trials, commit every result to SQLite with synchronous=FULL)
// on 1 and 2 worker threads, in one run so the ratio is meaningful:
//   BM_Sweep/threads:N   a 4 x 4 grid of reflex threshold and gain, 5 seeds (80 trials), into
//                        a fresh database each iteration; real time.
// Counter trials_per_s; the 2-thread / 1-thread ratio of it is the issue-5 scaling figure.
#include <benchmark/benchmark.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "sim/sweep/results_db.h"
#include "sim/sweep/sweep.h"
#include "sim/sweep/sweep_runner.h"

namespace pamsim {
namespace {

namespace fs = std::filesystem;

SweepDefinition bench_sweep(const fs::path& dir) {
  const fs::path file = dir / "bench_sweep.toml";
  std::ofstream(file)
      << "base = \"" PAMSIM_SOURCE_DIR
         "/scenarios/drop_mass.toml\"\n"
         "seeds = 5\n"
         "[[axis]]\nkey = \"reflex.v_thr_mm_s\"\nfrom = 40.0\nto = 100.0\ncount = 4\n"
         "[[axis]]\nkey = \"reflex.k_MPa_s_per_mm\"\nfrom = 0.0005\nto = 0.004\n"
         "count = 4\nscale = \"log\"\n";
  return load_sweep(file.string());
}

void BM_Sweep(benchmark::State& state) {
  const fs::path dir =
      fs::temp_directory_path() / ("pamsim_sweep_bench_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const SweepDefinition sweep = bench_sweep(dir);
  SweepRunOptions options;
  options.threads = static_cast<int>(state.range(0));
  int n = 0;
  for (auto _ : state) {
    const fs::path db_path = dir / ("run_" + std::to_string(n++) + ".db");
    ResultsDb db = ResultsDb::create(db_path.string(), sweep);
    const SweepRunResult r = run_sweep(sweep, db, options);
    if (r.ran != sweep.trials()) state.SkipWithError("not every trial ran");
  }
  state.counters["trials_per_s"] = benchmark::Counter(
      static_cast<double>(sweep.trials()), benchmark::Counter::kIsIterationInvariantRate);
  fs::remove_all(dir);
}
BENCHMARK(BM_Sweep)
    ->ArgName("threads")
    ->Arg(1)
    ->Arg(2)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->MinTime(3.0);

}  // namespace
}  // namespace pamsim
