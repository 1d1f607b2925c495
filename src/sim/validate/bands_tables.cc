// bands_tables.cc: the files of a band run and of a sensitivity run (bands.h): bands.csv,
// bands.md, draws.csv and the band chart bands.png; sensitivity.csv and sensitivity.md.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <optional>
#include <sstream>

#include "base/atomic_file.h"
#include "base/format.h"
#include "sim/io/gnuplot.h"
#include "sim/io/outputs.h"
#include "sim/validate/bands.h"
#include "sim/validate/table_cells.h"

namespace pamsim {
namespace {

// One metric of one cell over the rigs: max (false) or RMSE (true).
BandStats cell_stats(const Bands& b, std::size_t c, bool rmse) {
  std::vector<double> values;
  for (const std::vector<ErrorPct>& rig : b.runs.errors) {
    values.push_back(rmse ? rig[c].rmse_pct : rig[c].max_pct);
  }
  return band_stats(values);
}

// "inside", "outside" or "" (no paper value): the paper's value within the 5-95 % range
std::string verdict(const BandStats& s, const std::optional<ErrorPct>& paper, bool rmse) {
  if (!paper || s.n == 0) return "";
  const double p = rmse ? paper->rmse_pct : paper->max_pct;
  return p >= s.p5 && p <= s.p95 ? "inside" : "outside";
}

// "The protocol refused k of N <what>: <first reason>.\n\n", or "" when it ran them all
std::string refusals(const RunCells& runs, const std::string& what) {
  const int k = runs.refused_count();
  if (k == 0) return "";
  const auto first = std::find_if(runs.refused.begin(), runs.refused.end(),
                                  [](const std::string& r) { return !r.empty(); });
  return "The protocol could not run " + std::to_string(k) + " of " +
         std::to_string(runs.refused.size()) + " " + what +
         " (their cells n/a); the first: " + *first + "\n\n";
}

// The brackets as a Markdown table, an assumption's source marked as one
std::string bracket_rows(const std::vector<Bracket>& brackets) {
  std::string rows = markdown_header("unknown", {"key", "from", "to", "source"});
  for (const Bracket& k : brackets) {
    rows += "| " + k.name + " | " + k.key + " | " + format_value(k.from) + " | " +
            format_value(k.to) + " | " + (k.assumption ? "ASSUMPTION: " : "") + k.source + " |\n";
  }
  return rows;
}

std::string band_text(const BandStats& s) {
  if (s.n == 0) return "n/a";
  return markdown_number(s.median) + " [" + markdown_number(s.p5) + ", " + markdown_number(s.p95) +
         "]";
}

}  // namespace

std::string bands_csv(const Bands& b) {
  std::ostringstream out;
  out << "cell,metric,rigs,median_pct,p5_pct,p95_pct,min_pct,max_pct,paper_pct,paper_is\n";
  for (std::size_t c = 0; c < b.runs.cells.size(); ++c) {
    for (bool rmse : {false, true}) {
      const BandStats s = cell_stats(b, c, rmse);
      const std::optional<ErrorPct>& paper = b.runs.paper[c];
      out << csv_text(b.runs.cells[c]) << ',' << (rmse ? "rmse" : "max_error") << ',' << s.n << ','
          << csv_number(s.n ? s.median : NAN) << ',' << csv_number(s.n ? s.p5 : NAN) << ','
          << csv_number(s.n ? s.p95 : NAN) << ',' << csv_number(s.n ? s.min : NAN) << ','
          << csv_number(s.n ? s.max : NAN) << ','
          << (paper ? csv_number(rmse ? paper->rmse_pct : paper->max_pct) : "") << ','
          << verdict(s, paper, rmse) << '\n';
    }
  }
  return out.str();
}

std::string draws_csv(const Bands& b) {
  std::ostringstream out;
  out << "rig";
  for (const Bracket& k : b.brackets) out << ',' << k.key;
  for (const std::string& cell : b.runs.cells) out << ',' << csv_text(cell + " rmse_pct");
  out << ",refused\n";
  for (std::size_t r = 0; r < b.draws.size(); ++r) {
    out << r;
    for (double v : b.draws[r]) out << ',' << csv_number(v);
    for (const ErrorPct& e : b.runs.errors[r]) out << ',' << csv_number(e.rmse_pct);
    out << ',' << csv_text(b.runs.refused[r]) << '\n';
  }
  return out.str();
}

std::string bands_markdown(const Bands& b) {
  std::ostringstream out;
  out << "# Bands: pamsim validate " << b.protocol << ", " << b.draws.size()
      << " rigs drawn from the brackets\n\n"
      << "Each cell: " << b.cases_are << "; error in % of length over the drawn rigs as median ["
      << kBandLow * 100 << " %, " << kBandHigh * 100
      << " %], every hardware source on; the paper's "
      << "value beside, inside or outside that range.\n\n";
  out << markdown_header("cell", {"max error", "RMSE", "paper max / RMSE", "paper is (max, RMSE)"});
  int inside = 0, judged = 0;
  for (std::size_t c = 0; c < b.runs.cells.size(); ++c) {
    const BandStats mx = cell_stats(b, c, false), rm = cell_stats(b, c, true);
    const std::optional<ErrorPct>& paper = b.runs.paper[c];
    out << "| " << b.runs.cells[c] << " | " << band_text(mx) << " | " << band_text(rm) << " | "
        << (paper ? markdown_error_pct(*paper) : "-") << " | ";
    if (paper && rm.n > 0) {
      out << verdict(mx, paper, false) << ", " << verdict(rm, paper, true);
      judged += 1;
      inside += verdict(rm, paper, true) == "inside";
    } else {
      out << "-";
    }
    out << " |\n";
  }
  const bool assumed = std::any_of(b.brackets.begin(), b.brackets.end(),
                                   [](const Bracket& k) { return k.assumption; });
  out << "\nThe paper's RMSE inside the range: " << inside << " of " << judged << " cells"
      << (assumed ? ", assumptions drawn too: not the headline count, which draws the sourced "
                    "brackets alone.\n\n"
                  : ".\n\n")
      << refusals(b.runs, "rigs") << "The brackets (drawn uniformly, bracket_seed " << b.seed
      << "):\n\n"
      << bracket_rows(b.brackets);
  if (!b.held.empty()) {
    out << "\nAssumptions, not drawn (held at the scenario's values; --assumptions draws "
           "them):\n\n"
        << bracket_rows(b.held);
  }
  return out.str();
}

std::string sensitivity_csv(const Sensitivity& s) {
  std::ostringstream out;
  out << "cell,bracket,key,from,to,rmse_at_from_pct,rmse_at_to_pct,swing_pct,rmse_middle_pct\n";
  const std::vector<std::vector<ErrorPct>>& e = s.runs.errors;
  for (std::size_t c = 0; c < s.runs.cells.size(); ++c) {
    for (std::size_t b = 0; b < s.brackets.size(); ++b) {
      const Bracket& k = s.brackets[b];
      out << csv_text(s.runs.cells[c]) << ',' << k.name << ',' << k.key << ',' << csv_number(k.from)
          << ',' << csv_number(k.to) << ',' << csv_number(e[2 * b + 1][c].rmse_pct) << ','
          << csv_number(e[2 * b + 2][c].rmse_pct) << ',' << csv_number(s.swing(b, c)) << ','
          << csv_number(e[0][c].rmse_pct) << '\n';
    }
  }
  return out.str();
}

std::string sensitivity_markdown(const Sensitivity& s) {
  std::ostringstream out;
  out << "# Sensitivity: pamsim validate " << s.protocol << "\n\n"
      << "Each cell: " << s.cases_are << "; the RMSE's swing [% of length] as one unknown goes "
      << "across its bracket (its range over the bracket's two ends and middle, a rig the "
      << "protocol refused left out), every other at its bracket's middle (every hardware "
      << "source on). The dominant unknown of each cell: the largest swing.\n\n";
  std::vector<std::string> columns;
  for (const Bracket& k : s.brackets) columns.push_back(k.name);
  columns.push_back("dominant");
  out << markdown_header("cell (RMSE at the middles)", columns);
  for (std::size_t c = 0; c < s.runs.cells.size(); ++c) {
    out << "| " << s.runs.cells[c] << " (" << markdown_number(s.runs.errors[0][c].rmse_pct)
        << ") |";
    std::optional<std::size_t> top;  // the largest finite swing
    for (std::size_t b = 0; b < s.brackets.size(); ++b) {
      out << ' ' << markdown_number(s.swing(b, c)) << " |";
      if (std::isfinite(s.swing(b, c)) && (!top || s.swing(b, c) > s.swing(*top, c))) top = b;
    }
    out << ' ' << (top ? s.brackets[*top].name : "-") << " |\n";
  }
  out << '\n' << refusals(s.runs, "runs");
  return out.str();
}

void write_bands(const Bands& b, const std::string& out_dir, bool draw) {
  namespace fs = std::filesystem;
  make_directories(out_dir);
  write_file_atomically((fs::path(out_dir) / "bands.csv").string(), bands_csv(b));
  write_file_atomically((fs::path(out_dir) / "bands.md").string(), bands_markdown(b));
  write_file_atomically((fs::path(out_dir) / "draws.csv").string(), draws_csv(b));
  if (!draw) return;
  // per cell: the 5-95 % range of the RMSE as a bar, its median, the paper's value
  std::ostringstream data;
  for (std::size_t c = 0; c < b.runs.cells.size(); ++c) {
    const BandStats s = cell_stats(b, c, true);
    data << c << "\t\"" << b.runs.cells[c] << "\"\t" << gp_num(s.n ? s.p5 : NAN) << '\t'
         << gp_num(s.n ? s.median : NAN) << '\t' << gp_num(s.n ? s.p95 : NAN) << '\t'
         << gp_num(b.runs.paper[c] ? b.runs.paper[c]->rmse_pct : NAN) << '\n';
  }
  GnuplotJob job;
  job.width_px = 1200;
  job.height_px = 700;
  job.data_files = {{"bands.dat", data.str()}};
  job.script =
      "set datafile separator '\\t'\n"
      "set title " +
      gp_quote("pamsim validate " + b.protocol + " --bands " + std::to_string(b.draws.size())) +
      " noenhanced\n"
      "set ylabel 'RMS error [% of length]'\nset grid ytics\nset yrange [0:*]\n"
      "set xtics rotate by -40 noenhanced\nset key outside right top\n"
      "set offsets 0.5, 0.5, 0, 0\n"
      "plot 'bands.dat' using 1:4:3:5:xtic(2) with yerrorbars pt 7 lc rgb '#1f77b4' "
      "title 'median, 5-95 % of the rigs', "
      "'' using 1:6 with points pt 9 ps 1.5 lc rgb '#d62728' title 'paper'\n";
  run_gnuplot((fs::path(out_dir) / "bands.png").string(), job);
}

void write_sensitivity(const Sensitivity& s, const std::string& out_dir) {
  namespace fs = std::filesystem;
  make_directories(out_dir);
  write_file_atomically((fs::path(out_dir) / "sensitivity.csv").string(), sensitivity_csv(s));
  write_file_atomically((fs::path(out_dir) / "sensitivity.md").string(), sensitivity_markdown(s));
}

}  // namespace pamsim
