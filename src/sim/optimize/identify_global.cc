// identify_global.cc: see identify_global.h.
#include "sim/optimize/identify_global.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "sim/optimize/identify_offsets.h"
#include "sim/optimize/optimizer.h"

namespace pamsim {
namespace {

// A fall of the cost that does not count as progress for the stall stop, on top of 0.1 % of
// it: one unit of a cost whose residuals are in noise floors.
constexpr double kStallCost = 1.0;

// A failed point's fitness for CMA-ES: worse than any point whose trials ran.
constexpr double kFailedCost = 1e300;

// The global phase's objective: a point's cost (sum of squares), CMA-ES moving only the
// parameters the projection leaves to it, each point's offsets at their best
// (identify_offsets.h); the evaluation's unit is the whole projected point.
class IdentifyObjective : public Objective {
 public:
  IdentifyObjective(IdentifyResiduals& residuals, const OffsetProjection& projection)
      : residuals_(residuals), projection_(projection) {}
  std::size_t dimension() const override { return projection_.searched().size(); }
  std::size_t objective_count() const override { return 1; }
  Evaluation evaluate(std::int64_t index, const std::vector<double>& searched) override {
    Evaluation e;
    e.index = index;
    e.unit = projection_.embed(searched);
    std::vector<double> r = residuals_.at(e.unit, "global");
    if (projection_.projects() && !r.empty()) {
      e.unit = projection_.project(e.unit, r);
      r = residuals_.at(e.unit, "global");  // the same trials, other offsets
    }
    e.values = residuals_.values_at(e.unit);
    const double cost = sum_of_squares(r);
    e.objectives = {cost};
    e.fitness = {std::isfinite(cost) ? cost : kFailedCost};
    e.trials = 1;
    e.ok = std::isfinite(cost) ? 1 : 0;
    return e;
  }

 private:
  IdentifyResiduals& residuals_;
  const OffsetProjection& projection_;
};

// The runs' evaluations, pooled, best first (the earlier of equals); a point further than
// kStartSpacing (in some parameter) from every start in `starts` joins them, up to def.starts.
void add_distinct_starts(const IdentifyDefinition& def, std::vector<Evaluation> pooled,
                         std::vector<GlobalStart>* starts) {
  std::stable_sort(pooled.begin(), pooled.end(), [](const Evaluation& a, const Evaluation& b) {
    return a.fitness.at(0) < b.fitness.at(0);
  });
  for (const Evaluation& e : pooled) {
    if (starts->size() >= static_cast<std::size_t>(def.starts)) break;
    const bool apart = std::all_of(starts->begin(), starts->end(), [&](const GlobalStart& s) {
      double d = 0.0;
      for (std::size_t i = 0; i < s.unit.size(); ++i) {
        d = std::max(d, std::abs(s.unit[i] - e.unit[i]));
      }
      return d >= kStartSpacing;
    });
    if (apart) starts->push_back({e.unit, -1});
  }
}

// Keeps every evaluation of a run (for its best point) and reports progress.
class Recorder : public Objective {
 public:
  Recorder(IdentifyObjective& inner, std::vector<Evaluation>& out, std::int64_t* count,
           const IdentifyRunOptions& options)
      : inner_(inner), out_(out), count_(*count), options_(options) {}
  std::size_t dimension() const override { return inner_.dimension(); }
  std::size_t objective_count() const override { return 1; }
  Evaluation evaluate(std::int64_t index, const std::vector<double>& unit) override {
    out_.push_back(inner_.evaluate(index, unit));
    if (options_.on_progress) options_.on_progress("global", ++count_);
    return out_.back();
  }

 private:
  IdentifyObjective& inner_;
  std::vector<Evaluation>& out_;
  std::int64_t& count_;
  const IdentifyRunOptions& options_;
};

}  // namespace

std::vector<GlobalStart> global_search(const IdentifyDefinition& def, IdentifyResiduals& residuals,
                                       const IdentifyRunOptions& options, bool* interrupted,
                                       std::vector<unsigned>* generations) {
  const std::size_t n = def.parameters.size();
  if (def.generations == 0) return {{std::vector<double>(n, 0.5), 0}};
  const OffsetProjection projection(def, residuals);
  IdentifyObjective objective(residuals, projection);
  if (projection.searched().empty()) return {{objective.evaluate(0, {}).unit, 0}};
  SearchOptions search;
  search.stop = options.stop;
  std::vector<GlobalStart> starts;
  std::vector<Evaluation> pooled;
  std::int64_t evaluated = 0;
  for (int run = 0; run < def.runs && !*interrupted; ++run) {
    // run r: seed + r, population x 2^r (pagmo's seeds are 32-bit)
    SearchSettings settings{SearchAlgorithm::kCmaes, def.generations, def.population << run,
                            (def.seed + run) & 0xffffffffULL};
    settings.stall_generations = def.stall_generations;
    settings.stall_absolute = kStallCost;
    std::vector<Evaluation> history;
    Recorder recorder(objective, history, &evaluated, options);
    const SearchResult ran = run_search(settings, recorder, {}, search);
    *interrupted = ran.interrupted;
    generations->push_back(ran.generations);
    if (const Evaluation* best = best_evaluation(history)) starts.push_back({best->unit, run});
    pooled.insert(pooled.end(), history.begin(), history.end());
  }
  add_distinct_starts(def, std::move(pooled), &starts);
  if (starts.empty()) starts.push_back({std::vector<double>(n, 0.5), 0});
  return starts;
}

}  // namespace pamsim
