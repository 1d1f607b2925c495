// live_record.cc: a live trial's record (LiveSession::write_record, live_session.h): a run
// folder as `pamsim run` writes it, its scenario.toml holding the live changes as keys, and
// view_changes.json listing them; and what `run --from` says of the changes it cannot hold.
#include <nlohmann/json.hpp>

#include <chrono>
#include <filesystem>
#include <fstream>

#include "base/atomic_file.h"
#include "base/format.h"
#include "base/input_error.h"
#include "sim/io/outputs.h"
#include "sim/io/provenance.h"
#include "sim/io/staged_outputs.h"
#include "sim/scenario/scenario_file.h"
#include "sim/view/live_session.h"

namespace pamsim {
namespace {

nlohmann::json changes_json(const std::vector<LiveChange>& changes) {
  nlohmann::json list = nlohmann::json::array();
  for (const LiveChange& c : changes) {
    list.push_back({{"tick", c.tick},
                    {"time_s", c.time_s},
                    {"change", c.what},
                    {"scenario_keys", c.keys},
                    {"reproduced_by_run_from", c.why_not.empty()},
                    {"why_not", c.why_not}});
  }
  return {{"changes", list}};
}

}  // namespace

void LiveSession::write_record(const std::string& dir) {
  const auto started = std::chrono::steady_clock::now();
  const bool ended_early = !done();
  const double end_s = time_s();
  Provenance provenance;
  provenance.command = "view";
  provenance.started_utc = utc_timestamp();
  provenance.scenario_file = path_;
  provenance.seeds = {seed_};
  provenance.overrides = overrides_;
  provenance.overrides.push_back("seed=" + std::to_string(seed_));
  for (const LiveChange& c : changes_) {
    provenance.overrides.insert(provenance.overrides.end(), c.keys.begin(), c.keys.end());
  }
  // a trial closed before its end is the scenario's trial ended there by an event
  if (ended_early) {
    const std::string e = event_key();
    provenance.overrides.push_back(e + ".action=end");
    provenance.overrides.push_back(e + ".when.at_s=" + format_shortest(end_s));
  }
  const std::string header =
      "# The scenario of a trial watched live with pamsim view " PAMSIM_VERSION " from " + path_ +
      ",\n# its live changes as keys (view_changes.json lists them); pamsim run --from "
      "<this folder> runs it again\n";
  RecordedScenario recorded =
      load_recorded_scenario(text_, path_, provenance.overrides, dir, header);
  recorded.scenario.path = path_;
  provenance.inputs = fingerprint_inputs(recorded.input_paths);
  const TrialResult result = trial_->finish();
  StagedOutputs staged(dir, {"trajectory.csv", "summary.json", kResolvedScenarioFile,
                             kProvenanceFile, kLiveChangesFile});
  staged.write([&] {
    write_trial_outputs(staged.staging(), result, recorded.scenario);
    write_file_atomically(staged.path(kResolvedScenarioFile), recorded.resolved_toml);
    write_file_atomically(staged.path(kLiveChangesFile), changes_json(changes_).dump(2) + "\n");
    write_provenance(staged.path(kProvenanceFile), provenance, started);
  });
  staged.publish();
}

std::vector<std::string> unreproduced_live_changes(const std::string& dir) {
  const std::filesystem::path file = std::filesystem::path(dir) / kLiveChangesFile;
  std::vector<std::string> lines;
  if (!std::filesystem::exists(file)) return lines;
  std::ifstream in(file);
  const nlohmann::json j = nlohmann::json::parse(in, nullptr, false);
  if (j.is_discarded() || !j.contains("changes") || !j["changes"].is_array()) {
    throw InputError(file.string() + ": not a list of live changes (pamsim view --record)");
  }
  for (const nlohmann::json& c : j["changes"]) {
    if (c.value("reproduced_by_run_from", true)) continue;
    lines.push_back(dir + ": the live change at t = " + format_value(c.value("time_s", 0.0)) +
                    " s (" + c.value("change", std::string("?")) +
                    ") is not reproduced: " + c.value("why_not", std::string("?")));
  }
  return lines;
}

}  // namespace pamsim
