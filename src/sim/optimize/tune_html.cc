// tune_html.cc: see tune_html.h.
#include "sim/optimize/tune_html.h"

#include <cmath>
#include <limits>
#include <sstream>

#include "sim/io/html_page.h"
#include "sim/optimize/optimizer.h"

namespace pamsim {
namespace {

// The first objective of every evaluation (markers) and the best feasible so far (a line)
LineChart convergence(const TuneDefinition& def, const std::vector<TuneEvaluation>& history) {
  LineSeries every{"every evaluation", {}, {}, true}, best{"best feasible so far", {}, {}};
  double so_far = std::numeric_limits<double>::infinity();
  for (const TuneEvaluation& e : history) {
    const double x = static_cast<double>(e.index);
    every.x.push_back(x);
    every.y.push_back(e.objectives[0]);
    if (e.violation == 0.0) so_far = std::min(so_far, e.fitness[0]);
    if (std::isfinite(so_far)) {
      best.x.push_back(x);
      best.y.push_back(def.objectives[0].maximize ? -so_far : so_far);
    }
  }
  return {"convergence",
          "evaluation",
          def.objectives[0].metric + ", mean over its trials",
          {every, best}};
}

std::string best_table(const TuneDefinition& def, const TuneEvaluation& best) {
  std::ostringstream s;
  s << "<table id=\"best\"><tr><th>parameter</th><th>best</th><th>bounds</th></tr>";
  for (std::size_t i = 0; i < def.parameters.size(); ++i) {
    const TuneParameter& p = def.parameters[i];
    s << "<tr><td>" << html_escape(p.key) << "</td><td>" << short_number(best.values[i])
      << "</td><td>" << short_number(p.from) << " to " << short_number(p.to)
      << (p.log ? " (log)" : "") << "</td></tr>";
  }
  for (std::size_t k = 0; k < def.objectives.size(); ++k) {
    s << "<tr><td>" << html_escape(def.objectives[k].metric)
      << (def.objectives[k].maximize ? " (maximised)" : " (minimised)") << "</td><td>"
      << short_number(best.objectives[k]) << "</td><td>mean over " << best.trials
      << " trials</td></tr>";
  }
  s << "</table>";
  return s.str();
}

std::string evaluations_table(const TuneDefinition& def,
                              const std::vector<TuneEvaluation>& history) {
  std::ostringstream s;
  s << "<table id=\"evaluations\"><tr><th>evaluation</th>";
  for (const TuneParameter& p : def.parameters) s << "<th>" << html_escape(p.key) << "</th>";
  for (const TuneObjective& o : def.objectives) s << "<th>" << html_escape(o.metric) << "</th>";
  s << "<th>violation</th><th>trials ok</th></tr>\n";
  for (const TuneEvaluation& e : history) {
    s << "<tr><td>" << e.index << "</td>";
    for (double v : e.values) s << "<td>" << short_number(v) << "</td>";
    for (double v : e.objectives) s << "<td>" << short_number(v) << "</td>";
    s << "<td>" << short_number(e.violation) << "</td><td>" << e.ok << " / " << e.trials
      << "</td></tr>\n";
  }
  s << "</table>";
  return s.str();
}

}  // namespace

std::string tune_report_html(const TuneDefinition& def, const std::vector<TuneEvaluation>& history,
                             const std::string& db_path, const std::string& footer_html) {
  const TuneEvaluation& best = *best_evaluation(history);
  std::ostringstream body;
  body << "<h1>Tuning " << html_escape(def.file) << "</h1>\n<p>" << history.size()
       << " evaluations stored (" << def.generations << " generations of " << def.population << ", "
       << def.seeds << " seeds each). Database <code>" << html_escape(db_path)
       << "</code>.</p>\n<h2>The best setting</h2>\n<p>Evaluation " << best.index
       << (best.violation == 0.0 ? "" : ", though none is feasible") << ":</p>\n"
       << best_table(def, best) << "\n<h2>Convergence</h2>\n"
       << svg_line_chart(convergence(def, history)) << "\n<h2>Every evaluation</h2>\n"
       << evaluations_table(def, history);
  return html_document("pamsim report: " + def.file, body.str(), "", footer_html);
}

}  // namespace pamsim
