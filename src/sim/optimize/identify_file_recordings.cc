// identify_file_recordings.cc: see identify_file_recordings.h.
#include "sim/optimize/identify_file_recordings.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <limits>
#include <optional>
#include <set>

#include "base/format.h"
#include "base/input_error.h"
#include "base/toml_file.h"
#include "sim/scenario/scenario_file.h"

namespace pamsim {
namespace {

namespace fs = std::filesystem;

// noise = { <channel> = floor }: a chosen channel's noise floor, > 0 in its unit
std::vector<double> read_noise(const TableEntry& e, const Recording& data,
                               const std::vector<std::size_t>& channels) {
  std::vector<double> noise(channels.size(), std::numeric_limits<double>::quiet_NaN());
  const toml::node* given = e.table.get("noise");
  if (given == nullptr) return noise;
  if (!given->is_table()) e.in.fail(e.where + "noise", "must be a table { <channel> = floor }");
  for (const auto& [name, value] : *given->as_table()) {
    const std::string key = e.where + "noise." + std::string(name.str());
    std::size_t i = 0;
    while (i < channels.size() && data.channels[channels[i]] != name.str()) ++i;
    if (i == channels.size()) e.in.fail(key, "is not a channel the recording is matched on");
    const std::optional<double> v = value.value<double>();
    if (!v || !(*v > 0.0) || !std::isfinite(*v)) {
      e.in.fail(key, "must be a noise floor > 0 in the channel's unit");
    }
    noise[i] = *v;
  }
  return noise;
}

bool is_name(const std::string& s) {
  if (s.empty()) return false;
  for (char c : s) {
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '_' && c != '-') return false;
  }
  return true;
}

// The channels a recording is matched on: those named, or every one it has, but never one of
// `inputs` (the commands that drive its trial).
std::vector<std::size_t> read_channels(const TableEntry& e, const Recording& data,
                                       const std::vector<std::string>& inputs) {
  const auto input = [&](const std::string& name) {
    return std::find(inputs.begin(), inputs.end(), name) != inputs.end();
  };
  std::vector<std::size_t> out;
  const std::vector<std::string> named = e.texts("channels", false);
  if (named.empty()) {
    for (std::size_t c = 0; c < data.channels.size(); ++c) {
      if (!input(data.channels[c])) out.push_back(c);
    }
    e.in.check(!out.empty(), e.where + "file", "holds no channel besides the logged commands");
    return out;
  }
  for (const std::string& name : named) {
    const std::size_t c = data.channel(name);
    if (c == data.channels.size()) {
      e.in.fail(e.where + "channels", "names " + name + ", which " + data.path + " does not hold");
    }
    if (input(name)) {
      e.in.fail(e.where + "channels",
                "names " + name + ", a command that drives the trial (commands = \"log\")");
    }
    if (std::find(out.begin(), out.end(), c) != out.end()) {
      e.in.fail(e.where + "channels", "names " + name + " twice");
    }
    out.push_back(c);
  }
  return out;
}

// commands = "log": for each muscle of the recording's scenario whose command column
// p_cmd_<label>_MPa it holds, the override that drives the muscle by it, held, into
// r->log_commands, then the controller switched off at 0 s; the columns into *columns.
void read_log_commands(const TableEntry& e, const IdentifyDefinition& def, IdentifyRecording* r,
                       std::vector<std::string>* columns) {
  std::vector<std::string> overrides = def.overrides;
  overrides.insert(overrides.end(), r->set.begin(), r->set.end());
  Scenario sc;
  try {
    sc = load_scenario_text(def.base_text, def.base_path, overrides);
  } catch (const InputError& err) {
    e.in.fail(e.where + "set", std::string("(") + err.what() + ")");
  }
  // the controller stays off for the whole recording, under an event name of its own
  for (const EventSpec& ev : sc.events) {
    e.in.check(ev.name != kLogCommandsEvent, e.where + "set",
               "names an event \"" + ev.name + "\", the name commands = \"log\" uses");
    e.in.check(ev.action != EventAction::kControllerOn, e.where + "set",
               "switches the controller on (" + ev.key +
                   "), but with commands = \"log\" the log's commands are the controller's");
  }
  const std::string file = toml_value_text(
      toml::value<std::string>(fs::absolute(r->data.path).lexically_normal().string()));
  std::string labels;
  for (const MuscleSpec& m : sc.muscles) {
    const std::string column = "p_cmd_" + m.label + "_MPa";
    labels += (labels.empty() ? "" : ", ") + column;
    if (r->data.channel(column) == r->data.channels.size()) continue;
    columns->push_back(column);
    r->log_commands.push_back(m.key + ".command={kind=\"table\", file=" + file + ", column=\"" +
                              column + "\", hold=true}");
  }
  e.in.check(
      !columns->empty(), e.where + "commands",
      "is \"log\", but " + r->data.path + " holds none of its muscles' commands (" + labels + ")");
  r->log_commands.push_back("events." + std::string(kLogCommandsEvent) +
                            ".action=\"controller_off\"");
  r->log_commands.push_back("events." + std::string(kLogCommandsEvent) + ".when.at_s=0");
}

IdentifyRecording read_recording(ConfigReader& in, const TableEntry& e,
                                 const IdentifyDefinition& def) {
  IdentifyRecording r;
  const std::string file = e.text("file", true);
  const fs::path path = fs::path(in.name()).parent_path() / file;
  try {
    r.data = read_recording_csv(fs::path(file).is_absolute() ? file : path.string());
  } catch (const InputError& err) {
    in.fail(e.where + "file", std::string("(") + err.what() + ")");
  }
  r.name = e.text("name", false, fs::path(file).stem().string());
  if (!is_name(r.name)) {
    in.fail(e.where + "name", "must be letters, digits, '_' or '-', got \"" + r.name + "\"");
  }
  r.set = e.texts("set", false);
  std::vector<std::string> inputs;
  if (e.text("commands", false, "scenario") == "log") read_log_commands(e, def, &r, &inputs);
  r.channels = read_channels(e, r.data, inputs);
  r.noise = read_noise(e, r.data, r.channels);
  r.weight = e.number("weight").value_or(1.0);       // > 0, by its row
  r.held_out = e.table["held_out"].value_or(false);  // true or false, by its row
  return r;
}

// Whether a fitted recording is matched on channel `name` (its noise floor then stands for
// a candidate's).
bool fitted_channel(const IdentifyDefinition& def, const std::string& name) {
  for (const IdentifyRecording& r : def.recordings) {
    if (r.held_out) continue;
    for (std::size_t c : r.channels) {
      if (r.data.channels[c] == name) return true;
    }
  }
  return false;
}

// A candidate's sample times: every 1 / rate_hz from 0 to its duration (the scenario's
// sim.duration_s unless it says).
std::vector<double> candidate_times(ConfigReader& in, const TableEntry& e,
                                    const IdentifyDefinition& def, const IdentifyRecording& c) {
  const double rate = e.number("rate_hz").value_or(100.0);  // in (0, 10000], by its row
  std::vector<std::string> overrides = def.overrides;
  overrides.insert(overrides.end(), c.set.begin(), c.set.end());
  double duration = 0.0;
  try {
    duration = load_scenario_text(def.base_text, def.base_path, overrides).duration_s;
  } catch (const InputError& err) {
    in.fail(e.where + "set", std::string("(") + err.what() + ")");
  }
  const double given = e.number("duration_s").value_or(duration);
  in.check(given <= duration, e.where + "duration_s",
           "must be at most its scenario's sim.duration_s, " + format_value(duration) + " s, got " +
               format_value(given));
  // (a bound on what a candidate holds: a 6 s trial at 100 Hz is 600 samples)
  constexpr double kMaxSamples = 1e6;
  in.check(rate * given <= kMaxSamples, e.where + "rate_hz",
           "x duration_s gives " + format_value(std::floor(rate * given) + 1) +
               " samples, more than the 1000000 a candidate may hold");
  std::vector<double> times;
  for (std::size_t k = 0; static_cast<double>(k) / rate <= given + 1e-9; ++k) {
    times.push_back(static_cast<double>(k) / rate);
  }
  return times;
}

IdentifyRecording read_candidate(ConfigReader& in, const TableEntry& e,
                                 const IdentifyDefinition& def) {
  IdentifyRecording c;
  c.name = e.text("name", true);
  if (!is_name(c.name)) {
    in.fail(e.where + "name", "must be letters, digits, '_' or '-', got \"" + c.name + "\"");
  }
  c.set = e.texts("set", false);
  c.data.path = "candidate " + c.name;
  c.data.channels = e.texts("channels", false);
  in.check(!c.data.channels.empty(), e.where + "channels",
           "must name at least one channel a lab could log (trajectory.csv's columns)");
  c.data.time_s = candidate_times(in, e, def, c);
  for (std::size_t k = 0; k < c.data.channels.size(); ++k) {
    in.check(std::count(c.data.channels.begin(), c.data.channels.end(), c.data.channels[k]) == 1,
             e.where + "channels", "names " + c.data.channels[k] + " twice");
    c.channels.push_back(k);
    c.data.samples.emplace_back(c.data.time_s.size(), 0.0);
  }
  c.noise = read_noise(e, c.data, c.channels);
  for (std::size_t k = 0; k < c.channels.size(); ++k) {
    in.check(!std::isnan(c.noise[k]) || fitted_channel(def, c.data.channels[k]), e.where + "noise",
             "gives no floor for " + c.data.channels[k] + ", which no fitted recording measures");
  }
  return c;
}

}  // namespace

const std::vector<EntryKey>& tensile_entry_keys() {
  static const std::vector<EntryKey> keys = {
      {"muscle", "", "a muscle of the base scenario", "(required)",
       "the muscle whose plant the tensile test measured", EntryType::kText},
      {"file", "", "a tensile CSV (pamsim tensile's columns), relative to this file", "(required)",
       "the static test's rows, fitted with the recordings", EntryType::kText},
      {"weight", "", "", "1.0", "its share of the cost", EntryType::kNumber, kPositiveRange}};
  return keys;
}

const std::vector<EntryKey>& recording_entry_keys() {
  static const std::vector<EntryKey> keys = {
      {"file", "", "a recording CSV (time_s and trajectory.csv's columns), relative to this file",
       "(required)", "the lab's recording", EntryType::kText},
      {"name", "", "letters, digits, '_' or '-'; unique", "(the file's stem)",
       "its name in the outputs", EntryType::kText},
      {"set", "", "list of \"key=value\" scenario overrides", "[]",
       "what made this recording: a command schedule, an event, a mass", EntryType::kTexts},
      {"channels", "", "list of the file's columns", "(every column)",
       "the channels the fit matches", EntryType::kTexts},
      {"weight", "", "", "1.0", "its share of the cost", EntryType::kNumber, kPositiveRange},
      {"held_out", "", "", "false", "kept out of the fit, used for the held-out check",
       EntryType::kBool},
      {"noise", "(each channel's)", "{ <channel> = floor > 0 }", "(estimated from the recording)",
       "each channel's noise floor, in its unit", EntryType::kTable},
      {"commands",
       "",
       "log: the file holds p_cmd_<label>_MPa columns",
       "\"scenario\"",
       "what drives the valves: the scenario's schedules, or the log's own commands, each held "
       "from row to row as a regulator holds it, the controller off",
       EntryType::kChoice,
       {},
       {"scenario", "log"}}};
  return keys;
}

std::vector<std::string> IdentifyRecording::conditions() const {
  std::vector<std::string> out = set;
  out.insert(out.end(), log_commands.begin(), log_commands.end());
  return out;
}

const std::vector<EntryKey>& candidate_entry_keys() {
  static const std::vector<EntryKey> keys = {
      {"name", "", "letters, digits, '_' or '-'; unique", "(required)",
       "an experiment a lab could run, for --plan", EntryType::kText},
      {"set", "", "list of \"key=value\" scenario overrides", "[]",
       "what it would do: a command schedule, an event, a mass", EntryType::kTexts},
      {"channels", "", "list of trajectory.csv's columns, at least one", "(required)",
       "the channels it would log", EntryType::kTexts},
      {"rate_hz",
       "Hz",
       "",
       "100.0",
       "their sampling rate",
       EntryType::kNumber,
       {0.0, 10000.0, true, false}},
      {"duration_s", "s", "at most its scenario's sim.duration_s", "(sim.duration_s)",
       "how long it would log", EntryType::kNumber, kPositiveRange},
      {"noise", "(each channel's)", "{ <channel> = floor > 0 }", "(a fitted recording's floor)",
       "each channel's noise floor, in its unit", EntryType::kTable}};
  return keys;
}

void read_recordings(ConfigReader& in, IdentifyDefinition* def) {
  const TableArray tables(in, "recording");
  std::set<std::string> names;
  for (const TableEntry& e : tables.entries(recording_entry_keys())) {
    def->recordings.push_back(read_recording(in, e, *def));
    const IdentifyRecording& r = def->recordings.back();
    in.check(names.insert(r.name).second, e.where + "name", "\"" + r.name + "\" is taken");
  }
}

void read_candidates(ConfigReader& in, IdentifyDefinition* def) {
  const TableArray tables(in, "candidate");
  std::set<std::string> names;
  for (const TableEntry& e : tables.entries(candidate_entry_keys())) {
    def->candidates.push_back(read_candidate(in, e, *def));
    const IdentifyRecording& c = def->candidates.back();
    in.check(names.insert(c.name).second, e.where + "name", "\"" + c.name + "\" is taken");
  }
}

}  // namespace pamsim
