// identify_search_report.cc: how the identification's search ended, for the reports of
// identify_outputs.h: where the polish's starts ended against the result (start_warnings),
// the global search as it ran (global_search_text), and whether its runs agree (judge_settled).
#include <algorithm>
#include <cmath>

#include "base/format.h"
#include "sim/optimize/identify_outputs.h"
#include "sim/optimize/identify_residuals.h"

namespace pamsim {
namespace {

// How far polish end `e` lies from the result's: the most box units off in any parameter, and
// the most standard errors off in one the recordings determine (-1: none has a standard
// error), with the parameters that are. Ends within the polish's own difference step of each
// other in a parameter (kDifferenceStep of the box) are not apart in it, however small its
// standard error: the polish cannot tell them apart.
struct EndDistance {
  double box = 0.0, std_errors = -1.0;
  std::size_t by_box = 0, by_se = 0;
  // the same point as the result's (kSameEndErrors, kSameEnd; identify.h)
  bool same() const { return std_errors >= 0.0 ? std_errors <= kSameEndErrors : box <= kSameEnd; }
};

EndDistance end_distance(const IdentifyResult& r, const PolishEnd& e,
                         const std::vector<double>& at_e, const std::vector<double>& at_best) {
  const PolishEnd& best = r.starts[r.best_start];
  EndDistance d;
  for (std::size_t i = 0; i < e.end.size(); ++i) {
    const double box = std::abs(e.end[i] - best.end[i]);
    if (box > d.box) {
      d.box = box;
      d.by_box = i;
    }
    const IdentifiedParameter* p = i < r.parameters.size() ? &r.parameters[i] : nullptr;
    if (!p || !p->identifiable || !(p->std_error > 0.0)) continue;
    const double se = box > kDifferenceStep ? std::abs(at_e[i] - at_best[i]) / p->std_error : 0.0;
    if (se > d.std_errors) {
      d.std_errors = se;
      d.by_se = i;
    }
  }
  return d;
}

std::string where_apart(const IdentifyDefinition& def, const IdentifyResult& r, const PolishEnd& e,
                        EndDistance* distance) {
  const std::vector<double> at_e = parameter_values(def, e.end);
  const std::vector<double> at_best = parameter_values(def, r.starts[r.best_start].end);
  *distance = end_distance(r, e, at_e, at_best);
  if (e.end.empty()) return "";
  const double most_se = distance->std_errors;
  const std::size_t i = most_se >= 0.0 ? distance->by_se : distance->by_box;
  const std::string errors =
      " (" + format_value(std::round(most_se * 10) / 10) + " standard errors)";
  return def.parameters[i].key + " = " + format_value(at_e[i]) + " against " +
         format_value(at_best[i]) + (most_se >= 0.0 ? errors : "");
}

}  // namespace

std::vector<std::string> start_warnings(const IdentifyDefinition& def, const IdentifyResult& r) {
  std::vector<std::string> out;
  const std::size_t asked = static_cast<std::size_t>(std::max(def.starts, 1));
  if (asked > 1 && !r.starts.empty() && r.starts.size() < asked && !r.interrupted) {
    out.push_back("starts = " + std::to_string(asked) + " asked, " +
                  std::to_string(r.starts.size()) + " run: " +
                  (def.generations == 0
                       ? "without a global search (generations = 0) the polish starts from the "
                         "middle of the box alone"
                       : "the global search's points held no more that lie " +
                             format_value(kStartSpacing) +
                             " of the box apart (more generations "
                             "or a larger population give more)"));
  }
  if (r.starts.size() < 2) return out;
  const PolishEnd& best = r.starts[r.best_start];
  for (std::size_t k = 0; k < r.starts.size(); ++k) {
    const PolishEnd& e = r.starts[k];
    EndDistance distance;
    const std::string where = where_apart(def, r, e, &distance);
    // elsewhere: not the result's point in a parameter the recordings determine (an
    // undetermined one may end anywhere), or, without standard errors, in the box
    const bool elsewhere = !distance.same();
    const std::string start =
        "the polish's start " + std::to_string(k + 1) + " of " + std::to_string(r.starts.size());
    const std::string costs = "cost " + format_value(e.cost) + " against the result's " +
                              format_value(best.cost) + " (start " +
                              std::to_string(r.best_start + 1) + ")";
    if (e.cost > best.cost + kLocalMinimumMargin) {
      out.push_back(
          start + (e.converged ? " ended in a local minimum: " : " stopped without converging: ") +
          costs + ", at " + where);
    } else if (k != r.best_start && elsewhere) {
      out.push_back(start + " ended as low at another point: " + costs + ", at " + where +
                    ": the recordings do not single out one minimum");
    }
  }
  return out;
}

std::string global_search_text(const IdentifyDefinition& def, const IdentifyResult& r) {
  if (def.generations == 0) return "none: generations = 0";
  if (def.runs == 1 && def.stall_generations == 0) {
    return std::to_string(def.generations) + " generations of " + std::to_string(def.population);
  }
  std::string text = std::to_string(r.run_generations.size()) + " runs: ";
  for (std::size_t k = 0; k < r.run_generations.size(); ++k) {
    text += (k ? ", " : "") + std::to_string(r.run_generations[k]) +
            (k ? " of " : " generations of ") + std::to_string(def.population << k);
  }
  if (def.stall_generations > 0) {
    text += "; a run ends after " + std::to_string(def.stall_generations) +
            " generations without progress, or at " + std::to_string(def.generations);
  }
  return text;
}

SearchSettled judge_settled(const IdentifyDefinition& def, const IdentifyResult& r) {
  const PolishEnd& best = r.starts.at(r.best_start);
  const std::vector<double> at_best = parameter_values(def, best.end);
  int runs = 0, agreeing = 0;
  for (const PolishEnd& e : r.starts) {
    if (e.run < 0) continue;
    ++runs;
    const double most = std::max(best.cost + kLocalMinimumMargin, kSettledCostRatio * best.cost);
    const bool cheap = e.cost <= most;
    agreeing += cheap && end_distance(r, e, parameter_values(def, e.end), at_best).same();
  }
  if (runs < 2) return SearchSettled::kNotChecked;
  return agreeing >= 2 ? SearchSettled::kSettled : SearchSettled::kNotSettled;
}

}  // namespace pamsim
