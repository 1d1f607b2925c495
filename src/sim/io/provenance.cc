// provenance.cc: see provenance.h.
#include "sim/io/provenance.h"

#include <chrono>
#include <cmath>
#include <ctime>
#include <cstdio>
#include <filesystem>

#include "base/atomic_file.h"
#include "base/input_error.h"
#include "base/toml_file.h"
#include "sim/io/build_info.h"
#include "sim/io/outputs.h"  // number_or_null

namespace pamsim {
namespace {

std::vector<std::string>& recorded_command_line() {
  static std::vector<std::string> line;
  return line;
}

}  // namespace

std::uint64_t fnv1a64(const std::string& bytes) {
  std::uint64_t h = 1469598103934665603ull;
  for (const unsigned char c : bytes) h = (h ^ c) * 1099511628211ull;
  return h;
}

namespace {

std::string hex64(std::uint64_t v) {
  char buf[17];
  std::snprintf(buf, sizeof(buf), "%016llx", static_cast<unsigned long long>(v));
  return buf;
}

// The file's size and fingerprint; false if it is not a readable regular file of bounded
// size (read_text_file: a path in a hand-edited provenance.json to /dev/zero is refused,
// not read forever).
bool fingerprint(const std::string& path, std::uint64_t* bytes, std::string* hash) {
  if (path == "-") return false;  // standard input: nothing to read again
  std::string text;
  try {
    text = read_text_file(path);
  } catch (const InputError&) {
    return false;
  }
  *bytes = text.size();
  *hash = hex64(fnv1a64(text));
  return true;
}

}  // namespace

std::vector<InputFile> fingerprint_inputs(
    const std::vector<std::pair<std::string, std::string>>& key_paths) {
  std::vector<InputFile> inputs;
  for (const auto& [key, path] : key_paths) {
    InputFile f{key, path, 0, ""};
    if (fingerprint(path, &f.bytes, &f.fnv1a64)) inputs.push_back(f);
  }
  return inputs;
}

std::vector<std::string> changed_inputs(const std::vector<InputFile>& earlier) {
  std::vector<std::string> changed;
  for (const InputFile& f : earlier) {
    std::uint64_t bytes = 0;
    std::string hash;
    const bool readable = fingerprint(f.path, &bytes, &hash);
    if (!readable) {
      changed.push_back(f.key + " (" + f.path + ") is gone or not a readable file");
    } else if (bytes != f.bytes || hash != f.fnv1a64) {
      changed.push_back(f.key + " (" + f.path + ") changed");
    }
  }
  return changed;
}

nlohmann::json inputs_to_json(const std::vector<InputFile>& inputs) {
  nlohmann::json out = nlohmann::json::array();
  for (const InputFile& f : inputs) {
    out.push_back({{"key", f.key}, {"path", f.path}, {"bytes", f.bytes}, {"fnv1a64", f.fnv1a64}});
  }
  return out;
}

std::vector<InputFile> inputs_from_json(const nlohmann::json& j) {
  std::vector<InputFile> out;
  for (const auto& f : j) {
    out.push_back({f.at("key").get<std::string>(), f.at("path").get<std::string>(),
                   f.at("bytes").get<std::uint64_t>(), f.at("fnv1a64").get<std::string>()});
  }
  return out;
}

std::pair<std::string, std::string> inputs_meta(
    const std::vector<std::pair<std::string, std::string>>& key_paths) {
  return {"inputs", inputs_to_json(fingerprint_inputs(key_paths)).dump()};
}

void refuse_changed_inputs(const std::string& db_path, const std::string& stored,
                           const std::string& what) {
  const auto j = nlohmann::json::parse(stored, nullptr, false);
  std::vector<InputFile> inputs;
  try {
    if (j.is_array()) inputs = inputs_from_json(j);
  } catch (const nlohmann::json::exception&) {
    throw InputError(db_path + ": its inputs entry is unreadable (a damaged database)");
  }
  const std::vector<std::string> changed = changed_inputs(inputs);
  if (!changed.empty()) {
    throw InputError(db_path + ": " + changed.front() + " since this " + what +
                     " began; its stored points belong to the model as it was: start a new --db");
  }
}

std::vector<std::pair<std::string, std::string>> database_provenance_meta() {
  return {{"pamsim_version", PAMSIM_VERSION},
          {"git_commit", build_info().git_commit},
          {"mujoco_version", build_info().mujoco_version},
          {"sundials_version", build_info().sundials_version},
          {"command_line", nlohmann::json(command_line()).dump()},
          {"created_utc", utc_timestamp()}};
}

std::string utc_timestamp() {
  const std::time_t t = std::chrono::system_clock::to_time_t(std::chrono::system_clock::now());
  std::tm tm{};
  gmtime_r(&t, &tm);
  char buf[32];
  std::strftime(buf, sizeof(buf), "%Y-%m-%dT%H:%M:%SZ", &tm);
  return buf;
}

TrialTiming timing_of(const TrialSummary& summary) {
  TrialTiming t;
  t.seed = summary.seed;
  t.wall_time_s = NAN;
  t.realtime_factor = NAN;
  for (const Metric& m : summary.metrics) {
    if (m.name == "wall_time_s") t.wall_time_s = m.value;
    if (m.name == "realtime_factor") t.realtime_factor = m.value;
  }
  return t;
}

void record_command_line(int argc, const char* const* argv) {
  recorded_command_line().assign(argv, argv + argc);
}

const std::vector<std::string>& command_line() { return recorded_command_line(); }

nlohmann::json provenance_to_json(const Provenance& p) {
  nlohmann::json trials = nlohmann::json::array();
  for (const TrialTiming& t : p.trials) {
    trials.push_back({{"seed", t.seed},
                      {"wall_time_s", number_or_null(t.wall_time_s)},
                      {"realtime_factor", number_or_null(t.realtime_factor)}});
  }
  const nlohmann::json inputs = inputs_to_json(p.inputs);
  nlohmann::json j = {{"format", "pamsim-provenance-1"},
                      {"command", p.command},
                      {"command_line", command_line()},
                      {"scenario_file", p.scenario_file},
                      {"overrides", p.overrides},
                      {"seeds", p.seeds},
                      {"threads", p.threads},
                      {"started_utc", p.started_utc},
                      {"wall_time_s", number_or_null(p.wall_time_s)},
                      {"trials", trials},
                      {"inputs", inputs},
                      {"build", build_info_json()}};
  if (!p.from.empty()) j["from"] = p.from;
  return j;
}

void write_provenance(const std::string& path, Provenance provenance,
                      std::chrono::steady_clock::time_point started) {
  provenance.wall_time_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  write_file_atomically(path, provenance_to_json(provenance).dump(2) + "\n");
}

Provenance read_provenance(const std::string& dir) {
  const std::string path = (std::filesystem::path(dir) / kProvenanceFile).string();
  const nlohmann::json j = nlohmann::json::parse(read_text_file(path), nullptr, false);
  if (j.is_discarded() || !j.is_object() || j.value("format", "") != "pamsim-provenance-1") {
    throw InputError(path + ": not a pamsim provenance file");
  }
  Provenance p;
  const auto field = [&](const char* name) -> const nlohmann::json& {
    if (!j.contains(name)) throw InputError(path + ": " + name + " is missing");
    return j.at(name);
  };
  try {
    p.command = field("command").get<std::string>();
    p.scenario_file = field("scenario_file").get<std::string>();
    p.overrides = field("overrides").get<std::vector<std::string>>();
    p.seeds = field("seeds").get<std::vector<std::uint64_t>>();
    p.threads = field("threads").get<int>();
    if (j.contains("from")) p.from = j.at("from").get<std::string>();
    if (j.contains("inputs")) p.inputs = inputs_from_json(j.at("inputs"));
    if (j.contains("build")) {
      p.pamsim_version = j.at("build").value("pamsim_version", "");
      p.git_commit = j.at("build").value("git_commit", "");
    }
  } catch (const nlohmann::json::exception& e) {
    throw InputError(path + ": a field has the wrong type (" + std::string(e.what()) + ")");
  }
  if (p.seeds.empty()) throw InputError(path + ": seeds is empty");
  return p;
}

}  // namespace pamsim
