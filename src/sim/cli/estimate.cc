// estimate.cc: `pamsim estimate --params FILE --pressure-MPa P --force-N F [--json]`,
// length estimation from pressure and force: d by inverting Eq. (3)-(5), l = l_n + d
// with l_n from Eq. (2) (Eq. (1) of Yoshida and Hosoda).
#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdio>
#include <iostream>
#include <memory>
#include <string>

#include "base/input_error.h"
#include "pam_actuator/pam_params.h"
#include "base/units.h"
#include "sim/cli/cli_options.h"
#include "sim/cli/commands.h"

namespace pamsim {
namespace {

struct EstimateOptions {
  std::string params_path;
  double pressure_mpa = 0.0;
  double force_n = 0.0;
  bool json = false;
};

void run_estimate(const EstimateOptions& o) {
  // bad input is an error; an unreachable force is a result (status)
  if (!(std::isfinite(o.pressure_mpa) && o.pressure_mpa >= 0.0)) {
    throw InputError("--pressure-MPa must be a finite gauge pressure >= 0, got " +
                     std::to_string(o.pressure_mpa));
  }
  if (!std::isfinite(o.force_n)) {
    throw InputError("--force-N must be finite, got " + std::to_string(o.force_n));
  }
  const PamParams params = load_pam_params(o.params_path);

  // Eq. (3)-(5) inverted for d; Eq. (1)-(2) for the length
  const double p_pa = units::mpa_to_pa(o.pressure_mpa);
  const DeformationEstimate e = invert_spring_model(params.spring, p_pa, o.force_n);
  const bool have_length = e.status != InversionStatus::kNoPhysicalRoot;
  const double d_mm = units::m_to_mm(e.d_m);
  const double l_mm = units::m_to_mm(natural_length(params.spring, p_pa) + e.d_m);

  if (o.json) {
    nlohmann::json out = {{"status", to_string(e.status)}};
    out["deformation_mm"] = have_length ? nlohmann::json(d_mm) : nlohmann::json(nullptr);
    out["length_mm"] = have_length ? nlohmann::json(l_mm) : nlohmann::json(nullptr);
    std::cout << out.dump() << "\n";
  } else if (have_length) {
    std::printf("deformation %.6f mm, length %.6f mm (%s)\n", d_mm, l_mm, to_string(e.status));
  } else {
    std::printf("no physical root: %.6g N is beyond what %s can produce at %.6g MPa\n", o.force_n,
                params.name.c_str(), o.pressure_mpa);
  }
}

}  // namespace

void add_estimate_command(CLI::App& app) {
  const auto [cmd, o] = add_command<EstimateOptions>(
      app, "estimate", "estimate deformation and length from pressure and force (Eq. 1-5)",
      run_estimate);
  cmd->add_option("--params", o->params_path, "PAM parameter file (TOML)")->required();
  cmd->add_option("--pressure-MPa", o->pressure_mpa, "gauge pressure [MPa]")->required();
  cmd->add_option("--force-N", o->force_n, "measured force [N]")->required();
  cmd->add_flag("--json", o->json, "print one JSON object on stdout");
}

}  // namespace pamsim
