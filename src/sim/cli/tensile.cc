// tensile.cc: `pamsim tensile --params FILE | --plant FILE [--set table.field=value ...] ...
// -o FILE.csv`, the virtual static tensile test of Yoshida and Hosoda, Sec. II-B, on a PAM
// parameter file's spring law or on a physical plant (the lab's way to the estimator: test
// the muscle, then `pamsim fit`). --set changes a plant file's fields in its own units, each
// validated as the file's own (the scenario's muscles.<m>.plant.<table>.<field> does the
// same).
#include <CLI/CLI.hpp>

#include <cmath>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "base/atomic_file.h"
#include "base/config_reader.h"
#include "base/input_error.h"
#include "pam_actuator/pam_params.h"
#include "pam_actuator/plant_params.h"
#include "pam_actuator/tensile_csv.h"
#include "pam_actuator/tensile_test.h"
#include "sim/cli/cli_options.h"
#include "sim/cli/commands.h"
#include "sim/io/outputs.h"

namespace pamsim {
namespace {

struct TensileCommand {
  std::string params_path;
  std::string plant_path;
  std::string output_path;
  std::vector<std::string> plant_changes;  // --set geometry.wall_thickness_mm=0.5
  bool force = false;
  TensileTestOptions test;
};

std::string number(double x) {
  char buf[32];
  std::snprintf(buf, sizeof(buf), "%g", x);
  return buf;
}

void require(bool ok, const std::string& option, const std::string& allowed, double value) {
  if (!ok) throw InputError(option + " must be " + allowed + ", got " + number(value));
}

// every option checked with the name the user typed
void validate(const TensileTestOptions& t) {
  require(std::isfinite(t.noise_pressure_mpa) && t.noise_pressure_mpa >= 0.0,
          "--noise-pressure-MPa", "a standard deviation >= 0", t.noise_pressure_mpa);
  require(std::isfinite(t.noise_force_n) && t.noise_force_n >= 0.0, "--noise-force-N",
          "a standard deviation >= 0", t.noise_force_n);
  require(std::isfinite(t.noise_length_mm) && t.noise_length_mm >= 0.0, "--noise-length-mm",
          "a standard deviation >= 0", t.noise_length_mm);
  require(std::isfinite(t.hysteresis) && t.hysteresis >= 0.0 && t.hysteresis < 0.5, "--hysteresis",
          "in [0, 0.5)", t.hysteresis);
  require(std::isfinite(t.max_deformation_mm) && t.max_deformation_mm >= t.step_mm,
          "--max-deformation-mm", ">= the 2.5 mm step", t.max_deformation_mm);
  if (t.pressures_mpa.empty()) throw InputError("--pressures-MPa: the list is empty");
  for (double p : t.pressures_mpa) {
    require(std::isfinite(p) && p > 0.0, "--pressures-MPa", "a list of pressures > 0 MPa", p);
  }
}

void run_tensile(const TensileCommand& c) {
  refuse_existing_file(c.output_path, c.force);
  validate(c.test);
  if (c.params_path.empty() == c.plant_path.empty()) {
    throw InputError("tensile: give one of --params (a spring law) or --plant (a plant file)");
  }
  if (c.plant_path.empty() && !c.plant_changes.empty()) {
    throw InputError("tensile: --set changes a plant file's fields: give --plant");
  }
  ConfigReader changes("", "tensile");  // the --set fields, as the plant file's own tables
  changes.apply_overrides(c.plant_changes);
  const std::vector<TensileRow> rows =
      c.plant_path.empty()
          ? run_tensile_test(load_pam_params(c.params_path).spring, c.test)
          : run_tensile_test(load_plant_params(c.plant_path, changes.document(), "--set ").avbdl,
                             c.test);
  write_file_atomically(c.output_path, tensile_rows_to_csv(rows));
  // stderr: with -o - the CSV itself is on stdout
  std::fprintf(stderr, "pamsim: wrote %zu rows to %s\n", rows.size(),
               c.output_path == "-" ? "standard output" : c.output_path.c_str());
}

}  // namespace

void add_tensile_command(CLI::App& app) {
  const auto [cmd, c] = add_command<TensileCommand>(
      app, "tensile", "virtual static tensile test (Yoshida and Hosoda, Sec. II-B), written as CSV",
      run_tensile);
  TensileTestOptions& t = c->test;
  cmd->add_option("--params", c->params_path, "PAM parameter file (TOML): test its spring law");
  cmd->add_option("--plant", c->plant_path, "plant file (TOML, models/pams/plant_*.toml)");
  add_overrides_option(cmd, &c->plant_changes,
                       "Change a plant file's field: --set geometry.wall_thickness_mm=0.5");
  cmd->add_option("-o,--output", c->output_path, "output CSV file")->required();
  cmd->add_flag("--force", c->force, "replace an existing output file");
  cmd->add_option("--seed", t.seed, "noise seed (same seed, same data)")->check(non_negative_seed);
  cmd->add_option("--noise-pressure-MPa", t.noise_pressure_mpa, "pressure sensor noise SD");
  cmd->add_option("--noise-force-N", t.noise_force_n, "force sensor noise SD");
  cmd->add_option("--noise-length-mm", t.noise_length_mm, "length encoder noise SD");
  cmd->add_option("--hysteresis", t.hysteresis,
                  "loading force x(1+h), unloading x(1-h), h in [0, 0.5)");
  cmd->add_option("--pressures-MPa", t.pressures_mpa, "comma-separated test pressures")
      ->delimiter(',');
  cmd->add_option("--max-deformation-mm", t.max_deformation_mm, "largest deformation");
}

}  // namespace pamsim
