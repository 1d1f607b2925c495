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
#include <utility>
#include <vector>

#include "sim/core/trial.h"

namespace pamsim {

// The name of the file, in every output folder that has one.
inline constexpr const char* kProvenanceFile = "provenance.json";
// The resolved scenario saved beside it (`pamsim run --from DIR` reads it).
inline constexpr const char* kResolvedScenarioFile = "scenario.toml";

// FNV-1a (64 bit) of `bytes`: a stable fingerprint (the same on every platform and build,
// unlike std::hash) to tell whether a file changed. Not a cryptographic hash.
std::uint64_t fnv1a64(const std::string& bytes);

// An input file of a run: the scenario key that names it, its path as resolved, its size and
// fingerprint when the run read it.
struct InputFile {
  std::string key;
  std::string path;
  std::uint64_t bytes = 0;
  std::string fnv1a64;  // 16 hex digits
};
// The files the scenario's path keys name (model, pneumatics, calibration, params, plants,
// schedule tables), fingerprinted now.
std::vector<InputFile> fingerprint_inputs(
    const std::vector<std::pair<std::string, std::string>>& key_paths);
// "model.calibration (models/x.toml) changed since DIR's run" for each input of `earlier`
// whose file now differs (or is gone); empty if none.
std::vector<std::string> changed_inputs(const std::vector<InputFile>& earlier);

// The current time in UTC, ISO 8601 ("2026-11-24T00:15:55Z").
std::string utc_timestamp();

// Keeps the process's command line for the provenance (main() calls it first).
void record_command_line(int argc, const char* const* argv);
const std::vector<std::string>& command_line();

// Input files as JSON ({key, path, bytes, fnv1a64} each), and back (throws
// nlohmann::json::exception on a malformed entry).
nlohmann::json inputs_to_json(const std::vector<InputFile>& inputs);
std::vector<InputFile> inputs_from_json(const nlohmann::json& j);

// A database that resumes (tuning, identification) keeps its scenarios' input files in meta
// "inputs" (this entry, fingerprinted now); refuse_changed_inputs, given that entry's value
// on resume, throws InputError "<db_path>: <key> (<path>) changed since this <what> began;
// ... start a new --db" when one of them changed (an entry of an older pamsim: none kept).
std::pair<std::string, std::string> inputs_meta(
    const std::vector<std::pair<std::string, std::string>>& key_paths);
void refuse_changed_inputs(const std::string& db_path, const std::string& stored,
                           const std::string& what);

// What a run's database records of what made it, as meta entries: pamsim_version,
// git_commit, mujoco_version, sundials_version, command_line (JSON), created_utc.
std::vector<std::pair<std::string, std::string>> database_provenance_meta();

struct TrialTiming {
  std::uint64_t seed = 0;
  double wall_time_s = 0;
  double realtime_factor = 0;  // simulated s per wall-clock s
};

// A trial's wall time and real-time factor, from its summary's timing metrics.
TrialTiming timing_of(const TrialSummary& summary);

struct Provenance {
  std::string command;                 // "run", "validate", ...
  std::string scenario_file;           // as given on the command line
  std::vector<std::string> overrides;  // --set key=value, in order
  std::string from;                    // `run --from DIR`: the folder it reproduces
  std::vector<std::uint64_t> seeds;
  int threads = 1;
  std::string started_utc;  // ISO 8601
  double wall_time_s = 0;   // the whole command
  std::vector<TrialTiming> trials;
  std::vector<InputFile> inputs;  // the files the scenario read
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
