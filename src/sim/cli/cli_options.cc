// cli_options.cc: see cli_options.h.
#include "sim/cli/cli_options.h"

#include <CLI/CLI.hpp>

namespace pamsim {

void add_plot_format_option(CLI::App* cmd, std::string* plot_format) {
  cmd->add_option("--plot-format", *plot_format, "png, or svg and/or pdf beside the PNG (svg,pdf)");
}

void add_overrides_option(CLI::App* cmd, std::vector<std::string>* overrides,
                          const std::string& help) {
  cmd->add_option("--set", *overrides, help)->take_all();
}

}  // namespace pamsim
