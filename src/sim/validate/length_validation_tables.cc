// length_validation_tables.cc: the outputs of the length-estimation validation
// (length_estimation.h): Table III as CSV and Markdown, each PAM's figure, and the fitted
// PAM files moved into place.
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <sstream>
#include <system_error>

#include "base/atomic_file.h"
#include "base/format.h"
#include "base/input_error.h"
#include "sim/io/gnuplot.h"
#include "sim/io/outputs.h"
#include "sim/validate/length_estimation.h"
#include "sim/validate/table_cells.h"

namespace pamsim {
namespace {

namespace fs = std::filesystem;

// "3" for eq3: the law's equation number in Yoshida and Hosoda
std::string equation_number(SpringLaw law) { return std::string(to_string(law)).substr(2); }

// a Markdown table's header: the model column, then one per PAM
void pam_columns(std::ostringstream& out, const LengthValidationSpec& spec) {
  std::vector<std::string> pams;
  for (const ValidationPam& pam : spec.pams) pams.push_back("PAM-" + pam.name);
  out << markdown_header("model", pams);
}

}  // namespace

std::string table3_csv(const LengthValidationResult& result) {
  std::ostringstream out;
  out << "pam,law,weight_kg,status,max_error_pct,rmse_pct,paper_max_error_pct,paper_rmse_pct,"
         "fit_rmse_N,fit_max_residual_N,fit_r2\n";
  for (const DynamicRow& row : result.rows) {
    const auto fit = std::find_if(result.fits.begin(), result.fits.end(), [&](const FittedLaw& f) {
      return f.pam == row.pam && f.law == row.law;
    });
    out << row.pam << ',' << to_string(row.law) << ',' << csv_number(row.weight_kg) << ','
        << row.status << ',' << csv_number(row.sim.max_pct) << ',' << csv_number(row.sim.rmse_pct)
        << ',' << (row.paper ? csv_number(row.paper->max_pct) : "") << ','
        << (row.paper ? csv_number(row.paper->rmse_pct) : "") << ',' << csv_number(fit->fit.rmse_n)
        << ',' << csv_number(fit->max_residual_n) << ',' << csv_number(fit->fit.r2) << '\n';
  }
  return out.str();
}

std::string table3_markdown(const LengthValidationResult& result,
                            const LengthValidationSpec& spec) {
  std::ostringstream out;
  out << "# Table III in simulation: dynamic length estimation, error in % of length\n\n"
      << "Each cell: simulation max / RMSE (paper max / RMSE, Yoshida and Hosoda's Table III; "
         "the paper does not split by weight).\n";
  for (double weight : spec.weights_kg) {
    out << "\n## " << format_shortest(weight) << " kg\n\n";
    pam_columns(out, spec);
    for (SpringLaw law : spec.laws) {
      out << "| Eq. (" << equation_number(law) << ") |";
      for (const ValidationPam& pam : spec.pams) {
        for (const DynamicRow& row : result.rows) {
          if (row.pam != pam.name || row.law != law || row.weight_kg != weight) continue;
          out << ' ' << markdown_error_pct(row.sim);
          if (row.paper) out << " (" << markdown_error_pct(*row.paper) << ')';
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
