// cli_options.cc: see cli_options.h.
#include "sim/cli/cli_options.h"

#include <CLI/CLI.hpp>

#include <cctype>
#include <filesystem>

namespace pamsim {

void add_plot_format_option(CLI::App* cmd, std::string* plot_format) {
  cmd->add_option("--plot-format", *plot_format, "png, or svg and/or pdf beside the PNG (svg,pdf)");
}

void add_overrides_option(CLI::App* cmd, std::vector<std::string>* overrides,
                          const std::string& help) {
  cmd->add_option("--set", *overrides, help)->take_all();
}

// "renders/<scenario name>", and for each override "__<key's last part>-<value>" (characters
// other than letters, digits, '.', '_' and '-' as '-'): `--set reflex.v_thr_mm_s=60` runs into
// renders/drop_mass__v_thr_mm_s-60, beside the unmodified run.
std::string default_out_dir(const std::string& scenario,
                            const std::vector<std::string>& overrides) {
  std::string name = scenario == "-" ? "stdin" : std::filesystem::path(scenario).stem().string();
  for (const std::string& o : overrides) {
    const auto eq = o.find('=');
    const std::string key = o.substr(0, eq);
    std::string part = "__" + key.substr(key.find_last_of('.') + 1);
    if (eq != std::string::npos) part += "-" + o.substr(eq + 1);
    for (char& c : part) {
      if (!std::isalnum(static_cast<unsigned char>(c)) && c != '.' && c != '_' && c != '-') c = '-';
    }
    name += part;
  }
  if (name.size() > 120) name = name.substr(0, 120);  // a file name's length is bounded
  return "renders/" + name;
}

}  // namespace pamsim
