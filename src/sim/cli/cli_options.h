// cli_options.h: what the commands share in registering themselves: the subcommand with
// its options and callback, --plot-format (PNG, or SVG and/or PDF beside it) and --set
// (scenario overrides, repeatable).
#pragma once

#include <memory>
#include <string>
#include <utility>
#include <vector>

#include <CLI/CLI.hpp>

namespace pamsim {

// The subcommand `name` of `app`, described by `about`, and the options its flags fill: an
// `Options` that lives as long as the app, passed to `run` when the subcommand is given.
//   const auto [cmd, opt] = add_command<FitOptions>(app, "fit", "fit a spring law", run_fit);
//   cmd->add_option("--model", opt->model, "spring law")->required();
template <typename Options, typename Run>
std::pair<CLI::App*, std::shared_ptr<Options>> add_command(CLI::App& app, const std::string& name,
                                                           const std::string& about, Run run) {
  auto options = std::make_shared<Options>();
  CLI::App* cmd = app.add_subcommand(name, about);
  cmd->callback([options, run] { run(*options); });
  return {cmd, options};
}

// --plot-format: "png", or "svg" and/or "pdf" beside the PNG ("svg,pdf").
void add_plot_format_option(CLI::App* cmd, std::string* plot_format);

// --set key=value (repeatable, each taking the values after it), described by `help`
// ("Override a scenario key: --set reflex.v_thr_mm_s=60").
void add_overrides_option(CLI::App* cmd, std::vector<std::string>* overrides,
                          const std::string& help);

// "renders/<scenario name>", and for each override "__<key's last part>-<value>": the default
// output folder of a command that runs a scenario (run, hil).
std::string default_out_dir(const std::string& scenario, const std::vector<std::string>& overrides);

}  // namespace pamsim
