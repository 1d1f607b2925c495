// error_budget_tables.cc: the error budget's files (error_budget.h): budget.csv, budget.md
// and the bar chart budget.png.
#include <cmath>
#include <filesystem>
#include <sstream>

#include "base/atomic_file.h"
#include "sim/io/gnuplot.h"
#include "sim/io/outputs.h"
#include "sim/validate/error_budget.h"
#include "sim/validate/table_cells.h"

namespace pamsim {
namespace {

using Kind = BudgetConfig::Kind;

// The source a run names ("" for none and all)
std::string run_source(const ErrorBudget& b, const BudgetConfig& c) {
  return c.source >= 0 ? b.sources[c.source].name : "";
}

// A row's share: alone on an "only" run, by removal on an "all but" run
double run_share(const ErrorBudget& b, const BudgetConfig& c, std::size_t k) {
  if (c.kind == Kind::kOnly) return b.share_alone(c.source, k);
  if (c.kind == Kind::kWithout) return b.share_by_removal(c.source, k);
  return std::nan("");
}

// sqrt(RMSE(none)^2 + sum of the shares alone squared): what RMSE(all) would be were the
// sources independent and additive
double quadrature_sum(const ErrorBudget& b, std::size_t k) {
  const double none = b.at(Kind::kNone, -1, k).rmse_pct;
  double sum = none * none;
  for (std::size_t s = 0; s < b.sources.size(); ++s) {
    const double share = b.share_alone(static_cast<int>(s), k);
    sum += share * share;
  }
  return std::sqrt(sum);
}

}  // namespace

std::string budget_csv(const ErrorBudget& b) {
  std::ostringstream out;
  out << "case,config,source,max_error_pct,rmse_pct,share_rmse_pct\n";
  for (std::size_t k = 0; k < b.cases.size(); ++k) {
    for (std::size_t r = 0; r < b.configs.size(); ++r) {
      const BudgetConfig& c = b.configs[r];
      out << b.cases[k] << ',' << c.name << ',' << run_source(b, c) << ','
          << csv_number(b.errors[r][k].max_pct) << ',' << csv_number(b.errors[r][k].rmse_pct) << ','
          << csv_number(run_share(b, c, k)) << '\n';
    }
  }
  return out.str();
}

std::string budget_markdown(const ErrorBudget& b) {
  std::ostringstream out;
  out << "# Error budget: pamsim validate " << b.protocol << "\n\n"
      << "Cases: " << b.cases_are << ". Errors in % of length. Each source is turned on and off "
      << "by the scenario keys of the protocol file's [[budget_source]] tables.\n\n"
      << "## Every run: max / RMSE\n\n";
  out << markdown_header("run", b.cases);
  for (std::size_t r = 0; r < b.configs.size(); ++r) {
    out << "| " << b.configs[r].name << " |";
    for (std::size_t k = 0; k < b.cases.size(); ++k) {
      out << ' ' << markdown_error_pct(b.errors[r][k]) << " |";
    }
    out << '\n';
  }
  out << "\n## Each source's share of the RMS error: alone / by removal\n\n"
      << "Alone: sqrt(RMSE(only s)^2 - RMSE(none)^2); by removal: sqrt(RMSE(all)^2 - "
         "RMSE(all but s)^2); 0 where the source lowers the error.\n\n";
  out << markdown_header("source", b.cases);
  for (std::size_t s = 0; s < b.sources.size(); ++s) {
    out << "| " << b.sources[s].name << " |";
    for (std::size_t k = 0; k < b.cases.size(); ++k) {
      out << ' ' << markdown_number(b.share_alone(static_cast<int>(s), k)) << " / "
          << markdown_number(b.share_by_removal(static_cast<int>(s), k)) << " |";
    }
    out << '\n';
  }
  const auto row = [&](const char* name, auto value) {
    out << "| " << name << " |";
    for (std::size_t k = 0; k < b.cases.size(); ++k) out << ' ' << value(k) << " |";
    out << '\n';
  };
  row("none (the fit and the plant's dynamics)",
      [&](std::size_t k) { return markdown_number(b.at(Kind::kNone, -1, k).rmse_pct); });
  row("all", [&](std::size_t k) { return markdown_number(b.at(Kind::kAll, -1, k).rmse_pct); });
  row("sqrt(none^2 + sum of shares alone^2), its ratio to all", [&](std::size_t k) {
    const double sum = quadrature_sum(b, k);
    return markdown_number(sum) + " (" + markdown_number(sum / b.at(Kind::kAll, -1, k).rmse_pct) +
           ")";
  });
  return out.str();
}

void write_error_budget(const ErrorBudget& b, const std::string& out_dir, bool draw) {
  namespace fs = std::filesystem;
  make_directories(out_dir);
  write_file_atomically((fs::path(out_dir) / "budget.csv").string(), budget_csv(b));
  write_file_atomically((fs::path(out_dir) / "budget.md").string(), budget_markdown(b));
  if (!draw) return;
  // one cluster of bars per case: the none run's RMSE, then each source's share alone
  std::ostringstream data;
  data << "case\t\"none (fit, dynamics)\"";
  for (const BudgetSource& s : b.sources) data << "\t\"" << s.name << '"';
  data << '\n';
  for (std::size_t k = 0; k < b.cases.size(); ++k) {
    data << '"' << b.cases[k] << "\"\t" << gp_num(b.at(Kind::kNone, -1, k).rmse_pct);
    for (std::size_t s = 0; s < b.sources.size(); ++s) {
      data << '\t' << gp_num(b.share_alone(static_cast<int>(s), k));
    }
    data << '\n';
  }
  GnuplotJob job;
  job.width_px = 1200;
  job.height_px = 700;
  job.data_files = {{"budget.dat", data.str()}};
  job.script =
      "set datafile separator '\\t'\n"
      "set title " +
      gp_quote("Error budget: pamsim validate " + b.protocol + " (" + b.cases_are + ")") +
      " noenhanced\n"
      "set ylabel 'RMS error: the none run, each source alone [% of length]'\n"
      "set style data histograms\nset style histogram clustered gap 1\n"
      "set style fill solid 0.85 border -1\nset boxwidth 0.9\n"
      "set key outside right top noenhanced\nset grid ytics\nset yrange [0:*]\n"
      "set xtics noenhanced\n"
      "plot for [i=2:" +
      std::to_string(b.sources.size() + 2) +
      "] 'budget.dat' using i:xtic(1) title columnheader(i)\n";
  run_gnuplot((fs::path(out_dir) / "budget.png").string(), job);
}

}  // namespace pamsim
