// identify_file.cc: see identify_file.h.
#include "sim/optimize/identify_file.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <limits>
#include <optional>
#include <set>

#include <nlohmann/json.hpp>

#include "base/config_reader.h"
#include "base/format.h"
#include "base/input_error.h"
#include "sim/core/trial.h"
#include "sim/core/trial_model.h"
#include "pam_actuator/tensile_csv.h"
#include "sim/optimize/identify_file_recordings.h"
#include "sim/scenario/scenario_file.h"

namespace pamsim {
namespace {

namespace fs = std::filesystem;

void read_tensile(ConfigReader& in, IdentifyDefinition* def) {
  const TableArray tables(in, "tensile");
  for (const TableEntry& e : tables.entries(tensile_entry_keys())) {
    IdentifyTensile t;
    t.muscle = e.text("muscle", true);
    const std::string file = e.text("file", true);
    t.file =
        fs::path(file).is_absolute() ? file : (fs::path(in.name()).parent_path() / file).string();
    try {
      t.rows = read_tensile_csv(t.file);
    } catch (const InputError& err) {
      in.fail(e.where + "file", std::string("(") + err.what() + ")");
    }
    t.weight = e.number("weight").value_or(1.0);  // > 0, by its row
    def->tensile.push_back(std::move(t));
  }
}

// Each tensile test's muscle is one of the base scenario's, with a plant file.
void check_tensile(const IdentifyDefinition& def) {
  if (def.tensile.empty()) return;
  std::vector<double> middle;
  for (const SearchParameter& p : def.parameters) middle.push_back(value_at(p, 0.5));
  const Scenario sc = load_scenario_text(def.base_text, def.base_path, def.overrides_at(middle));
  for (std::size_t i = 0; i < def.tensile.size(); ++i) {
    const std::string where = def.file + ": tensile[" + std::to_string(i) + "].muscle ";
    std::string names;
    const MuscleSpec* found = nullptr;
    for (const MuscleSpec& m : sc.muscles) {
      names += (names.empty() ? "" : ", ") + m.actuator;
      if (m.actuator == def.tensile[i].muscle) found = &m;
    }
    if (!found) {
      throw InputError(where + "\"" + def.tensile[i].muscle +
                       "\" is not a muscle of the base "
                       "scenario (it has " +
                       names + ")");
    }
    if (found->plant_file.empty()) {
      throw InputError(where + "\"" + found->actuator + "\" has no plant file (muscles." +
                       found->actuator + ".plant): its law is the estimator's");
    }
  }
}

// "channel.<column>.<kind>" parameters: their kind and column, each column one the recordings
// match, a gain's range above 0 and a delay's within [0, 1000] ms.
void read_channel_parameters(ConfigReader& in, IdentifyDefinition* def) {
  using Kind = ChannelParameter::Kind;
  for (std::size_t i = 0; i < def->parameters.size(); ++i) {
    const SearchParameter& p = def->parameters[i];
    ChannelParameter c;
    const std::string where = "parameter[" + std::to_string(i) + "].key";
    if (p.key.rfind("channel.", 0) == 0) {
      const std::size_t dot = p.key.rfind('.');
      const std::string kind = p.key.substr(dot + 1);
      c.column = p.key.substr(8, dot > 8 ? dot - 8 : 0);
      c.kind = kind == "offset"     ? Kind::kOffset
               : kind == "gain"     ? Kind::kGain
               : kind == "delay_ms" ? Kind::kDelay
                                    : Kind::kNone;
      in.check(c.kind != Kind::kNone && !c.column.empty(), where,
               "\"" + p.key +
                   "\": a channel's parameter is channel.<column>.offset, .gain or .delay_ms");
      bool matched = false;
      for (const IdentifyRecording& r : def->recordings) {
        for (std::size_t k : r.channels) matched = matched || r.data.channels[k] == c.column;
      }
      in.check(matched, where, "\"" + p.key + "\": no recording matches " + c.column);
      in.check(c.kind != Kind::kGain || p.from > 0, where,
               "\"" + p.key + "\": a gain's range must be above 0");
      in.check(c.kind != Kind::kDelay || (p.from >= 0 && p.to <= 1000), where,
               "\"" + p.key + "\": a delay's range must lie within [0, 1000] ms");
    }
    def->channel_parameters.push_back(c);
  }
}

// The settings a recording's scenario is checked at: every parameter mid-box, then each at
// its bounds with the others mid-box.
std::vector<std::vector<double>> checked_settings(const IdentifyDefinition& def) {
  std::vector<double> middle;
  for (const SearchParameter& p : def.parameters) middle.push_back(value_at(p, 0.5));
  std::vector<std::vector<double>> out = {middle};
  for (std::size_t i = 0; i < def.parameters.size(); ++i) {
    for (double u : {0.0, 1.0}) {
      out.push_back(middle);
      out.back()[i] = value_at(def.parameters[i], u);
    }
  }
  return out;
}

// `recording`'s scenario at each checked setting loads and binds its model (InputError
// "<where>: ..." otherwise); the one mid-box is returned.
Scenario checked_scenario(const IdentifyDefinition& def, const IdentifyRecording& r,
                          const std::string& where) {
  Scenario middle;
  for (const std::vector<double>& values : checked_settings(def)) {
    try {
      Scenario sc = load_scenario_text(def.base_text, def.base_path, def.overrides_at(r, values));
      load_trial_model(sc);
      if (middle.path.empty()) middle = std::move(sc);
    } catch (const InputError& e) {
      throw InputError(where + ": " + e.what());
    }
  }
  return middle;
}

// `r`'s scenario loads with the parameters mid-box and at each bound, logs its channels and
// lasts as long as the recording; `where` names it in a refusal.
void check_recording(const IdentifyDefinition& def, const IdentifyRecording& r,
                     const std::string& where) {
  for (const std::string& s : r.set) {
    for (const SearchParameter& p : def.parameters) {  // (a channel. key is never a set's)
      if (s.rfind(p.key + "=", 0) == 0)
        throw InputError(where + ": set gives " + p.key + ", a parameter");
    }
  }
  const Scenario sc = checked_scenario(def, r, where);
  const std::vector<std::string> logged = trial_log_layout(load_trial_model(sc), sc).columns;
  for (std::size_t c : r.channels) {
    const std::string& name = r.data.channels[c];
    if (std::find(logged.begin(), logged.end(), name) == logged.end()) {
      throw InputError(where + ": channel " + name +
                       " is not a column pamsim logs for this "
                       "scenario (trajectory.csv's columns)");
    }
  }
  if (r.data.time_s.back() > sc.duration_s + 1e-9) {
    throw InputError(where + ": the recording lasts " + format_value(r.data.time_s.back()) +
                     " s, its scenario " + format_value(sc.duration_s) + " s (set sim.duration_s)");
  }
}

// Every recording and candidate, checked (check_recording).
void check_recordings(const IdentifyDefinition& def) {
  for (std::size_t i = 0; i < def.recordings.size(); ++i) {
    const IdentifyRecording& r = def.recordings[i];
    check_recording(def, r, def.file + ": recording[" + std::to_string(i) + "] (" + r.name + ")");
  }
  for (std::size_t i = 0; i < def.candidates.size(); ++i) {
    const IdentifyRecording& c = def.candidates[i];
    check_recording(def, c, def.file + ": candidate[" + std::to_string(i) + "] (" + c.name + ")");
  }
}

}  // namespace

KeyTable identify_search_table(IdentifyDefinition* def) {
  KeyTable t{"", {}, {}, {}};
  t.ints = {
      int_row("generations",
              "CMA-ES generations of the global search (0: none, the polish starts from the "
              "middle of the box)",
              0, 1000, &def->generations),
      int_row("population", "CMA-ES population", 5, 1000, &def->population),
      int_row("seed", "CMA-ES seed (pagmo's seeds are 32-bit)", 0, 4294967295LL, &def->seed),
      int_row("polish_iterations", "Levenberg-Marquardt iterations of the local polish (Ceres)", 0,
              1000, &def->polish_iterations),
      int_row("starts",
              "the polish's starts: each run's best point, then the runs' best points at "
              "least 0.1 of the box from every start before (the lowest end is the result; "
              "one that ends higher is reported as a local minimum)",
              1, 20, &def->starts),
      int_row("runs",
              "independent runs of the global search, run r with seed + r and population x 2^r "
              "(IPOP-CMA-ES's restarts), each run's best point polished; when the fit is above "
              "the noise, runs that ended apart say the search did not settle, not the model",
              1, 8, &def->runs),
      int_row("stall_generations",
              "a run of the global search ends once its best cost has fallen by less than 0.1 % "
              "plus 1 (the cost is in noise floors squared) over this many generations in a "
              "row; generations is then the most it runs (0: every generation)",
              0, 1000, &def->stall_generations)};
  t.ints[1].fallback_doc =
      "(the larger of 8 and 4 + floor(3 ln m), m the parameters CMA-ES moves: the offsets "
      "it sets aside not counted)";
  t.bools = {{"profile_offsets",
              "the global search leaves each channel's offset (on a linear scale) to its "
              "least-squares value at every point, searching only the other parameters "
              "(variable projection); the polish fits all together",
              &def->profile_offsets}};
  t.numbers = {
      {"interval",
       "",
       1.0,
       {0.0, 1.0, true, true},
       "the level of the parameters' reported intervals",
       &def->interval},
      {"explained_noise_factor",
       "",
       1.0,
       {1.0, 1000.0, false, false},
       "a fitted channel is explained when its RMS after the fit is at most this many noise "
       "floors (the model's own noise and the recording's make sqrt(2))",
       &def->explained_noise_factor}};
  return t;
}

unsigned default_population(const IdentifyDefinition& def) {
  std::size_t searched = 0;
  for (std::size_t k = 0; k < def.parameters.size(); ++k) searched += !def.offset_projected(k);
  if (searched == 0) return 8;
  const double hansen = 4.0 + std::floor(3.0 * std::log(static_cast<double>(searched)));
  return std::max(8u, static_cast<unsigned>(hansen));
}

bool IdentifyDefinition::offset_projected(std::size_t k) const {
  return profile_offsets && channel_parameters[k].kind == ChannelParameter::Kind::kOffset &&
         !parameters[k].log;
}

std::vector<std::string> IdentifyDefinition::overrides_at(const std::vector<double>& values) const {
  std::vector<std::string> out = overrides;
  for (std::size_t i = 0; i < parameters.size(); ++i) {
    if (channel_parameters[i].kind != ChannelParameter::Kind::kNone) continue;
    out.push_back(parameters[i].key + "=" + format_number(values[i]));
  }
  return out;
}

std::vector<std::string> IdentifyDefinition::overrides_at(const IdentifyRecording& recording,
                                                          const std::vector<double>& values) const {
  std::vector<std::string> out = overrides;
  const std::vector<std::string> conditions = recording.conditions();
  out.insert(out.end(), conditions.begin(), conditions.end());
  const std::vector<std::string> params = overrides_at(values);
  out.insert(out.end(), params.begin() + static_cast<std::ptrdiff_t>(overrides.size()),
             params.end());
  return out;
}

ChannelTransform IdentifyDefinition::transform_at(const IdentifyRecording& recording, std::size_t i,
                                                  const std::vector<double>& values) const {
  ChannelTransform t;
  const std::string& column = recording.data.channels[recording.channels[i]];
  for (std::size_t k = 0; k < parameters.size(); ++k) {
    const ChannelParameter& c = channel_parameters[k];
    if (c.kind == ChannelParameter::Kind::kNone || c.column != column) continue;
    if (c.kind == ChannelParameter::Kind::kOffset) t.offset = values[k];
    if (c.kind == ChannelParameter::Kind::kGain) t.gain = values[k];
    if (c.kind == ChannelParameter::Kind::kDelay) t.delay_s = values[k] * 1e-3;
  }
  return t;
}

std::vector<double> IdentifyDefinition::scenario_values(const std::vector<double>& values) const {
  std::vector<double> out;
  for (std::size_t i = 0; i < values.size(); ++i) {
    if (channel_parameters[i].kind == ChannelParameter::Kind::kNone) out.push_back(values[i]);
  }
  return out;
}

std::string IdentifyDefinition::canonical_json() const {
  const nlohmann::json params = search_parameters_json(parameters);
  nlohmann::json recs = nlohmann::json::array();
  for (const auto& r : recordings) {
    std::vector<std::string> channels;
    for (std::size_t c : r.channels) channels.push_back(r.data.channels[c]);
    recs.push_back({{"name", r.name},
                    {"set", r.set},
                    {"channels", channels},
                    {"weight", r.weight},
                    {"held_out", r.held_out},
                    {"time_s", r.data.time_s},
                    {"samples", r.data.samples},
                    {"noise", r.noise}});
    if (!r.log_commands.empty()) recs.back()["commands"] = "log";  // (older files' text kept)
  }
  nlohmann::json tensile_json = nlohmann::json::array();
  for (const auto& t : tensile) {
    std::vector<std::vector<double>> rows;
    for (const TensileRow& r : t.rows) {
      rows.push_back({r.pressure_mpa, r.length_mm, r.force_n,
                      r.direction == StrokeDirection::kLoading ? 1.0 : 0.0});
    }
    tensile_json.push_back({{"muscle", t.muscle}, {"weight", t.weight}, {"rows", rows}});
  }
  const nlohmann::json j = {{"base_scenario", base_text},
                            {"base_path", base_path},
                            {"overrides", overrides},
                            {"generations", generations},
                            {"population", population},
                            {"seed", seed},
                            {"polish_iterations", polish_iterations},
                            {"parameters", params},
                            {"recordings", recs},
                            // residuals over the channels' noise floors (pamsim 0.4): a
                            // database of an earlier scale does not resume
                            {"residual_scale", "noise_floor"}};
  // each added only where given, so that an older database (no tensile tests, one start, no
  // offset the search could project) resumes as it did
  const bool offsets = std::any_of(
      channel_parameters.begin(), channel_parameters.end(),
      [](const ChannelParameter& c) { return c.kind == ChannelParameter::Kind::kOffset; });
  if (tensile.empty() && starts == 1 && runs == 1 && stall_generations == 0 && !offsets) {
    return j.dump();
  }
  nlohmann::json with = j;
  if (!tensile.empty()) with["tensile"] = tensile_json;
  if (starts > 1) with["starts"] = starts;
  if (runs > 1) with["runs"] = runs;
  if (stall_generations > 0) with["stall_generations"] = stall_generations;
  if (offsets) with["profile_offsets"] = profile_offsets;
  return with.dump();
}

std::vector<std::pair<std::string, std::string>> identify_input_paths(
    const IdentifyDefinition& def) {
  std::vector<std::pair<std::string, std::string>> out;
  const std::string dir = fs::path(def.base_path).parent_path().string();
  auto add = [&](const std::vector<std::string>& overrides) {
    for (const auto& kp :
         load_recorded_scenario(def.base_text, def.base_path, overrides, dir, "").input_paths) {
      const bool seen =
          std::any_of(out.begin(), out.end(), [&](const auto& o) { return o.second == kp.second; });
      if (!seen) out.push_back(kp);
    }
  };
  add(def.overrides);
  for (const IdentifyRecording& r : def.recordings) {
    std::vector<std::string> o = def.overrides;
    const std::vector<std::string> conditions = r.conditions();
    o.insert(o.end(), conditions.begin(), conditions.end());
    add(o);
  }
  return out;
}

IdentifyDefinition load_identify_definition(const std::string& path) {
  ConfigReader in(path);
  IdentifyDefinition def;
  def.file = path;
  SearchBase base = read_search_base(in);
  def.base_path = std::move(base.path);
  def.base_text = std::move(base.text);
  def.overrides = std::move(base.overrides);
  const bool population_given = in.has("population");
  read_key_rows(in, identify_search_table(&def));
  def.parameters = read_search_parameters(in, {"seed"}, "a recording's noise is its own", false);
  read_recordings(in, &def);
  read_tensile(in, &def);
  read_channel_parameters(in, &def);
  if (!population_given) def.population = default_population(def);
  read_candidates(in, &def);
  const bool fitted = std::any_of(def.recordings.begin(), def.recordings.end(),
                                  [](const IdentifyRecording& r) { return !r.held_out; });
  in.check(fitted || !def.tensile.empty(), "recording",
           "needs at least one [[recording]] that is not held_out, or a [[tensile]]");
  in.reject_unknown();
  check_recordings(def);
  check_tensile(def);
  return def;
}

}  // namespace pamsim
