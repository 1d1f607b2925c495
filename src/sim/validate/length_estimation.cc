// length_estimation.cc: see length_estimation.h.
#include "sim/validate/length_estimation.h"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <mutex>
#include <set>
#include <sstream>
#include <system_error>

#include "base/atomic_file.h"
#include "base/format.h"
#include "base/input_error.h"
#include "base/units.h"
#include "sim/core/runner.h"
#include "sim/core/trial_model.h"
#include "base/config_reader.h"
#include "sim/io/gnuplot.h"
#include "sim/io/outputs.h"
#include "sim/io/scenario_file.h"

namespace pamsim {
namespace {

namespace fs = std::filesystem;

ValidationPam read_pam(ConfigReader& in, const std::string& name, const TensileTestOptions& base,
                       const std::vector<SpringLaw>& laws) {
  const std::string key = "pams." + name;
  ValidationPam pam;
  pam.name = name;
  pam.plant_file = in.get_path(key + ".plant", "");
  in.check(!pam.plant_file.empty(), key + ".plant", "is required");
  try {
    pam.plant = load_plant_params(pam.plant_file);
  } catch (const InputError& e) {
    in.fail(key + ".plant", std::string("(") + e.what() + ")");
  }
  const double bladder_mm = in.require_double(key + ".bladder_diameter_mm");
  in.check(bladder_mm > 0.0, key + ".bladder_diameter_mm",
           "must be > 0 mm, got " + format_value(bladder_mm));
  pam.bladder_diameter_m = units::mm_to_m(bladder_mm);

  pam.tensile = base;
  pam.tensile.pressures_mpa = in.get_double_list(key + ".pressures_MPa", {});
  std::set<double> levels(pam.tensile.pressures_mpa.begin(), pam.tensile.pressures_mpa.end());
  in.check(levels.size() >= 3, key + ".pressures_MPa",
           "needs at least 3 distinct pressures (Eq. (4)'s p^2 term), got " +
               std::to_string(levels.size()));
  pam.tensile.max_deformation_mm = in.require_double(key + ".max_deformation_mm");
  try {
    validate_tensile_options(pam.tensile);
  } catch (const InputError& e) {
    in.fail(key, std::string("(") + e.what() + ")");
  }
  pam.offset_mpa = in.require_double(key + ".offset_MPa");
  in.check(pam.offset_mpa > 0.0 && pam.offset_mpa < 1.0, key + ".offset_MPa",
           "must be in (0, 1) MPa, got " + format_value(pam.offset_mpa));

  // Table III's values, by law
  for (const std::string& law_name : in.child_keys(key + ".paper")) {
    const std::string law_key = key + ".paper." + law_name;
    in.check(std::any_of(laws.begin(), laws.end(),
                         [&](SpringLaw l) { return law_name == to_string(l); }),
             law_key, "names no law of `laws`");
    const std::vector<double> v = in.get_double_list(law_key, {});
    in.check(v.size() == 2 && v[0] >= 0.0 && v[1] >= 0.0, law_key,
             "must be [max, RMSE] in % of length, both >= 0");
    pam.paper[law_name] = {v[0], v[1]};
  }
  in.raw(key + ".paper");  // read (an empty or absent table is fine)
  return pam;
}

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

// "3" for eq3: the law's equation number in seeds/000
std::string equation_number(SpringLaw law) { return std::string(to_string(law)).substr(2); }

// a Markdown table's header: the model column, then one per PAM
void pam_columns(std::ostringstream& out, const LengthValidationSpec& spec) {
  out << "| model |";
  for (const ValidationPam& pam : spec.pams) out << " PAM-" << pam.name << " |";
  out << "\n| --- |";
  for (std::size_t i = 0; i < spec.pams.size(); ++i) out << " --- |";
  out << '\n';
}

std::string quoted(const std::string& path) {
  std::string out = "\"";
  for (char c : path) {
    if (c == '"' || c == '\\') out += '\\';
    out += c;
  }
  return out + "\"";
}

}  // namespace

LengthValidationSpec load_length_validation(const std::string& path,
                                            const std::vector<std::string>& only,
                                            const std::vector<std::string>& protocol_overrides) {
  ConfigReader in(path);
  for (const std::string& o : protocol_overrides) in.apply_override(o);
  LengthValidationSpec spec;
  spec.file = path;
  spec.rig_file = in.get_path("rig", "");
  in.check(!spec.rig_file.empty(), "rig", "is required (the pulley rig's scenario)");
  spec.overrides = in.get_string_list("overrides", {});
  for (const std::string& name : in.get_string_list("laws", {"eq3", "eq4", "eq5"})) {
    try {
      spec.laws.push_back(parse_spring_law(name, "laws"));
    } catch (const InputError& e) {
      in.fail("laws", std::string("(") + e.what() + ")");
    }
  }
  in.check(!spec.laws.empty(), "laws", "must name at least one law");
  spec.weights_kg = in.get_double_list("weights_kg", {5.0, 10.0});
  in.check(!spec.weights_kg.empty(), "weights_kg", "must hold at least one weight");
  for (double w : spec.weights_kg) {
    in.check(w > 0.0 && w <= 1000.0, "weights_kg",
             "must be in (0, 1000] kg, got " + format_value(w));
  }

  TensileTestOptions base;
  base.step_mm = in.get_double("tensile.step_mm", base.step_mm);
  base.noise_pressure_mpa = in.get_double("tensile.noise_pressure_MPa", 0.0);
  base.noise_force_n = in.get_double("tensile.noise_force_N", 0.0);
  base.noise_length_mm = in.get_double("tensile.noise_length_mm", 0.0);
  const std::int64_t seed = in.get_int("tensile.seed", 1);
  in.check(seed >= 0, "tensile.seed", "must be >= 0");
  base.seed = static_cast<std::uint64_t>(seed);
  spec.gauge_file = in.get_path("tensile.sensors_from", "");
  in.check(!spec.gauge_file.empty(), "tensile.sensors_from",
           "is required (the strain gauge of the rig's force reading, Eq. (8))");
  try {
    const PamParams sensors = load_pam_params(spec.gauge_file);
    in.check(sensors.strain_gauge.has_value(), "tensile.sensors_from",
             "(" + spec.gauge_file + ") needs a [strain_gauge] table (Eq. (8))");
    spec.gauge = *sensors.strain_gauge;
  } catch (const InputError& e) {
    in.fail("tensile.sensors_from", std::string("(") + e.what() + ")");
  }

  const std::vector<std::string> names = in.child_keys("pams");
  in.check(!names.empty(), "pams", "must hold at least one [pams.<NAME>] table");
  for (std::size_t i = 0; i < only.size(); ++i) {
    const std::string& wanted = only[i];
    if (std::find(only.begin(), only.begin() + i, wanted) != only.begin() + i) {
      throw InputError("--pams: " + wanted + " is named twice");
    }
    if (std::find(names.begin(), names.end(), wanted) == names.end()) {
      std::string list;
      for (const std::string& n : names) list += (list.empty() ? "" : ", ") + n;
      throw InputError("--pams: unknown PAM " + wanted + "; " + path + " has " + list);
    }
  }
  for (const std::string& name : names) {
    ValidationPam pam = read_pam(in, name, base, spec.laws);  // every PAM validated
    if (only.empty() || std::find(only.begin(), only.end(), name) != only.end()) {
      spec.pams.push_back(std::move(pam));
    }
  }
  if (!only.empty()) {  // the order asked for
    std::vector<ValidationPam> ordered;
    for (const std::string& wanted : only) {
      for (const ValidationPam& p : spec.pams) {
        if (p.name == wanted) ordered.push_back(p);
      }
    }
    spec.pams = std::move(ordered);
  }
  in.reject_unknown();
  return spec;
}

LengthValidationResult run_length_validation(const LengthValidationSpec& spec,
                                             const ValidationOptions& options) {
  LengthValidationResult result;
  make_directories(options.out_dir);
  // the fits go to a temp folder until the outputs are complete (see the header)
  const fs::path fits_tmp = fs::path(options.out_dir) / (".fits.tmp." + std::to_string(::getpid()));
  struct RemoveOnError {
    fs::path dir;
    bool keep = false;
    ~RemoveOnError() {
      std::error_code ec;
      if (!keep) fs::remove_all(dir, ec);
    }
  } guard{fits_tmp};
  fs::remove_all(fits_tmp);
  make_directories(fits_tmp.string());
  const std::string fits_dir = fits_tmp.string();

  // the static tests and their fits (seeds/000 Sec. II-B), each fit as a PAM file
  for (const ValidationPam& pam : spec.pams) {
    TensileTestOptions test = pam.tensile;
    if (options.seed) test.seed = *options.seed;
    try {
      result.tensile.push_back(run_tensile_test(pam.plant.avbdl, test));
    } catch (const InputError& e) {
      throw InputError(spec.file + ": pams." + pam.name + " (" + pam.plant_file +
                       "): tensile test: " + e.what());
    }
    const std::vector<TensileRow>& rows = result.tensile.back();
    for (SpringLaw law : spec.laws) {
      FittedLaw f;
      f.pam = pam.name;
      f.law = law;
      f.fit = fit_spring_model(law, rows, "PAM-" + pam.name + " tensile test");
      f.max_residual_n = max_residual_n(f.fit.model, rows);
      f.params_file =
          (fs::path(fits_dir) / ("pam_" + pam.name + "_" + to_string(law) + ".toml")).string();
      write_file_atomically(f.params_file, pam_params_to_toml(fitted_params(spec, pam, f.fit)));
      result.fits.push_back(f);
    }
  }

  // the protocol sets these per trial: a --set of them would be silently overruled
  for (const std::string& o : options.overrides) {
    for (const char* key : {"muscles.pam.plant", "muscles.pam.params", "bodies.weight.mass_kg",
                            "muscles.pam.command.offset_MPa", "seed"}) {
      if (o.rfind(std::string(key) + "=", 0) == 0) {
        throw InputError("--set " + o + ": " + key + " is set per trial by " + spec.file +
                         " (its pams, weights_kg; --seed for the seed)");
      }
    }
  }

  // the dynamic trials' scenarios, all loaded (and so validated) before any runs
  struct Job {
    Scenario scenario;
    std::size_t row;
  };
  std::vector<Job> jobs;
  std::size_t fit_index = 0;
  for (const ValidationPam& pam : spec.pams) {
    for (SpringLaw law : spec.laws) {
      const FittedLaw& f = result.fits[fit_index++];
      for (double weight : spec.weights_kg) {
        std::vector<std::string> overrides = spec.overrides;
        overrides.push_back("muscles.pam.plant=" + quoted(fs::absolute(pam.plant_file).string()));
        overrides.push_back("muscles.pam.params=" + quoted(fs::absolute(f.params_file).string()));
        overrides.push_back("bodies.weight.mass_kg=" + format_shortest(weight));
        overrides.push_back("muscles.pam.command.offset_MPa=" + format_shortest(pam.offset_mpa));
        overrides.insert(overrides.end(), options.overrides.begin(), options.overrides.end());
        if (options.seed) overrides.push_back("seed=" + std::to_string(*options.seed));
        DynamicRow row;
        row.pam = pam.name;
        row.law = law;
        row.weight_kg = weight;
        const auto paper = pam.paper.find(to_string(law));
        if (paper != pam.paper.end()) row.paper = paper->second;
        result.rows.push_back(row);
        jobs.push_back({load_scenario(spec.rig_file, overrides), result.rows.size() - 1});
      }
    }
  }

  if (options.started) options.started(static_cast<int>(jobs.size()));

  // each trial binds its own model (the plants differ), on the pool
  std::mutex progress_mutex;
  int done = 0;
  parallel_for(static_cast<int>(jobs.size()), options.threads, [&](int k) {
    const Job& job = jobs[k];
    const TrialModel model = load_trial_model(job.scenario);
    TrialResult r = run_trial(model, job.scenario, job.scenario.seed);
    DynamicRow& row = result.rows[job.row];
    row.status = r.summary.status;
    row.sim = {r.summary.metric("length_est_max_error_pct"),
               r.summary.metric("length_est_rmse_pct")};
    row.trajectory = std::move(r.trajectory);
    if (options.progress) {
      std::lock_guard<std::mutex> lock(progress_mutex);
      options.progress(++done, static_cast<int>(jobs.size()));
    }
  });

  guard.keep = true;  // write_length_validation moves it into place
  result.fits_dir = fits_tmp.string();
  return result;
}

std::string table3_csv(const LengthValidationResult& result) {
  std::ostringstream out;
  out << "pam,law,weight_kg,status,max_error_pct,rmse_pct,paper_max_error_pct,paper_rmse_pct,"
         "fit_rmse_N,fit_max_residual_N,fit_r2\n";
  const auto num = [](double v) { return std::isfinite(v) ? format_shortest(v) : std::string(); };
  for (const DynamicRow& row : result.rows) {
    const auto fit = std::find_if(result.fits.begin(), result.fits.end(), [&](const FittedLaw& f) {
      return f.pam == row.pam && f.law == row.law;
    });
    out << row.pam << ',' << to_string(row.law) << ',' << num(row.weight_kg) << ',' << row.status
        << ',' << num(row.sim.max_pct) << ',' << num(row.sim.rmse_pct) << ','
        << (row.paper ? num(row.paper->max_pct) : "") << ','
        << (row.paper ? num(row.paper->rmse_pct) : "") << ',' << num(fit->fit.rmse_n) << ','
        << num(fit->max_residual_n) << ',' << num(fit->fit.r2) << '\n';
  }
  return out.str();
}

std::string table3_markdown(const LengthValidationResult& result,
                            const LengthValidationSpec& spec) {
  std::ostringstream out;
  const auto cell = [](double v) {
    char buf[32];
    std::snprintf(buf, sizeof(buf), std::isfinite(v) ? "%.3g" : "n/a", v);
    return std::string(buf);
  };
  out << "# Table III in simulation: dynamic length estimation, error in % of length\n\n"
      << "Each cell: simulation max / RMSE (paper max / RMSE, seeds/000 Table III; the paper "
         "does not split by weight).\n";
  for (double weight : spec.weights_kg) {
    out << "\n## " << format_shortest(weight) << " kg\n\n";
    pam_columns(out, spec);
    for (SpringLaw law : spec.laws) {
      out << "| Eq. (" << equation_number(law) << ") |";
      for (const ValidationPam& pam : spec.pams) {
        for (const DynamicRow& row : result.rows) {
          if (row.pam != pam.name || row.law != law || row.weight_kg != weight) continue;
          out << ' ' << cell(row.sim.max_pct) << " / " << cell(row.sim.rmse_pct);
          if (row.paper)
            out << " (" << cell(row.paper->max_pct) << " / " << cell(row.paper->rmse_pct) << ')';
          if (row.status != "ok") out << " [" << row.status << ']';
          out << " |";
        }
      }
      out << '\n';
    }
  }
  out << "\nFits to the static tensile test (force RMSE / largest residual [N], R^2):\n\n";
  pam_columns(out, spec);
  for (SpringLaw law : spec.laws) {
    out << "| Eq. (" << equation_number(law) << ") |";
    for (const ValidationPam& pam : spec.pams) {
      for (const FittedLaw& f : result.fits) {
        if (f.pam != pam.name || f.law != law) continue;
        char buf[64];
        std::snprintf(buf, sizeof(buf), " %.3g / %.3g, %.5f |", f.fit.rmse_n, f.max_residual_n,
                      f.fit.r2);
        out << buf;
      }
    }
    out << '\n';
  }
  return out.str();
}

namespace {

// the figures, then the tables (a failed plot leaves no table claiming a complete run)
void write_figures_and_tables(const LengthValidationResult& result,
                              const LengthValidationSpec& spec, const std::string& out_dir,
                              bool plots) {
  make_directories(out_dir);
  for (const ValidationPam& pam : spec.pams) {
    if (!plots) break;
    GnuplotJob job;
    job.width_px = 1200;
    job.height_px = 900;
    std::string plots_top, plots_bottom;
    int series = 0;
    for (const DynamicRow& row : result.rows) {
      if (row.pam != pam.name || row.trajectory.rows() == 0) continue;
      const Trajectory& tr = row.trajectory;
      const std::size_t t = tr.column("time_s"), truth = tr.column("length_pam_mm"),
                        est = tr.column("length_est_pam_mm");
      std::string data;
      for (std::size_t i = 0; i < tr.rows(); ++i) {
        const double l = tr.at(i, truth), e = tr.at(i, est);
        data += gp_num(tr.at(i, t)) + ' ' + gp_num(l) + ' ' + gp_num(e) + ' ' +
                gp_num(100.0 * (e - l) / l) + '\n';
      }
      const std::string name = "s" + std::to_string(series++) + ".dat";
      job.data_files.push_back({name, data});
      const std::string label =
          std::string(to_string(row.law)) + ", " + format_shortest(row.weight_kg) + " kg";
      const char* dash = row.weight_kg == spec.weights_kg.front() ? "1" : "2";
      if (row.law == spec.laws.front()) {
        plots_top += (plots_top.empty() ? "" : ", ") + gp_quote(name) +
                     " using 1:2 with lines dt " + dash + " lc rgb 'black' title " +
                     gp_quote("true, " + format_shortest(row.weight_kg) + " kg") + ", " +
                     gp_quote(name) + " using 1:3 with lines dt " + dash +
                     " lc rgb '#c0392b' title " + gp_quote("estimate " + label);
      }
      plots_bottom += (plots_bottom.empty() ? "" : ", ") + gp_quote(name) +
                      " using 1:4 with lines dt " + dash + " lw 1.5 title " + gp_quote(label);
    }
    if (plots_top.empty()) continue;
    job.script = "set multiplot layout 2,1 title " +
                 gp_quote("PAM-" + pam.name + ": dynamic length estimation (Fig. 5-6)") +
                 "\nset grid\nset key outside right\nset ylabel 'length (mm)'\nplot " + plots_top +
                 "\nset xlabel 'time (s)'\nset ylabel 'error (% of length)'\nplot " + plots_bottom +
                 "\nunset multiplot\n";
    run_gnuplot((fs::path(out_dir) / ("pam_" + pam.name + ".png")).string(), job);
  }
  write_file_atomically((fs::path(out_dir) / "table3.csv").string(), table3_csv(result));
  write_file_atomically((fs::path(out_dir) / "table3.md").string(), table3_markdown(result, spec));
}

}  // namespace

void write_length_validation(LengthValidationResult& result, const LengthValidationSpec& spec,
                             const std::string& out_dir, bool plots) {
  const fs::path fits_tmp = result.fits_dir;
  try {
    write_figures_and_tables(result, spec, out_dir, plots);
  } catch (...) {
    std::error_code ec;
    fs::remove_all(fits_tmp, ec);
    throw;
  }
  // the new fits replace the old: the old aside first, so a failure leaves one of them whole
  const fs::path fits = fs::path(out_dir) / "fits";
  const fs::path old = fs::path(out_dir) / (".fits.old." + std::to_string(::getpid()));
  std::error_code ec;
  if (fs::exists(fits)) fs::rename(fits, old, ec);
  if (!ec) fs::rename(fits_tmp, fits, ec);
  if (ec) {
    throw InputError(fits.string() + ": cannot move the fitted files there: " + ec.message());
  }
  fs::remove_all(old, ec);
  for (FittedLaw& f : result.fits)
    f.params_file = (fits / fs::path(f.params_file).filename()).string();
  result.fits_dir = fits.string();
}

}  // namespace pamsim
