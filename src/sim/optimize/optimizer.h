// optimizer.h: the search driver that tuning (and identification) share: pagmo2's CMA-ES for
// one objective or NSGA-II for a Pareto front over the unit box [0, 1]^n, asking an Objective
// to score each point it proposes. The Objective stores every evaluation as it finishes (a
// database); the optimiser is deterministic for its seed, so a run interrupted at any point is
// resumed by replaying it with the stored evaluations answered from memory: nothing is
// evaluated twice (a point proposed again is answered the same way) and the result is the
// uninterrupted run's. pagmo proposes the points one by one.
#pragma once

#include <atomic>
#include <cstdint>
#include <functional>
#include <vector>

namespace pamsim {

// One point the optimiser proposed, as its objective scored it.
struct Evaluation {
  std::int64_t index = 0;
  std::vector<double> unit;        // the optimiser's point in [0, 1]^n (the resume's key)
  std::vector<double> values;      // the parameters' values at it
  std::vector<double> objectives;  // each objective as it reads (not negated)
  double violation = 0.0;          // constraints broken and trials failed; 0: feasible
  std::vector<double> fitness;     // what is minimised: objectives (signed) + penalty
  int trials = 0, ok = 0;          // trials run, trials that ran to the end
};

// What a client of the driver plugs in: its dimension, its number of objectives, and the
// scoring of one point (which the client also stores durably before it returns).
class Objective {
 public:
  virtual ~Objective() = default;
  virtual std::size_t dimension() const = 0;
  virtual std::size_t objective_count() const = 0;
  // Scores `unit` as evaluation number `index`; the result's index, unit and fitness are set.
  virtual Evaluation evaluate(std::int64_t index, const std::vector<double>& unit) = 0;
};

enum class SearchAlgorithm { kCmaes, kNsga2 };

struct SearchSettings {
  SearchAlgorithm algorithm = SearchAlgorithm::kCmaes;
  unsigned generations = 10, population = 8;
  std::uint64_t seed = 1;  // pagmo's seed, < 2^32
  // CMA-ES only: with stall_generations > 0 it stops once its best fitness has fallen by less
  // than stall_relative x |best| + stall_absolute over that many generations in a row
  // (`generations` is then the most it runs); 0: every generation.
  unsigned stall_generations = 0;
  double stall_relative = 1e-3, stall_absolute = 0.0;
  // The points the optimiser asks for at the most: the first population and one per generation.
  std::int64_t evaluations() const {
    return static_cast<std::int64_t>(population) * (generations + 1);
  }
};

struct SearchOptions {
  const std::atomic<bool>* stop = nullptr;  // set: finish the evaluation in flight, then stop
  std::function<void(std::int64_t evaluated, std::int64_t total, bool cached)> on_evaluation;
};

struct SearchResult {
  std::int64_t cached = 0;   // proposals answered from `stored` or from earlier proposals
  bool interrupted = false;  // stopped by options.stop
  unsigned generations = 0;  // generations run (CMA-ES with a stall stop; else as asked)
};

// Runs (or, with the evaluations `stored` before, resumes) the search. CMA-ES runs all its
// generations unless it stalls (SearchSettings::stall_generations); it needs exactly one
// objective.
SearchResult run_search(const SearchSettings& settings, Objective& objective,
                        const std::vector<Evaluation>& stored, const SearchOptions& options);

// The best feasible evaluation by the first fitness (the least violating if none is
// feasible; the earliest of equals); nullptr for none.
const Evaluation* best_evaluation(const std::vector<Evaluation>& history);
// The feasible evaluations no other feasible one dominates, by their first fitness.
std::vector<const Evaluation*> pareto_front(const std::vector<Evaluation>& history);

}  // namespace pamsim
