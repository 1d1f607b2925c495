// sweep.h: a parameter sweep read from a sweep TOML file: a base scenario, fixed overrides,
// the axes (any scenario key, as a list or a linear/log range), the design that turns the axes
// into points (full grid, uniform random, or Latin hypercube) and the seeds per point.
// Trial t is point t / seeds with seed base.seed + t % seeds, so every point sees the same
// noise seeds (common random numbers: differences between points are not sampling noise).
// The file's keys are listed at load_sweep.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "base/entry_keys.h"
#include "sim/scenario/randomize.h"

namespace pamsim {

enum class SweepDesign { kGrid, kRandom, kLatinHypercube };
const char* sweep_design_name(SweepDesign design);
// "grid", "random" or "lhs"; InputError "<context> must be ..." otherwise.
SweepDesign parse_sweep_design(const std::string& name, const std::string& context);

// One value of an axis: a float or an integer (both held in `number`), or a string or
// boolean scenario value. Integers stay integers (integer keys refuse 12.0).
struct AxisValue {
  enum class Kind { kNumber, kInteger, kString, kBool } kind = Kind::kNumber;
  double number = 0;  // kNumber, kInteger (exact up to 2^53)
  std::string text;   // kString
  bool flag = false;  // kBool
  // The value as TOML source for a `key=value` override (numbers round-trip exactly).
  std::string toml() const;
};

struct SweepAxis {
  std::string key;                // scenario key, e.g. "reflex.v_thr_mm_s"; a case axis's name
  std::vector<AxisValue> values;  // grid levels (grid design); a case axis's case names
  // A case axis: case_sets[i] holds case i's "key=value" overrides in key order (values[i]
  // its name).
  std::vector<std::vector<std::string>> case_sets;
  bool is_cases() const { return !case_sets.empty(); }
  // The "key=value" overrides of the level `v`: key=v, or the case named v's set.
  std::vector<std::string> overrides_of(const AxisValue& v) const;
  bool is_range = false;  // from/to given (random and lhs sample inside it)
  double from = 0, to = 0;
  bool log_scale = false;
  // The value at fraction u in [0, 1] of the range (geometric on a log scale).
  double at(double u) const;
};

struct SweepDefinition {
  std::string file;                // the sweep file, as given
  std::string base_path;           // the base scenario, resolved
  std::string base_text;           // its content (part of the definition)
  std::vector<std::string> fixed;  // "key=value" overrides at every point
  std::vector<SweepAxis> axes;
  SweepDesign design = SweepDesign::kGrid;
  std::int64_t samples = 0;       // random, lhs
  std::uint64_t design_seed = 1;  // random, lhs
  std::int64_t seeds = 1;
  std::vector<Randomization> randomize;  // drawn per seed index (randomize.h)
  std::uint64_t randomize_seed = 1;
  std::int64_t max_trials = 1000000;  // the cap on points x seeds (not part of the definition)
  std::uint64_t base_seed = 1;        // the base scenario's seed (with fixed overrides)
  // the metrics each trial stores (the database's metric columns), from the base scenario
  std::vector<std::string> metric_names;

  // The points' coordinates, point-major: point_values[p * axes.size() + a].
  std::vector<AxisValue> point_values;

  std::int64_t points() const;
  std::int64_t trials() const { return points() * seeds; }
  const AxisValue& value(std::int64_t point, std::size_t axis) const;
  // "key=value" overrides for a point: the fixed ones, then the axes'.
  std::vector<std::string> overrides(std::int64_t point) const;
  std::uint64_t seed_of(std::int64_t trial) const;
  // The values [[randomize]] draws for trial `trial` (those of its seed index), in order.
  std::vector<double> draws(std::int64_t trial) const;
  // "key=value" overrides for a trial: its point's, then its draws.
  std::vector<std::string> trial_overrides(std::int64_t trial) const;
  // What makes two sweeps the same experiment, as canonical JSON text: base scenario content,
  // fixed overrides, axes, design, seeds and any randomization (not the file names or the
  // project version).
  std::string canonical_json() const;
};

// A deterministic share of a sweep's trials for one machine of a cluster (`--shard I/N`,
// 0 <= I < N): trial t belongs to shard t mod N. Every trial is in exactly one shard, the
// shards' sizes differ by at most one, and each holds every point's trials in turn, so trials
// whose cost depends on the point spread evenly over the shards.
struct SweepShard {
  std::int64_t index = 0;
  std::int64_t count = 1;  // 1: the whole sweep

  bool whole() const { return count == 1; }
  bool holds(std::int64_t trial) const { return trial % count == index; }
  // How many of the trials 0..total-1 this shard holds.
  std::int64_t trials_of(std::int64_t total) const {
    return total / count + (index < total % count ? 1 : 0);
  }
  std::string text() const;  // "I/N"
};

// Parses "I/N" (decimal integers, N >= 1, 0 <= I < N). Throws InputError
// "<source> must be I/N with 0 <= I < N, got '<text>'" (source names the option).
SweepShard parse_sweep_shard(const std::string& text, const std::string& source);

// The number of points of a grid over `axes` (the product of their levels), or -1 once it
// exceeds `cap` (the product is never formed past it, so it cannot wrap).
std::int64_t grid_points(const std::vector<SweepAxis>& axes, std::int64_t cap);
// Fills def->point_values from its axes and design (the grid row-major, the first axis
// varying slowest; random and lhs drawn from design_seed).
void make_points(SweepDefinition* def);

// The most a count key (seeds, max_trials, samples) allows: 10^12, far past any sweep, and
// far from a product's overflow.
inline constexpr std::int64_t kMaxCount = 1000000000000;

// The sweep file's top-level keys as rows (base/key_table.h), bound to `def`: design, seeds
// and max_trials; and samples and design_seed, which only a random or lhs design reads. The
// reader, `pamsim keys --sweep` and the tests read them.
KeyTable sweep_design_table(SweepDefinition* def);
KeyTable sweep_sampling_table(SweepDefinition* def);

// The keys of an [[axis]] over a scenario key, of an [[axis]] of named cases, and of one of
// its [[axis.case]] tables, as the reader takes them and the key reference lists them.
const std::vector<EntryKey>& axis_entry_keys();
const std::vector<EntryKey>& case_axis_entry_keys();
const std::vector<EntryKey>& case_entry_keys();

// Sweep file keys:
//   base         scenario file (path, relative to the sweep file)            required
//   design, seeds, max_trials, and samples, design_seed (random and lhs only): rows of
//                sweep_design_table and sweep_sampling_table above (`pamsim keys --sweep`)
//   [fixed]      scenario keys set at every point, as in the scenario: [fixed.sim] duration_s = 2
//   [[axis]]     key = "reflex.v_thr_mm_s", and either
//                  values = [..]                       (grid only), or
//                  from, to, count, scale = "linear"|"log"   (count for grid only)
//                or a case axis (grid only): name = "regulator" (its column) and one or more
//                  [[axis.case]] name = "ITV2000 class", set = { "valve.dead_time_ms" = 2.0 }
//                  (named bundles of scenario keys; an empty set is the base scenario's);
//                  from = { file = "f.toml", table = "t" } takes a case's keys from a table
//                  of another file (relative to the sweep file), before its set
//   [[randomize]] key and a distribution drawn per trial (sim/scenario/randomize.h), e.g. a plant's
//   field randomize_seed  seed of those draws, >= 0                                  default 1
// Reads and validates a sweep file (sweep_file.cc), including every point's scenario. Throws
// InputError
// "<file>: <key> <problem>" for the first problem found.
SweepDefinition load_sweep(const std::string& path);

}  // namespace pamsim
