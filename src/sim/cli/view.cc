// view.cc: `pamsim view SCENARIO [--set key=value ...] [--script FILE] [--record DIR]
// [--quality fast|default] [--force]`: the scenario's trial live in a window (sim/view/viewer.h);
// with --script the timed key presses and slider moves of a file (sim/view/view_script.h); with
// --record the trial shown last as a run folder that `pamsim run --from DIR` runs again. Everything
// the command reads is checked before the window opens: a bad scenario, script line or record
// folder is one line and exit 2, with nothing written. SIGINT/SIGTERM close the window as
// its button does (the record is still written), and the command exits with the signal's
// code.
#include <CLI/CLI.hpp>

#include <cstdio>
#include <iostream>
#include <memory>

#include "sim/cli/cli_options.h"
#include "sim/cli/commands.h"
#include "sim/cli/stop_signal.h"
#include "sim/io/staged_outputs.h"
#include "sim/render/scene_renderer.h"  // parse_render_quality
#include "sim/view/live_session.h"
#include "sim/view/viewer.h"

namespace pamsim {
namespace {

struct ViewCliOptions {
  std::string scenario;
  std::vector<std::string> overrides;
  std::string script;
  std::string record;
  std::string quality = "default";
  bool force = false;
};

const std::vector<std::string> kRecordOutputs = {"trajectory.csv", "summary.json", "scenario.toml",
                                                 "provenance.json", kLiveChangesFile};

void view(const ViewCliOptions& opt) {
  LiveSession session(opt.scenario, opt.overrides);
  ViewOptions options;
  options.quality = parse_render_quality(opt.quality);
  if (!opt.script.empty()) options.script = read_view_script(opt.script, session);
  if (!opt.record.empty() && !opt.force) refuse_earlier_outputs(opt.record, kRecordOutputs);
  StopOnSignal stop;
  options.stop_requested = [] { return stop_requested().load(); };
  const ViewStats stats = run_viewer(session, options);
  if (!opt.record.empty()) session.write_record(opt.record);
  char rate[64];
  std::snprintf(rate, sizeof(rate), "%.1f", stats.frames_per_s);
  std::cerr << "pamsim view: " << stats.frames << " frames in " << stats.wall_s << " s (" << rate
            << " frames/s, figures on), " << stats.simulated_s << " s of trials shown; " << stats.gl
            << "\n";
  if (!opt.record.empty()) std::cerr << "pamsim: record in " << opt.record << "\n";
  if (stop_signal() != 0) throw CommandExit(128 + stop_signal());
}

}  // namespace

void add_view_command(CLI::App& app) {
  auto opt = std::make_shared<ViewCliOptions>();
  CLI::App* cmd = app.add_subcommand(
      "view", "Watch a scenario's trial live: pause, step, slow motion, drop, reflex, sliders");
  cmd->add_option("scenario", opt->scenario, "Scenario file (TOML)")->required();
  add_overrides_option(cmd, &opt->overrides, "Override a scenario key: --set reflex.v_thr_mm_s=60");
  cmd->add_option("--script", opt->script,
                  "Timed key presses and slider moves, one per line: <time_s> <command> [arg]");
  cmd->add_option("--record", opt->record,
                  "Write the trial shown last as a run folder (pamsim run --from DIR)");
  cmd->add_option("--quality", opt->quality,
                  "fast (no shadows, reflections, skybox, multisampling) or default (the model's)")
      ->capture_default_str();
  cmd->add_flag("--force", opt->force, "Replace an earlier record in the --record folder");
  cmd->callback([opt] { view(*opt); });
}

}  // namespace pamsim
