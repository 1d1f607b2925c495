// provenance.h: what made an output folder, written beside its outputs as provenance.json:
// the command line, the scenario file and the overrides as given, the seeds and thread
// count, pamsim's version and git commit, the MuJoCo and SUNDIALS versions (build_info.h),
// when it started and how long it took (the per-trial wall times too: they vary from run to
// run, so they live here and not in summary.json, which a rerun reproduces byte for byte).
// The resolved scenario itself is saved beside it as scenario.toml (scenario_file.h).
#pragma once

#include <chrono>
#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "sim/core/trial.h"

namespace pamsim {

// The name of the file, in every output folder that has one.
inline constexpr const char* kProvenanceFile = "provenance.json";
// The resolved scenario saved beside it (`pamsim run --from DIR` reads it).
inline constexpr const char* kResolvedScenarioFile = "scenario.toml";

// The current time in UTC, ISO 8601 ("2026-11-24T00:15:55Z").
std::string utc_timestamp();

// Keeps the process's command line for the provenance (main() calls it first).
void record_command_line(int argc, const char* const* argv);
const std::vector<std::string>& command_line();

struct TrialTiming {
  std::uint64_t seed = 0;
  double wall_time_s = 0;
  double realtime_factor = 0;   // simulated s per wall-clock s
};

// A trial's wall time and real-time factor, from its summary's timing metrics.
TrialTiming timing_of(const TrialSummary& summary);

struct Provenance {
  std::string command;                  // "run", "validate", ...
  std::string scenario_file;            // as given on the command line
  std::vector<std::string> overrides;   // --set key=value, in order
  std::string from;                     // `run --from DIR`: the folder it reproduces
  std::vector<std::uint64_t> seeds;
  int threads = 1;
  std::string started_utc;              // ISO 8601
  double wall_time_s = 0;               // the whole command
  std::vector<TrialTiming> trials;
  // read back by read_provenance from "build" (written by provenance_to_json)
  std::string pamsim_version, git_commit;
};

// The provenance as JSON, with build_info_json() under "build" and command_line().
nlohmann::json provenance_to_json(const Provenance& provenance);
// Writes `provenance` to `path` (atomically), its wall_time_s the time since `started`.
void write_provenance(const std::string& path, Provenance provenance,
                      std::chrono::steady_clock::time_point started);

// Reads DIR/provenance.json back (for `run --from DIR`). Throws InputError naming the file
// and the field when it is missing or not a pamsim provenance.
Provenance read_provenance(const std::string& dir);

}  // namespace pamsim
