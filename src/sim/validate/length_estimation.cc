// length_estimation.cc: run_length_validation of length_estimation.h, the protocol run:
// each PAM's tensile test and the fits of its laws, then the dynamic trials on the pulley
// rig, one per fitted law and weight. The protocol file is read in
// length_validation_protocol.cc, the tables and figures written in
// length_validation_tables.cc.
#include "sim/validate/length_estimation.h"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <mutex>
#include <system_error>

#include "base/atomic_file.h"
#include "base/format.h"
#include "base/input_error.h"
#include "base/units.h"
#include "sim/core/runner.h"
#include "sim/core/trial_model.h"
#include "sim/io/outputs.h"
#include "sim/scenario/scenario_file.h"
#include "sim/validate/line_breaks.h"

namespace pamsim {
namespace {

namespace fs = std::filesystem;

// A fitted law as the estimator's PAM file: the fit, the rig's strain gauge, the plant's
// Table I geometry (so the scenario's plant-vs-estimator check holds)
PamParams fitted_params(const LengthValidationSpec& spec, const ValidationPam& pam,
                        const SpringFit& fit) {
  PamParams params;
  params.name = "PAM-" + pam.name + " " + to_string(fit.model.law);
  params.source = "pamsim validate length-estimation " + spec.file + ": " +
                  to_string(fit.model.law) + " fitted to the tensile test of " + pam.plant_file;
  params.spring = fit.model;
  params.strain_gauge = spec.gauge;
  PamGeometry g;
  g.length_m = pam.plant.avbdl.length_m;
  g.sleeve_diameter_m = pam.plant.avbdl.diameter_m;
  g.bladder_diameter_m = pam.bladder_diameter_m;
  g.braid_angle_rad = pam.plant.avbdl.braid_angle_rad;
  params.geometry = g;
  return params;
}

double max_residual_n(const SpringModel& model, const std::vector<TensileRow>& rows) {
  double worst = 0.0;
  for (const TensileRow& r : rows) {
    const double f =
        spring_force(model, units::mpa_to_pa(r.pressure_mpa), units::mm_to_m(r.deformation_mm));
    worst = std::max(worst, std::fabs(f - r.force_n));
  }
  return worst;
}

std::string quoted(const std::string& path) {
  std::string out = "\"";
  for (char c : path) {
    if (c == '"' || c == '\\') out += '\\';
    out += c;
  }
  return out + "\"";
}

// A folder removed with what it holds when this goes out of scope, unless kept.
struct RemoveOnError {
  fs::path dir;
  bool keep = false;
  ~RemoveOnError() {
    std::error_code ec;
    if (!keep) fs::remove_all(dir, ec);
  }
};

// A changed plant (a drawn wall, a stiffer bladder) may not stretch as far as the file's
// max_deformation_mm at the test's lowest pressure; the lab sets that deformation "based on
// each PAM's strength" (Sec. II-B), so the test goes as far as the plant reaches, in whole
// steps.
double reachable_mm(const AvbdlParams& plant, const TensileTestOptions& test) {
  double reach = test.max_deformation_mm;
  for (double p_mpa : test.pressures_mpa) {
    const double room =
        units::m_to_mm(avbdl_max_length(plant) - avbdl_free_length(plant, units::mpa_to_pa(p_mpa)));
    reach = std::min(reach, std::floor(room / test.step_mm) * test.step_mm);
  }
  return reach;
}

// The static tests and their fits (Yoshida and Hosoda, Sec. II-B), each fit as a PAM file in
// fits_dir.
void run_tensile_tests_and_fits(const LengthValidationSpec& spec, const ValidationOptions& options,
                                const std::string& fits_dir, LengthValidationResult* result) {
  for (const ValidationPam& pam : spec.pams) {
    TensileTestOptions test = pam.tensile;
    if (options.seed) test.seed = *options.seed;
    if (!pam.plant_changes.empty()) test.max_deformation_mm = reachable_mm(pam.plant.avbdl, test);
    try {
      result->tensile.push_back(run_tensile_test(pam.plant.avbdl, test));
    } catch (const InputError& e) {
      throw InputError(spec.file + ": pams." + pam.name + " (" + pam.plant_file +
                       "): tensile test: " + e.what());
    }
    const std::vector<TensileRow>& rows = result->tensile.back();
    for (SpringLaw law : spec.laws) {
      FittedLaw f;
      f.pam = pam.name;
      f.law = law;
      f.fit = fit_spring_model(law, rows, "PAM-" + pam.name + " tensile test");
      f.max_residual_n = max_residual_n(f.fit.model, rows);
      f.params_file =
          (fs::path(fits_dir) / ("pam_" + pam.name + "_" + to_string(law) + ".toml")).string();
      write_file_atomically(f.params_file, pam_params_to_toml(fitted_params(spec, pam, f.fit)));
      result->fits.push_back(f);
    }
  }
}

// The protocol sets these per trial: a --set of them would be silently overruled.
void check_overrides_not_per_trial(const LengthValidationSpec& spec,
                                   const ValidationOptions& options) {
  for (const std::string& o : options.overrides) {
    if (o.rfind("muscles.pam.plant.", 0) == 0) {
      throw InputError("--set " + o +
                       ": a PAM's plant is changed by pams.<NAME>.plant.<table>."
                       "<field> (its tensile test and fits see the change too)");
    }
    for (const char* key : {"muscles.pam.plant", "muscles.pam.params", "bodies.weight.mass_kg",
                            "muscles.pam.command.offset_MPa", "seed"}) {
      if (o.rfind(std::string(key) + "=", 0) == 0) {
        throw InputError("--set " + o + ": " + key + " is set per trial by " + spec.file +
                         " (its pams, weights_kg; --seed for the seed)");
      }
    }
  }
}

// One dynamic trial's overrides of the rig: the protocol's, the PAM's plant, the fit as its
// estimator, the weight and the sine's offset, then the command line's
std::vector<std::string> trial_overrides(const LengthValidationSpec& spec,
                                         const ValidationOptions& options, const ValidationPam& pam,
                                         const FittedLaw& f, double weight) {
  std::vector<std::string> overrides = spec.overrides;
  const std::string plant = quoted(fs::absolute(pam.plant_file).string());
  if (pam.plant_changes.empty()) {
    overrides.push_back("muscles.pam.plant=" + plant);
  } else {  // the plant file with the PAM's changes, as the rig's table form
    overrides.push_back("muscles.pam.plant={ file = " + plant + " }");
    for (const std::string& c : pam.plant_changes) overrides.push_back("muscles.pam.plant." + c);
  }
  overrides.push_back("muscles.pam.params=" + quoted(fs::absolute(f.params_file).string()));
  overrides.push_back("bodies.weight.mass_kg=" + format_shortest(weight));
  overrides.push_back("muscles.pam.command.offset_MPa=" + format_shortest(pam.offset_mpa));
  overrides.insert(overrides.end(), options.overrides.begin(), options.overrides.end());
  if (options.seed) overrides.push_back("seed=" + std::to_string(*options.seed));
  return overrides;
}

// a dynamic trial's scenario and the row of the result it fills
struct Job {
  Scenario scenario;
  std::size_t row;
};

// The dynamic trials' scenarios, all loaded (and so validated) before any runs, and their
// rows in result->rows.
std::vector<Job> dynamic_jobs(const LengthValidationSpec& spec, const ValidationOptions& options,
                              LengthValidationResult* result) {
  std::vector<Job> jobs;
  std::size_t fit_index = 0;
  for (const ValidationPam& pam : spec.pams) {
    for (SpringLaw law : spec.laws) {
      const FittedLaw& f = result->fits[fit_index++];
      for (double weight : spec.weights_kg) {
        const std::vector<std::string> overrides = trial_overrides(spec, options, pam, f, weight);
        DynamicRow row;
        row.pam = pam.name;
        row.law = law;
        row.weight_kg = weight;
        const auto paper = pam.paper.find(to_string(law));
        if (paper != pam.paper.end()) row.paper = paper->second;
        result->rows.push_back(row);
        jobs.push_back({load_scenario(spec.rig_file, overrides), result->rows.size() - 1});
      }
    }
  }
  return jobs;
}

// Each trial binds its own model (the plants differ), on the pool.
void run_dynamic_trials(const std::vector<Job>& jobs, const ValidationOptions& options,
                        LengthValidationResult* result) {
  std::mutex progress_mutex;
  int done = 0;
  parallel_for(static_cast<int>(jobs.size()), options.threads, [&](int k) {
    const Job& job = jobs[k];
    const TrialModel model = load_trial_model(job.scenario);
    TrialResult r = run_trial(model, job.scenario, job.scenario.seed);
    DynamicRow& row = result->rows[job.row];
    row.status = r.summary.status;
    row.sim = {r.summary.metric("length_est_max_error_pct"),
               r.summary.metric("length_est_rmse_pct")};
    row.trajectory = std::move(r.trajectory);
    if (options.progress) {
      std::lock_guard<std::mutex> lock(progress_mutex);
      options.progress(++done, static_cast<int>(jobs.size()));
    }
  });
}

}  // namespace

LengthValidationResult run_length_validation(const LengthValidationSpec& given,
                                             const ValidationOptions& given_options) {
  // a PAM's plant changed by --set or a bracket: its tensile test, fits and trials see it
  ValidationOptions options = given_options;
  const LengthValidationSpec spec = with_plant_changes(given, &options.overrides);
  LengthValidationResult result;
  make_directories(options.out_dir);
  // the fits go to a temp folder until the outputs are complete (see the header)
  const fs::path fits_tmp = fs::path(options.out_dir) / (".fits.tmp." + std::to_string(::getpid()));
  RemoveOnError guard{fits_tmp};
  fs::remove_all(fits_tmp);
  make_directories(fits_tmp.string());
  const std::string fits_dir = fits_tmp.string();

  run_tensile_tests_and_fits(spec, options, fits_dir, &result);
  check_overrides_not_per_trial(spec, options);
  const std::vector<Job> jobs = dynamic_jobs(spec, options, &result);
  if (options.started) options.started(static_cast<int>(jobs.size()));
  run_dynamic_trials(jobs, options, &result);
  for (const Job& job : jobs) check_line_breaks(job.scenario, {&result.rows[job.row].trajectory});

  guard.keep = true;  // write_length_validation moves it into place
  result.fits_dir = fits_tmp.string();
  return result;
}

}  // namespace pamsim
