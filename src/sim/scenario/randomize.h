// randomize.h: parameters drawn per trial, the [[randomize]] tables of a sweep or tuning file,
// for questions such as "does the tuned reflex keep the mass if the braid's friction is 30 %
// higher and the wall 10 % thinner?". Each table names a scenario key (any numeric key: a
// plant's or the pneumatics file's field, a body's mass, a joint's loss, ...) and how it is
// drawn (Randomization). The values are stored with the trial (a column per key,
// results_db.h), which is what `pamsim replay` runs again.
#pragma once

#include <cstdint>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "base/entry_keys.h"

namespace pamsim {

class ConfigReader;  // base/config_reader.h

enum class Distribution { kUniform, kNormal, kLogNormal };

// A [[randomize]] table:
//   key          = "muscles.agonist.plant.geometry.wall_thickness_mm"
//   distribution = "uniform"     from, to (from < to)
//                  "normal"      mean, stddev (> 0)
//                  "lognormal"   median (> 0), sigma (> 0: the logarithm's standard deviation)
//   min, max     optional, normal and lognormal: truncation (a draw outside is drawn again);
//                the range must hold at least 1 % of the distribution
struct Randomization {
  std::string key;
  Distribution distribution = Distribution::kUniform;
  double a = 0.0;  // uniform: from; normal: mean; lognormal: median
  double b = 0.0;  // uniform: to; normal: stddev; lognormal: sigma
  double min = -std::numeric_limits<double>::infinity();  // normal, lognormal
  double max = std::numeric_limits<double>::infinity();

  // One draw (truncated to [min, max] by drawing again).
  double draw(std::mt19937_64& rng) const;
  // The share of the untruncated distribution inside [min, max].
  double kept_share() const;
};

// A [[randomize]] table's keys, as the key reference lists them (which a distribution takes
// is the reader's: from and to for uniform, mean and stddev for normal, median and sigma for
// lognormal, min and max for the last two).
const std::vector<EntryKey>& randomize_entry_keys();

// The [[randomize]] tables (none: empty) and randomize_seed of `in`'s document. Throws
// InputError "<file>: randomize[<i>].<key> <problem>" and the like.
void read_randomizations(ConfigReader& in, std::vector<Randomization>* randomize,
                         std::uint64_t* randomize_seed);

// A trial's draws depend on the sweep's randomize_seed and the trial's seed index (trial t:
// t % seeds) alone, never on its point, thread, shard or rank: every point sees the same
// `seeds` drawn arms (common random numbers, as with the noise seeds), and a sweep draws the
// same values wherever it runs.
// The values of the trials with seed index `seed_index`, one per randomization, in order.
std::vector<double> draw_values(const std::vector<Randomization>& randomize,
                                std::uint64_t randomize_seed, std::int64_t seed_index);

// Appends the draws of seed index `seed_index` to `overrides` as "key=value" (the value in
// its shortest exact form).
void append_draws(const std::vector<Randomization>& randomize, std::uint64_t randomize_seed,
                  std::int64_t seed_index, std::vector<std::string>* overrides);

// The randomizations as canonical JSON (part of a sweep's or tuning's definition), and back
// (throws nlohmann::json::exception on a missing field).
nlohmann::json randomizations_json(const std::vector<Randomization>& randomize);
std::vector<Randomization> randomizations_from_json(const nlohmann::json& j);

}  // namespace pamsim
