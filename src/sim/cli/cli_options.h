// cli_options.h: the options several commands share, registered one way: --plot-format
// (PNG, or SVG and/or PDF beside it) and --set (scenario overrides, repeatable).
#pragma once

#include <string>
#include <vector>

namespace CLI {
class App;
}

namespace pamsim {

// --plot-format: "png", or "svg" and/or "pdf" beside the PNG ("svg,pdf").
void add_plot_format_option(CLI::App* cmd, std::string* plot_format);

// --set key=value (repeatable, each taking the values after it), described by `help`
// ("Override a scenario key: --set reflex.v_thr_mm_s=60").
void add_overrides_option(CLI::App* cmd, std::vector<std::string>* overrides,
                          const std::string& help);

}  // namespace pamsim
