// controller.cc: `pamsim controller export` and `pamsim controller replay`: the scenario's
// controller as the embedded C library a board runs (src/embedded/pamctl.h), exported with
// its settings, and that library driven by a logged stream of readings (docs/embedded.md).
//   pamsim controller export SCENARIO [--set key=value ...] [-o DIR] [--force]
//   pamsim controller replay LOG (--export DIR | --scenario FILE [--set ...]) [--out DIR]
//                           [--force] [--no-plot]
#include <CLI/CLI.hpp>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <sstream>

#include "base/atomic_file.h"
#include "base/format.h"
#include "base/input_error.h"
#include "base/toml_file.h"
#include "sim/cli/cli_options.h"
#include "sim/cli/commands.h"
#include "sim/core/trial_model.h"
#include "sim/io/build_info.h"
#include "sim/io/controller_export.h"
#include "sim/io/controller_replay.h"
#include "sim/io/embedded_config.h"
#include "sim/io/plot.h"
#include "sim/io/provenance.h"
#include "sim/io/staged_outputs.h"
#include "sim/scenario/scenario_file.h"

namespace pamsim {
// (a named namespace: the unity build joins this file with the other commands')
namespace controller_command {

namespace fs = std::filesystem;

struct ControllerExportOptions {
  std::string scenario;
  std::vector<std::string> overrides;
  std::string out;
  bool force = false;
};

struct ControllerReplayOptions {
  std::string log;
  std::string export_dir;
  std::string scenario;
  std::vector<std::string> overrides;
  std::string out = "renders/controller_replay";
  bool force = false;
  bool no_plot = false;
};

// A scenario's controller as the embedded controller holds it, with its muscles' labels
struct EmbeddedScenario {
  Scenario scenario;
  TrialModel model;
  pamctl_config config{};
  std::vector<std::string> muscles;
};

EmbeddedScenario embedded_scenario(const std::string& path,
                                   const std::vector<std::string>& overrides) {
  EmbeddedScenario e{load_scenario(path, overrides), {}, {}, {}};
  e.model = load_trial_model(e.scenario);
  const std::string why = embedded_controller_config(e.model, e.scenario, &e.config);
  if (!why.empty()) {
    throw InputError(path + ": controller.kind = " + e.scenario.controller_kind + ": " + why);
  }
  const std::int32_t code = pamctl_check_config(&e.config);
  if (code != 0)
    throw InputError(path + ": the embedded controller refuses " +
                     std::string(pamctl_config_error(code)));
  for (const BoundMuscle& m : e.model.muscles) e.muscles.push_back(m.label);
  return e;
}

void run_export(const ControllerExportOptions& opt) {
  const std::string out = !opt.out.empty()
                              ? opt.out
                              : "renders/" + fs::path(opt.scenario).stem().string() + "_controller";
  const EmbeddedScenario e = embedded_scenario(opt.scenario, opt.overrides);
  // the generated files name what made them: the resolved scenario's digest and pamsim
  const std::string resolved =
      resolved_scenario_toml(read_text_file(opt.scenario), opt.scenario, opt.overrides, out, "");
  char digest[32];
  std::snprintf(digest, sizeof(digest), "%016llx",
                static_cast<unsigned long long>(fnv1a64(resolved)));
  std::string set;
  for (const std::string& o : opt.overrides) set += " --set " + o;
  const BuildInfo build = build_info();
  const std::string comment = "From " + opt.scenario + set + " (resolved scenario fnv1a64 " +
                              digest + ") by pamsim " + build.pamsim_version + " (" +
                              build.git_commit + "), pamctl " PAMCTL_VERSION ".";
  write_controller_export(out, e.config, e.muscles, comment, opt.force);
  std::cout << "pamsim: the controller of " << opt.scenario << " (" << e.scenario.controller_kind
            << ", " << e.muscles.size() << " muscles) exported into " << out
            << "; build it with make -C " << out << "\n";
}

// the scheduled commands where the log has none: the scenario's schedules at each tick
void fill_goal_pressures(const EmbeddedScenario* e, const std::vector<std::string>& muscles,
                         const std::string& log, ControlStream* s) {
  for (std::size_t j = 0; j < s->muscles.size(); ++j) {
    MuscleStream& m = s->muscles[j];
    if (!m.p_tp_pa.empty()) continue;
    if (!e) {
      throw InputError(log + ": no column p_tp_" + muscles[j] + "_Pa or p_tp_" + muscles[j] +
                       "_MPa (the scheduled commands): give them, or replay with --scenario, "
                       "whose schedules give them");
    }
    const PressureSchedule& schedule = e->scenario.muscles[e->model.muscles[j].spec].command;
    for (double t : s->time_s) m.p_tp_pa.push_back(schedule.at(t));
  }
}

nlohmann::json replay_json(const ReplaySummary& r, const std::vector<std::string>& muscles) {
  nlohmann::json j;
  j["ticks"] = r.ticks;
  j["flagged_ticks"] = r.flagged_ticks;
  j["status"] = r.status;
  for (std::size_t m = 0; m < muscles.size(); ++m) {
    j["stretch_triggers_s"][muscles[m]] = r.stretch_triggers_s[m];
    j["tension_triggers_s"][muscles[m]] = r.tension_triggers_s[m];
  }
  const ReplayComparison& c = r.comparison;
  j["compared"] = c.compared;
  if (c.compared) {
    j["commands_equal"] = c.first_differing_tick < 0;
    j["first_differing_tick"] = c.first_differing_tick;
    if (c.first_differing_tick >= 0) j["first_differing_time_s"] = c.first_differing_time_s;
    j["largest_difference_MPa"] = c.largest_difference_pa / 1e6;
    j["largest_difference_muscle"] = c.largest_muscle;
  }
  return j;
}

void run_replay(const ControllerReplayOptions& opt) {
  if (opt.export_dir.empty() == opt.scenario.empty()) {
    throw InputError("controller replay needs the controller: --export DIR or --scenario FILE");
  }
  // the controller: an export's configuration, or a scenario's
  std::unique_ptr<EmbeddedScenario> e;
  pamctl_config config{};
  std::vector<std::string> muscles;
  if (!opt.scenario.empty()) {
    e = std::make_unique<EmbeddedScenario>(embedded_scenario(opt.scenario, opt.overrides));
    config = e->config;
    muscles = e->muscles;
  } else {
    const std::string path = (fs::path(opt.export_dir) / "pamctl_config.json").string();
    nlohmann::json j;
    try {
      j = nlohmann::json::parse(read_text_file(path));
    } catch (const nlohmann::json::parse_error& err) {
      throw InputError(path + ": not JSON (" + err.what() + ")");
    }
    config = embedded_config_from_json(j, path, &muscles);
  }
  // the log, at the controller's rate, with its goal pressures
  ControlStream stream = read_control_stream(read_text_file(opt.log), opt.log, muscles);
  check_control_rate(stream, config.control_period_s, opt.log);
  fill_goal_pressures(e.get(), muscles, opt.log, &stream);
  if (!stream.has_enabled) {
    std::cerr << "pamsim: " << opt.log
              << " has no enabled column: the reflexes are on "
                 "throughout\n";
  }
  if (stream.missing_readings > 0) {
    std::cerr << "pamsim: " << opt.log << ": " << stream.missing_readings << " missing readings "
              << "(nan or empty) handed to the controller as NaN (it holds that muscle's "
                 "estimate and flags the tick)\n";
  }
  const std::vector<std::string> outputs = {"replay.csv", "replay.json", "replay.png"};
  if (!opt.force) refuse_earlier_outputs(opt.out, outputs);
  std::ostringstream csv;
  const ReplaySummary summary = replay_controller(config, muscles, stream, &csv);
  StagedOutputs staged(opt.out, outputs);
  const bool plots = plots_wanted(opt.no_plot);
  staged.write([&] {
    write_file_atomically(staged.path("replay.csv"), csv.str());
    write_file_atomically(staged.path("replay.json"), replay_json(summary, muscles).dump(2) + "\n");
    if (plots) write_replay_plot(staged.path("replay.png"), csv.str(), config, muscles, stream);
  });
  staged.publish();
  std::cout << replay_json(summary, muscles).dump(2) << "\n";
  std::cerr << "pamsim: outputs in " << opt.out << "\n";
}

}  // namespace controller_command

using namespace controller_command;

void add_controller_command(CLI::App& app) {
  CLI::App* cmd = app.add_subcommand(
      "controller", "The controller as the embedded C library a board runs: export, replay");
  cmd->require_subcommand(1);
  const auto [exp, eo] = add_command<ControllerExportOptions>(
      *cmd, "export", "Write the scenario's controller as C sources and a build file", run_export);
  exp->add_option("scenario", eo->scenario, "Scenario file, or a best.toml of tune or report")
      ->required();
  add_overrides_option(exp, &eo->overrides, "Override a scenario key: --set reflex.v_thr_mm_s=60");
  exp->add_option("-o,--out", eo->out, "Export folder (default renders/<scenario>_controller)");
  exp->add_flag("--force", eo->force, "Replace an earlier export in the folder");
  const auto [rep, ro] = add_command<ControllerReplayOptions>(
      *cmd, "replay", "Drive the embedded controller with a log of its readings", run_replay);
  rep->add_option("log", ro->log,
                  "readings.csv (pamsim run --readings), trajectory.csv or a "
                  "lab's log with the same columns")
      ->required();
  rep->add_option("--export", ro->export_dir, "An export folder (pamsim controller export)");
  rep->add_option("--scenario", ro->scenario, "Or a scenario whose controller to run");
  add_overrides_option(rep, &ro->overrides, "Override a key of --scenario");
  rep->add_option("--out", ro->out, "Output folder")->capture_default_str();
  rep->add_flag("--force", ro->force, "Replace an earlier replay's outputs in the folder");
  rep->add_flag("--no-plot", ro->no_plot, "Write no plot (gnuplot not needed)");
}

}  // namespace pamsim
