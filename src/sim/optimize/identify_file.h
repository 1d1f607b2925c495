// identify_file.h: an identification file (`pamsim identify`) as data: the base
// scenario, the parameters to identify (search_space.h: any scenario key, e.g. a plant's
// field), the lab's recordings and how to search; load_identify_definition reads it.
#pragma once

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "base/key_table.h"
#include "pam_actuator/tensile_test.h"
#include "sim/io/recording_csv.h"
#include "sim/optimize/search_space.h"

namespace pamsim {

// Identification file keys (paths relative to the file):
//   base                scenario file, required
//   overrides           scenario overrides at every simulation ("key=value" strings)
//   generations, population, seed, polish_iterations, starts, profile_offsets, interval,
//                       explained_noise_factor: how to search and how to judge, rows of
//                       identify_search_table below
//   [[parameter]]       key (a scenario key), from < to, scale = "linear" | "log" (from > 0);
//                       or a recorded channel's sensor, key = "channel.<column>.offset" (in
//                       the column's unit), ".gain" (> 0) or ".delay_ms" (>= 0, <= 1000):
//                       recorded = gain x simulated(t - delay) + offset, in every recording
//                       that matches <column> (one instrument); not a scenario key
//   [[recording]]       file: a recording (sim/io/recording_csv.h), required
//                       name: letters, digits, '_' and '-'; default the file's stem; unique
//                       set: the conditions it was recorded under, as --set "key=value"
//                       channels: the columns to match; default every one it has
//                       weight: > 0, its residuals' weight; default 1
//                       held_out: true: used only to check the result; default false
//                       noise: a chosen channel's noise floor, > 0 in its unit, as a table
//                       ({ angle_deg = 0.01 }); default: estimated from the recording
//                       commands: "scenario" (default: the scenario's schedules) or "log":
//                       the recording's own p_cmd_<label>_MPa columns drive the valves, held
//                       (IdentifyRecording::log_commands), and are no channel to match
//   [[candidate]]       an experiment a lab could run next, for `pamsim identify --plan`
//                       (identify_plan.h): no data. name (required, unique; letters, digits,
//                       '_', '-'); set: its conditions as --set "key=value" (a command
//                       schedule, an event such as a drop); channels: the columns a lab could
//                       log, at least one; rate_hz: their sampling rate, (0, 10000], default
//                       100; duration_s: (0, its scenario's sim.duration_s], default that;
//                       noise: { <channel> = floor }, > 0, required for a channel no fitted
//                       recording measures (default: the floor identify finds for it there)
//   [[tensile]]         muscle: a muscle of the base scenario with a plant file (its actuator
//                       name); file: a tensile test of it in `pamsim tensile`'s CSV format;
//                       weight: > 0, default 1. Its plant's forces at the recorded pressures
//                       and lengths, on each row's stroke, must match the recorded forces.
// With no [[parameter]], nothing is searched: the model as the file gives it is held against
// the recordings (identify.h). At least one recording is fitted (not held out), or a tensile
// test given. Every recording's
// scenario must load, and each channel must be one its trials log (trajectory.csv's columns); a
// recording must not outlast its scenario's sim.duration_s (load_identify_definition).
struct IdentifyRecording {
  std::string name;
  Recording data;
  std::vector<std::string> set;       // the recording's own overrides
  std::vector<std::size_t> channels;  // indices into data.channels
  double weight = 1.0;
  bool held_out = false;
  std::vector<double> noise;  // per chosen channel, its given noise floor (NaN: none)
  // commands = "log": each muscle whose valve command the recording logged (p_cmd_<label>_MPa)
  // driven by that column, held from row to row, with the controller off from 0 s (the log's
  // commands are the controller's); the overrides that do it (identify_file_recordings.h)
  std::vector<std::string> log_commands;

  // Every override of its trial but the parameters': `set`, then log_commands.
  std::vector<std::string> conditions() const;
};

// A parameter that is a recorded channel's sensor rather than a scenario key.
struct ChannelParameter {
  enum class Kind { kNone, kOffset, kGain, kDelay } kind = Kind::kNone;  // kNone: a scenario key
  std::string column;
};

// What a channel's sensor does to the simulated column: gain x column(t - delay) + offset.
struct ChannelTransform {
  double gain = 1.0, offset = 0.0, delay_s = 0.0;
};

struct IdentifyTensile {
  std::string muscle;  // the actuator's name (muscles.<muscle>)
  std::string file;
  std::vector<TensileRow> rows;
  double weight = 1.0;
};

struct IdentifyDefinition {
  std::string file;
  std::string base_path, base_text;
  std::vector<std::string> overrides;
  unsigned generations = 20, population = 8;  // generations: each run's most
  std::uint64_t seed = 1;
  int polish_iterations = 30;
  int starts = 1;  // Levenberg-Marquardt starts (identify.h: IdentifyResult::starts)
  int runs = 3;    // independent CMA-ES runs (identify_global.h)
  unsigned stall_generations = 4;  // a run's stall stop (identify_global.h); 0: none
  bool profile_offsets = true;  // the global search projects the offsets out (identify_offsets.h)
  // the reported intervals' level, and the RMS in noise floors within which a fitted channel
  // is explained (identify_uncertainty.h); neither in canonical_json: neither changes the search
  double interval = 0.95;
  double explained_noise_factor = 3.0;
  std::vector<SearchParameter> parameters;
  std::vector<ChannelParameter> channel_parameters;  // per parameter (kNone: a scenario key)
  std::vector<IdentifyRecording> recordings;
  std::vector<IdentifyTensile> tensile;
  // [[candidate]]s: a recording's conditions and channels on a sample grid, no data
  // (samples 0); not part of the search (nor of canonical_json)
  std::vector<IdentifyRecording> candidates;

  // The overrides of the base scenario with the parameters at `values` (the tensile tests'
  // plants are its muscles').
  std::vector<std::string> overrides_at(const std::vector<double>& values) const;
  // The overrides of `recording`'s trial with the parameters at `values` (the scenario
  // keys among them).
  std::vector<std::string> overrides_at(const IdentifyRecording& recording,
                                        const std::vector<double>& values) const;
  // The sensor of `recording`'s chosen channel `i` with the parameters at `values`.
  ChannelTransform transform_at(const IdentifyRecording& recording, std::size_t i,
                                const std::vector<double>& values) const;
  // The parameters' values that change the trials (the channel parameters' left out).
  std::vector<double> scenario_values(const std::vector<double>& values) const;
  // Whether the global search sets parameter `k` aside, at its least-squares value at each
  // point (identify_offsets.h): with profile_offsets, a channel's offset on a linear scale.
  bool offset_projected(std::size_t k) const;
  // Everything that decides the result, as canonical JSON (stored; a resume must match):
  // the settings, parameters and every recording's name, set, channels, weight, role and
  // samples.
  std::string canonical_json() const;
};

// The files the base scenario and every recording's scenario read (model, pneumatics,
// calibration, parameter and plant files, schedule tables), as (scenario key, path), each
// once: what a resumed identification must find unchanged (identify_db.h).
std::vector<std::pair<std::string, std::string>> identify_input_paths(
    const IdentifyDefinition& def);

// The file's top-level numbers as rows (base/key_table.h), bound to `def`: each one's range,
// default (the struct's own) and meaning; the reader, `pamsim keys --identify` and the tests
// read them.
KeyTable identify_search_table(IdentifyDefinition* def);

// The CMA-ES population where the file gives none: the larger of 8 and CMA-ES's default
// 4 + floor(3 ln m) (Hansen, "The CMA Evolution Strategy: A Tutorial", 2016), m the
// parameters the global search moves (the projected offsets aside), so that a search of many
// parameters draws more points per generation.
unsigned default_population(const IdentifyDefinition& def);

// Reads and validates the file and its recordings. Throws InputError "<file>: <key> <problem>"
// or the recording's own "<recording>: line <n>: <problem>".
IdentifyDefinition load_identify_definition(const std::string& path);

}  // namespace pamsim
