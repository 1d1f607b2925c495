// tuning_file.h: a tuning file (`pamsim tune`) as data: the base scenario, the free
// parameters with bounds (search_space.h), the objectives and constraints built from trial
// metrics averaged over seeds and sensor-noise levels, references to check beside the best,
// and the algorithm (optimizer.h). The file's keys are listed at load_tune_definition.
#pragma once

#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "base/entry_keys.h"
#include "sim/scenario/randomize.h"
#include "sim/optimize/optimizer.h"
#include "sim/optimize/search_space.h"

namespace pamsim {

using TuneParameter = SearchParameter;
using TuneAlgorithm = SearchAlgorithm;

// The held-out seeds are base.seed + this + k (and, with [[randomize]], seed indices this + k).
inline constexpr std::uint64_t kHeldOutSeedOffset = 1000;

struct TuneObjective {
  std::string metric;
  bool maximize = false;
};

struct TuneConstraint {
  std::string metric;
  double min = -std::numeric_limits<double>::infinity();
  double max = std::numeric_limits<double>::infinity();
};

struct TuneReference {
  std::string name;
  std::vector<double> values;
};

struct TuneDefinition {
  std::string file;
  std::string base_path, base_text;
  std::vector<std::string> overrides;
  TuneAlgorithm algorithm = TuneAlgorithm::kCmaes;
  unsigned generations = 10, population = 8;
  std::uint64_t seed = 1;
  int seeds = 3;
  std::vector<double> noise_scales{1.0};
  int held_out_seeds = 20;
  std::vector<TuneParameter> parameters;
  std::vector<TuneObjective> objectives;
  std::vector<TuneConstraint> constraints;
  std::vector<TuneReference> references;
  std::vector<Randomization> randomize;  // drawn per seed index (robust tuning)
  std::uint64_t randomize_seed = 1;

  // Everything that decides the evaluations, as canonical JSON (stored; a resume must match).
  std::string canonical_json() const;
  // The optimiser's settings.
  SearchSettings search() const { return {algorithm, generations, population, seed}; }
  // The base scenario's overrides with the parameters set to `values`.
  std::vector<std::string> overrides_at(const std::vector<double>& values) const {
    return parameter_overrides(overrides, parameters, values);
  }
};

// The file's top-level search keys as rows (base/key_table.h), bound to `def`: each one's
// range, default (the struct's own) and meaning; the reader, `pamsim keys --tune` and the
// tests read them.
KeyTable tune_search_table(TuneDefinition* def);

// The keys of an [[objective]], a [[constraint]] and a [[reference]] table, as the reader
// takes them and the key reference lists them.
const std::vector<EntryKey>& objective_entry_keys();
const std::vector<EntryKey>& constraint_entry_keys();
const std::vector<EntryKey>& reference_entry_keys();

// Tuning file keys (paths relative to the file):
//   base              scenario file, required
//   overrides         scenario overrides at every evaluation ("key=value" strings)
//   algorithm, generations, population, seed, seeds, held_out_seeds: rows of
//                     tune_search_table above (`pamsim keys --tune`)
//   noise_scales      sensors.noise_scale levels each evaluation averages over, each in
//                     [0, 1000] once; default [1]
//   [[parameter]]     key (a scenario key), from < to, scale = "linear" | "log" (from > 0)
//   [[objective]]     metric (a summary metric), maximize = false
//   [[constraint]]    metric, min and/or max: on the metric's mean over an evaluation's trials
//   [[reference]]     name, values = [one per parameter]: settings checked beside the best
//   [[randomize]]     key and distribution drawn per seed (sim/scenario/randomize.h): robust
//                     tuning, each evaluation's k-th seed on the same drawn arm;
//                     randomize_seed
// Reads and validates the file, the base scenario (with the overrides, and with each
// parameter at both bounds) and the metric names. Throws InputError "<file>: <key> <problem>".
TuneDefinition load_tune_definition(const std::string& path);

// The definition from its canonical JSON (a tuning database's), with its file as given.
// Throws InputError "<where>: its tuning definition cannot be read" when it does not parse.
TuneDefinition tune_definition_from_json(const std::string& json, const std::string& file,
                                         const std::string& where);

}  // namespace pamsim
