// hil.cc: `pamsim hil SCENARIO [--set key=value ...] (--udp HOST:PORT | --serial DEVICE
// [--baud N]) [--realtime] [--connect-timeout-s S] [--out DIR] [--force] [faults]`: the
// scenario's trial with a controller board closing the loop over a link (sim/hil/): the
// muscles' raw readings out at every control tick, the board's valve commands back, in
// lockstep (the plant waits: deterministic) or in real time. The outputs are a run folder:
// trajectory.csv as `run` writes it, summary.json with the link's numbers under "hil",
// link.csv (per tick: sent, arrived, on time, what was applied), scenario.toml and
// provenance.json, written together when the trial ends, or when the link is lost (exit 5,
// one line saying why). `pamsim hil --byte-budget` prints the packet sizes against a serial
// line's rate.
#include <CLI/CLI.hpp>

#include <cstdio>
#include <iostream>
#include <memory>

#include "base/atomic_file.h"
#include "base/input_error.h"
#include "base/toml_file.h"
#include "sim/cli/cli_options.h"
#include "sim/cli/commands.h"
#include "sim/hil/hil_budget.h"
#include "sim/hil/remote_controller.h"
#include "sim/io/outputs.h"
#include "sim/io/provenance.h"
#include "sim/io/staged_outputs.h"
#include "sim/scenario/scenario_file.h"

namespace pamsim {
namespace {

struct HilOptions {
  std::string scenario;
  std::vector<std::string> overrides;
  std::string udp, serial;
  int baud = 115200;
  bool realtime = false;
  double connect_timeout_s = 10.0;
  std::string out;
  bool force = false;
  HilFaults faults;
  std::string burst;  // TICK:COUNT
  double corrupt_fraction = 0.0;
  bool byte_budget = false;
};

const std::vector<std::string> kHilOutputs = {"trajectory.csv", "summary.json", "link.csv",
                                              kResolvedScenarioFile, kProvenanceFile};

// --drop-burst TICK:COUNT
void parse_burst(const std::string& text, HilFaults* faults) {
  long at = -1, length = -1;
  char tail = 0;
  if (std::sscanf(text.c_str(), "%ld:%ld%c", &at, &length, &tail) != 2 || at < 0 || length < 1) {
    throw InputError("--drop-burst must be TICK:COUNT (a tick >= 0, a count >= 1), got '" + text +
                     "'");
  }
  faults->burst_at_tick = at;
  faults->burst_length = length;
}

std::unique_ptr<HilLink> open_link(const HilOptions& opt) {
  if (opt.udp.empty() == opt.serial.empty()) {
    throw InputError("hil needs one link: --udp HOST:PORT or --serial DEVICE");
  }
  std::unique_ptr<HilLink> link =
      opt.udp.empty() ? open_serial_link(opt.serial, opt.baud) : open_udp_link(opt.udp);
  if (opt.corrupt_fraction > 0) link->corrupt_received_bytes(opt.corrupt_fraction, opt.faults.seed);
  return link;
}

std::string link_csv(const std::vector<HilTick>& ticks) {
  std::string csv = "tick,time_s,sent_s,arrived_s,latency_ms,on_time,applied,jitter_ms\n";
  char row[256];
  for (const HilTick& t : ticks) {
    const double latency = std::isnan(t.arrived_s) ? NAN : 1000.0 * (t.arrived_s - t.sent_s);
    std::snprintf(row, sizeof(row), "%ld,%.17g,%.6f,%.6f,%.4f,%d,%s,%.4f\n", t.tick, t.time_s,
                  t.sent_s, t.arrived_s, latency, t.on_time ? 1 : 0,
                  t.applied == 'b'   ? "board"
                  : t.applied == 'h' ? "held"
                                     : "vented",
                  t.jitter_ms);
    csv += row;
  }
  return csv;
}

void hil(const HilOptions& opt) {
  const auto started = std::chrono::steady_clock::now();
  if (opt.byte_budget) {
    std::cout << hil_byte_budget_table();
    return;
  }
  if (opt.scenario.empty()) throw InputError("hil needs a scenario file (or --byte-budget)");
  HilFaults faults = opt.faults;
  if (!opt.burst.empty()) parse_burst(opt.burst, &faults);
  for (const auto& [name, value] :
       {std::pair<const char*, double>{"--drop-fraction", faults.drop_fraction},
        {"--corrupt-fraction", opt.corrupt_fraction}}) {
    if (!(value >= 0.0 && value <= 1.0)) {
      throw InputError(std::string(name) + " must be in [0, 1], got " + std::to_string(value));
    }
  }
  Provenance provenance;
  provenance.command = "hil";
  provenance.started_utc = utc_timestamp();
  provenance.scenario_file = opt.scenario;
  provenance.overrides = opt.overrides;
  const std::string out =
      opt.out.empty() ? default_out_dir(opt.scenario, opt.overrides) + "_hil" : opt.out;
  RecordedScenario recorded = load_recorded_scenario(
      read_text_file(opt.scenario), opt.scenario, opt.overrides, out,
      "# The scenario of a pamsim hil run (provenance.json beside it says how)\n");
  Scenario& sc = recorded.scenario;
  provenance.inputs = fingerprint_inputs(recorded.input_paths);
  const TrialModel model = load_trial_model(sc);
  if (!opt.force) refuse_earlier_outputs(out, kHilOutputs);
  std::unique_ptr<HilLink> link = open_link(opt);
  RemoteController board(*link, sc.hil, opt.realtime ? HilMode::kRealTime : HilMode::kLockstep,
                         sc.control_hz, static_cast<int>(model.muscles.size()), faults);
  board.connect(opt.connect_timeout_s);
  std::cerr << "pamsim: hil: a controller on " << link->describe() << ", "
            << (opt.realtime ? "real time" : "lockstep") << "\n";
  TrialOptions options;
  options.command_source = &board;
  const TrialResult result = run_trial(model, sc, sc.seed, options);
  board.finish(result.summary.metric("sim_time_s"));
  provenance.seeds = {sc.seed};
  nlohmann::json summary = summary_to_json(result.summary, sc, false);
  summary["hil"] = board.summary();
  StagedOutputs staged(out, kHilOutputs);
  staged.write([&] {
    write_file_atomically(staged.path("trajectory.csv"), trajectory_to_csv(result.trajectory));
    write_file_atomically(staged.path("summary.json"), summary.dump(2) + "\n");
    write_file_atomically(staged.path("link.csv"), link_csv(board.ticks()));
    write_file_atomically(staged.path(kResolvedScenarioFile), recorded.resolved_toml);
    write_provenance(staged.path(kProvenanceFile), provenance, started);
  });
  staged.publish();
  std::cout << summary["hil"].dump(2) << "\n";
  std::cerr << "pamsim: outputs in " << out << "\n";
  if (result.summary.status == "link_lost") {
    std::cerr << "pamsim: " << result.summary.message << "\n";
    throw CommandExit(5);
  }
}

}  // namespace

void add_hil_command(CLI::App& app) {
  auto opt = std::make_shared<HilOptions>();
  CLI::App* cmd = app.add_subcommand(
      "hil",
      "Close the loop around the simulated arm with a controller board (hardware in the loop)");
  cmd->add_option("scenario", opt->scenario, "Scenario file (TOML)");
  add_overrides_option(cmd, &opt->overrides, "Override a scenario key: --set hil.hold_ticks=5");
  cmd->add_option("--udp", opt->udp,
                  "Listen for the controller on HOST:PORT (UDP, e.g. 127.0.0.1:9000)");
  cmd->add_option("--serial", opt->serial, "The controller on this serial line (a tty)");
  cmd->add_option("--baud", opt->baud, "The serial line's rate")->capture_default_str();
  cmd->add_flag("--realtime", opt->realtime,
                "Pace the plant to the wall clock (default: lockstep, the plant waits)");
  cmd->add_option("--connect-timeout-s", opt->connect_timeout_s,
                  "How long to wait for the controller's hello")
      ->capture_default_str();
  cmd->add_option("--out", opt->out, "Output folder (default renders/<scenario name>_hil)");
  cmd->add_flag("--force", opt->force, "Replace the outputs of an earlier run in the folder");
  cmd->add_option("--drop-fraction", opt->faults.drop_fraction,
                  "Fault: drop each command with this probability");
  cmd->add_option("--drop-burst", opt->burst, "Fault: drop the commands of TICK:COUNT ticks");
  cmd->add_option("--corrupt-fraction", opt->corrupt_fraction,
                  "Fault (serial): corrupt each received byte with this probability");
  cmd->add_option("--fault-seed", opt->faults.seed, "The faults' random seed")
      ->capture_default_str();
  cmd->add_flag("--byte-budget", opt->byte_budget,
                "Print the packets' bytes per tick against a serial line's rate, and exit");
  cmd->callback([opt] { hil(*opt); });
}

}  // namespace pamsim
