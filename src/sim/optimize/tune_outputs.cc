// tune_outputs.cc: see tune_outputs.h.
#include "sim/optimize/tune_outputs.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "base/atomic_file.h"
#include "base/format.h"
#include "base/input_error.h"
#include "sim/io/gnuplot.h"
#include "sim/io/outputs.h"
#include "sim/scenario/scenario_file.h"
#include "sim/io/staged_outputs.h"

namespace pamsim {
namespace {

// "<first>,<parameter keys>,<objective>_mean.." (and "<constraint>_mean.." if asked).
std::string csv_header(const std::string& first, const TuneDefinition& def, bool constraints) {
  std::string out = first;
  for (const TuneParameter& p : def.parameters) out += "," + p.key;
  for (const TuneObjective& o : def.objectives) out += "," + o.metric + "_mean";
  if (constraints) {
    for (const TuneConstraint& c : def.constraints) out += "," + c.metric + "_mean";
  }
  return out;
}

// A CSV cell: the shortest round-trip form, empty where there is no value.
std::string cell(double v) { return std::isfinite(v) ? format_shortest(v) : std::string(); }

std::string cells(const std::vector<double>& values) {
  std::string out;
  for (double v : values) out += "," + cell(v);
  return out;
}

// convergence: every evaluation's first objective, and the best feasible so far
void write_convergence_plot(const TuneDefinition& def, const std::vector<TuneEvaluation>& history,
                            const std::string& png) {
  std::string all, running;
  double so_far = std::numeric_limits<double>::infinity();
  for (const TuneEvaluation& e : history) {
    all += gp_num(static_cast<double>(e.index)) + ' ' + gp_num(e.objectives[0]) + ' ' +
           (e.violation == 0.0 ? "1" : "0") + '\n';
    if (e.violation == 0.0) so_far = std::min(so_far, e.fitness[0]);
    if (std::isfinite(so_far)) {
      running += gp_num(static_cast<double>(e.index)) + ' ' +
                 gp_num(def.objectives[0].maximize ? -so_far : so_far) + '\n';
    }
  }
  GnuplotJob job;
  job.width_px = 1100;
  job.height_px = 700;
  job.data_files = {{"all.dat", all}, {"best.dat", running.empty() ? "0 nan\n" : running}};
  const std::string y = def.objectives[0].metric + " (mean over each evaluation's trials)";
  job.script = "set title " + gp_quote("pamsim tune: convergence") + "\nset grid\n" +
               "set xlabel 'evaluation'\nset ylabel " + gp_quote(y) + "\n" +
               "set key outside bottom center horizontal\n"
               "plot 'all.dat' using 1:($3 == 1 ? $2 : 1/0) with points pt 7 ps 0.6 lc rgb "
               "'#2471a3' title 'feasible', 'all.dat' using 1:($3 == 0 ? $2 : 1/0) with points "
               "pt 6 ps 0.6 lc rgb '#999999' title 'breaks a constraint', 'best.dat' using 1:2 "
               "with steps lw 2 lc rgb '#c0392b' title 'best feasible so far'\n";
  run_gnuplot(png, job);
}

// pareto.csv and pareto.png: the non-dominated feasible evaluations of two or more objectives
void write_pareto_outputs(const TuneDefinition& def, const std::vector<TuneEvaluation>& history,
                          const StagedOutputs& out, bool plots) {
  std::string csv = csv_header("evaluation", def, false) + "\n";
  std::string dat;
  for (const TuneEvaluation* e : pareto_front(history)) {
    csv += std::to_string(e->index);
    for (double v : e->values) csv += "," + format_shortest(v);
    for (double v : e->objectives) csv += "," + format_shortest(v);
    csv += "\n";
    dat += gp_num(e->objectives[0]) + ' ' + gp_num(e->objectives[1]) + '\n';
  }
  std::string all;
  for (const TuneEvaluation& e : history) {
    if (e.violation == 0.0) all += gp_num(e.objectives[0]) + ' ' + gp_num(e.objectives[1]) + '\n';
  }
  GnuplotJob job;
  job.width_px = 1000;
  job.height_px = 800;
  job.data_files = {{"front.dat", dat.empty() ? "nan nan\n" : dat},
                    {"all.dat", all.empty() ? "nan nan\n" : all}};
  job.script = "set title " + gp_quote("pamsim tune: Pareto front (feasible evaluations)") +
               "\nset grid\nset xlabel " + gp_quote(def.objectives[0].metric) + "\nset ylabel " +
               gp_quote(def.objectives[1].metric) +
               "\nplot 'all.dat' with points pt 6 lc rgb '#999999' title 'evaluated', "
               "'front.dat' with linespoints pt 7 lc rgb '#c0392b' title 'non-dominated'\n";
  if (plots) run_gnuplot(out.path("pareto.png"), job);
  write_file_atomically(out.path("pareto.csv"), csv);
}

// best.toml: the best setting as a ready scenario (paths relative to the output folder)
void write_best_scenario(const TuneDefinition& def, const TuneEvaluation& best,
                         const StagedOutputs& out) {
  std::ostringstream header;
  header << "# pamsim tune: evaluation " << best.index << " of " << def.file << " ("
         << (best.violation == 0.0 ? "the best feasible" : "none feasible: the least violating")
         << "), " << def.objectives[0].metric << " mean " << format_value(best.objectives[0])
         << "\n";
  write_file_atomically(out.path("best.toml"), resolved_scenario_toml(def.base_text, def.base_path,
                                                                      def.overrides_at(best.values),
                                                                      out.dir(), header.str()));
}

}  // namespace

std::string tune_evaluations_csv(const TuneDefinition& def,
                                 const std::vector<TuneEvaluation>& history) {
  std::string out = csv_header("evaluation", def, false) + ",violation,feasible,trials,ok\n";
  for (const TuneEvaluation& e : history) {
    out += std::to_string(e.index) + cells(e.values) + cells(e.objectives) + "," +
           cell(e.violation) + "," + (e.violation == 0.0 ? "1" : "0") + "," +
           std::to_string(e.trials) + "," + std::to_string(e.ok) + "\n";
  }
  return out;
}

std::string held_out_csv(const TuneDefinition& def, const std::vector<HeldOutCheck>& checks) {
  std::string out = csv_header("setting", def, true) + ",violation,trials,ok\n";
  for (const HeldOutCheck& c : checks) {
    out += c.name + cells(c.values) + cells(c.objectives) + cells(c.constraints) + "," +
           cell(c.violation) + "," + std::to_string(c.trials) + "," + std::to_string(c.ok) + "\n";
  }
  return out;
}

void write_tune_outputs(const TuneDefinition& def, const std::vector<TuneEvaluation>& history,
                        const StagedOutputs& out, bool plots) {
  if (history.empty()) throw InputError("no evaluation stored yet: nothing to report");
  if (plots) write_convergence_plot(def, history, out.path("convergence.png"));
  if (def.objectives.size() > 1) write_pareto_outputs(def, history, out, plots);
  write_file_atomically(out.path("evaluations.csv"), tune_evaluations_csv(def, history));
  write_best_scenario(def, *best_evaluation(history), out);
}

}  // namespace pamsim
