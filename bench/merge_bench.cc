// merge_bench.cc: `pamsim merge` at cluster scale: one million synthetic trials with the
// smoke sweep's columns (a 1000 x 100 grid of its two axes, 10 seeds), written as the 16
// shard databases a 16-task job array leaves, then merged into one database.
//   BM_Merge1M   real time of merge_sweep_databases; counters trials_per_s and merged_MB
//                (the merged file's size). The shards are written once, before timing.
//   BM_StoreTrials/batch:N   one writer storing trials N to a transaction (below)
// The issue-16 figures (merge time and database size for 10^6 trials) come from here.
#include <benchmark/benchmark.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include "sim/sweep/merge.h"
#include "sim/sweep/results_db.h"
#include "sim/sweep/sweep.h"

namespace pamsim {
namespace {

namespace fs = std::filesystem;

constexpr std::int64_t kShards = 16;

// The smoke sweep, widened to 1000 x 100 points x 10 seeds (the base scenario and metric
// columns stay the smoke sweep's; no point's scenario is loaded).
SweepDefinition million_trial_sweep() {
  SweepDefinition def = load_sweep(PAMSIM_SOURCE_DIR "/scenarios/sweep_smoke.toml");
  const std::int64_t levels[2] = {1000, 100};
  for (std::size_t a = 0; a < 2; ++a) {
    def.axes[a].values.clear();
    for (std::int64_t i = 0; i < levels[a]; ++i) {
      AxisValue v;
      v.number = def.axes[a].from + (def.axes[a].to - def.axes[a].from) * i / (levels[a] - 1);
      def.axes[a].values.push_back(v);
    }
  }
  def.point_values.clear();
  for (std::int64_t p = 0; p < levels[0] * levels[1]; ++p) {
    def.point_values.push_back(def.axes[0].values[p / levels[1]]);
    def.point_values.push_back(def.axes[1].values[p % levels[1]]);
  }
  def.seeds = 10;
  return def;
}

// Trial t of `def` with every metric filled with a full-precision value.
TrialRecord synthetic_record(const SweepDefinition& def, std::int64_t t) {
  TrialRecord r;
  r.trial = t;
  r.point = t / def.seeds;
  r.seed_index = t % def.seeds;
  r.summary.seed = def.seed_of(t);
  for (std::size_t m = 0; m < def.metric_names.size(); ++m) {
    r.summary.metrics.push_back({def.metric_names[m], std::sin(0.001 * t + m), false});
  }
  return r;
}

// Shard `shard` of `def`, every trial synthetic.
void write_shard(const SweepDefinition& def, const SweepShard& shard, const std::string& path) {
  ResultsDb db = ResultsDb::create(path, def, shard);
  std::vector<TrialRecord> batch;
  for (std::int64_t t = shard.index; t < def.trials(); t += shard.count) {
    batch.push_back(synthetic_record(def, t));
    if (batch.size() == 20000) {
      db.insert(def, batch);
      batch.clear();
    }
  }
  db.insert(def, batch);
}

void BM_Merge1M(benchmark::State& state) {
  const fs::path dir =
      fs::temp_directory_path() / ("pamsim_merge_bench_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  const SweepDefinition def = million_trial_sweep();
  std::vector<std::string> parts;
  for (std::int64_t i = 0; i < kShards; ++i) {
    parts.push_back((dir / ("shard" + std::to_string(i) + ".db")).string());
    write_shard(def, SweepShard{i, kShards}, parts.back());
  }
  int n = 0;
  double merged_bytes = 0;
  for (auto _ : state) {
    const std::string out = (dir / ("merged" + std::to_string(n++) + ".db")).string();
    const MergeResult r = merge_sweep_databases(out, parts);
    if (r.merged != def.trials() || r.missing != 0) state.SkipWithError("trials lost");
    merged_bytes = static_cast<double>(fs::file_size(out));
    fs::remove(out);
  }
  state.counters["trials"] = static_cast<double>(def.trials());
  state.counters["trials_per_s"] = benchmark::Counter(
      static_cast<double>(def.trials()), benchmark::Counter::kIsIterationInvariantRate);
  state.counters["merged_MB"] = merged_bytes / 1e6;
  fs::remove_all(dir);
}
BENCHMARK(BM_Merge1M)->Unit(benchmark::kSecond)->UseRealTime()->Iterations(1);

// What one writer (an MPI sweep's rank 0, or a threaded sweep) can store: 20000 synthetic
// trials of the smoke sweep's columns inserted in transactions of `batch` trials each
// (ResultsDb::insert: WAL, synchronous=FULL, so each commit waits for the disk). Counter
// trials_per_s: the storage rate docs/cluster.md's estimate uses.
void BM_StoreTrials(benchmark::State& state) {
  const fs::path dir =
      fs::temp_directory_path() / ("pamsim_store_bench_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  const SweepDefinition def = million_trial_sweep();
  const std::int64_t batch = state.range(0), total = 20000;
  std::vector<std::vector<TrialRecord>> batches;
  for (std::int64_t t = 0; t < total; t += batch) {
    batches.emplace_back();
    for (std::int64_t k = t; k < std::min(total, t + batch); ++k) {
      batches.back().push_back(synthetic_record(def, k));
    }
  }
  int n = 0;
  for (auto _ : state) {
    ResultsDb db = ResultsDb::create((dir / ("store" + std::to_string(n++) + ".db")).string(), def);
    for (const std::vector<TrialRecord>& b : batches) db.insert(def, b);
  }
  state.counters["trials_per_s"] =
      benchmark::Counter(static_cast<double>(total), benchmark::Counter::kIsIterationInvariantRate);
  fs::remove_all(dir);
}
BENCHMARK(BM_StoreTrials)
    ->ArgName("batch")
    ->Arg(1)
    ->Arg(16)
    ->Arg(256)
    ->Unit(benchmark::kSecond)
    ->UseRealTime()
    ->Iterations(1);

}  // namespace
}  // namespace pamsim
