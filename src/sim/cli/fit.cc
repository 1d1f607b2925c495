// fit.cc: `pamsim fit --model eq3|eq4|eq5 TENSILE.csv [--json] [-o PARAMS.toml]
// [--sensors-from PARAMS.toml]`, the least-squares identification of Yoshida and Hosoda,
// Sec. II-B, on a tensile CSV file. --sensors-from carries a muscle's strain-gauge
// calibration (Eq. (8)) and geometry, measured apart from the tensile test, into the written
// file, so that it is an estimator a scenario can use.
#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <cstdio>
#include <iostream>
#include <memory>
#include <optional>
#include <string>

#include "base/atomic_file.h"
#include "pam_actuator/identification.h"
#include "base/input_error.h"
#include "pam_actuator/pam_params.h"
#include "pam_actuator/tensile_csv.h"
#include "sim/cli/cli_options.h"
#include "sim/cli/commands.h"
#include "sim/io/outputs.h"

namespace pamsim {
namespace {

struct FitOptions {
  std::string model;
  std::string csv_path;
  std::string output_path;
  std::string sensors_from;
  bool json = false;
  bool force = false;
};

// Eq. (2) and the law's coefficients in the paper's units (m mm/MPa, h mm)
struct PaperFit {
  double m = 0.0, h = 0.0;
  std::array<double, 6> coef{};
};

PaperFit to_paper(const SpringModel& model) {
  PaperFit out;
  spring_model_to_paper_units(model, &out.m, &out.h, &out.coef);
  return out;
}

void print_json(const SpringFit& fit) {
  const PaperFit p = to_paper(fit.model);
  nlohmann::json coefficients = nlohmann::json::object();
  for (int k = 0; k < coefficient_count(fit.model.law); ++k) {
    coefficients[coefficient_name(fit.model.law, k)] = p.coef[k];
  }
  const nlohmann::json out = {{"model", to_string(fit.model.law)},
                              {"m", p.m},
                              {"h", p.h},
                              {"coefficients", coefficients},
                              {"rmse_N", fit.rmse_n},
                              {"r2", fit.r2}};
  std::cout << out.dump() << "\n";
}

void print_table(const SpringFit& fit, const std::string& csv_path, std::FILE* out) {
  const PaperFit p = to_paper(fit.model);
  std::fprintf(out, "%s fitted to %s (%d points); units: p MPa, d mm, f N\n",
               to_string(fit.model.law), csv_path.c_str(), fit.points);
  std::fprintf(out, "  %-4s %14.6g  mm/MPa  (Eq. 2 slope)\n", "m", p.m);
  std::fprintf(out, "  %-4s %14.6g  mm      (Eq. 2 intercept)\n", "h", p.h);
  for (int k = 0; k < coefficient_count(fit.model.law); ++k) {
    std::fprintf(out, "  %-4s %14.6g\n", coefficient_name(fit.model.law, k).c_str(), p.coef[k]);
  }
  std::fprintf(out, "  rmse %.6g N, R^2 %.6f\n", fit.rmse_n, fit.r2);
}

void run_fit(const FitOptions& o) {
  // validate everything before any output
  const bool to_stream = !o.output_path.empty() && is_stream_output(o.output_path);
  if (to_stream && o.json) {
    throw InputError("fit: -o - and --json would both write to standard output; give -o FILE");
  }
  if (!o.output_path.empty()) refuse_existing_file(o.output_path, o.force);
  const SpringLaw law = parse_spring_law(o.model, "--model");
  const std::vector<TensileRow> rows = read_tensile_csv(o.csv_path);
  const SpringFit fit = fit_spring_model(law, rows, o.csv_path);
  std::optional<PamParams> sensors;
  if (!o.sensors_from.empty()) {
    if (o.output_path.empty()) throw InputError("fit: --sensors-from needs -o (a file to write)");
    sensors = load_pam_params(o.sensors_from);
    if (!sensors->strain_gauge) {
      throw InputError(o.sensors_from + ": --sensors-from needs a [strain_gauge] table (Eq. (8))");
    }
  }

  // parameter file that `pamsim estimate` reads
  if (!o.output_path.empty()) {
    PamParams params;
    params.name = "fit";
    params.source = "pamsim fit --model " + o.model + " " + o.csv_path;
    params.spring = fit.model;
    if (sensors) {
      params.source += " --sensors-from " + o.sensors_from;
      params.strain_gauge = sensors->strain_gauge;
      params.geometry = sensors->geometry;
    }
    write_file_atomically(o.output_path, pam_params_to_toml(params));
  }

  if (o.json) {
    print_json(fit);
  } else {
    // with -o - the parameter file is on standard output: the table goes to stderr
    const bool to_stream = is_stream_output(o.output_path);
    std::FILE* out = to_stream ? stderr : stdout;
    print_table(fit, o.csv_path, out);
    if (!o.output_path.empty() && !to_stream) {
      std::fprintf(out, "wrote %s\n", o.output_path.c_str());
    }
  }
}

}  // namespace

void add_fit_command(CLI::App& app) {
  const auto [cmd, o] = add_command<FitOptions>(
      app, "fit", "fit Eq. (2) and a spring law (Eq. 3, 4 or 5) to tensile-test data", run_fit);
  cmd->add_option("--model", o->model, "spring law: eq3 | eq4 | eq5")->required();
  cmd->add_option("tensile_csv", o->csv_path,
                  "CSV with pressure_MPa, deformation_mm, force_N, length_mm columns")
      ->required();
  cmd->add_flag("--json", o->json, "print one JSON object (paper units) on stdout");
  cmd->add_option("-o,--output", o->output_path, "write a PAM parameter file (TOML)");
  cmd->add_flag("--force", o->force, "replace an existing output file");
  cmd->add_option("--sensors-from", o->sensors_from,
                  "copy [strain_gauge] and [geometry] from this PAM file into the output");
}

}  // namespace pamsim
