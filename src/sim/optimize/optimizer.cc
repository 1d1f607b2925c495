// optimizer.cc: see optimizer.h.
#include "sim/optimize/optimizer.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
#include <pagmo/algorithm.hpp>
#include <pagmo/algorithms/cmaes.hpp>
#include <pagmo/algorithms/nsga2.hpp>
#include <pagmo/population.hpp>
#include <pagmo/problem.hpp>
#include <pagmo/types.hpp>
#include <string>
#include <utility>

namespace pamsim {
namespace {

// Thrown out of a fitness call to stop the optimiser (a stop was requested).
struct StopSearch {};

// What pagmo's problem calls: answers a point from memory or has the objective score it.
// pagmo copies the problem; every copy shares this.
struct Evaluator {
  Objective* objective = nullptr;
  SearchOptions options;
  std::map<std::vector<double>, std::vector<double>> cache;  // fitness by the point
  std::int64_t next_index = 0, cached = 0, total = 0, evaluated = 0;

  pagmo::vector_double fitness(const pagmo::vector_double& u) {
    const auto hit = cache.find(u);
    if (hit != cache.end()) {
      ++cached;
      if (options.on_evaluation) options.on_evaluation(++evaluated, total, true);
      return hit->second;
    }
    if (options.stop && options.stop->load()) throw StopSearch{};
    const Evaluation e = objective->evaluate(next_index++, u);
    cache.emplace(u, e.fitness);
    if (options.on_evaluation) options.on_evaluation(++evaluated, total, false);
    return e.fitness;
  }
};

struct Problem {
  std::shared_ptr<Evaluator> evaluator;
  std::size_t dimension = 1, objectives = 1;
  pagmo::vector_double fitness(const pagmo::vector_double& u) const {
    return evaluator->fitness(u);
  }
  std::pair<pagmo::vector_double, pagmo::vector_double> get_bounds() const {
    return {pagmo::vector_double(dimension, 0.0), pagmo::vector_double(dimension, 1.0)};
  }
  pagmo::vector_double::size_type get_nobj() const { return objectives; }
  std::string get_name() const { return "pamsim search"; }
  // the copies share one Evaluator (its cache and the objective): never call them concurrently
  pagmo::thread_safety get_thread_safety() const { return pagmo::thread_safety::none; }
};

pagmo::algorithm make_algorithm(const SearchSettings& s) {
  const auto seed = static_cast<unsigned>(s.seed);
  if (s.algorithm == SearchAlgorithm::kCmaes) {
    // with a stall stop, one generation per call, its state kept between calls (memory)
    const bool stepped = s.stall_generations > 0;
    return pagmo::algorithm{pagmo::cmaes(stepped ? 1u : s.generations, -1, -1, -1, -1, 0.3, 0.0,
                                         0.0, stepped, true, seed)};
  }
  return pagmo::algorithm{pagmo::nsga2(s.generations, 0.95, 10.0, 0.01, 50.0, seed)};
}

// CMA-ES a generation at a time until it stalls (SearchSettings::stall_generations) or has run
// every generation; returns the generations run.
unsigned evolve_until_stalled(const SearchSettings& s, pagmo::population* population) {
  pagmo::algorithm algorithm = make_algorithm(s);
  double reference = population->champion_f()[0];
  unsigned since = 0, g = 0;
  while (g < s.generations) {
    *population = algorithm.evolve(*population);
    ++g;
    const double best = population->champion_f()[0];
    if (best < reference - (s.stall_relative * std::abs(reference) + s.stall_absolute)) {
      reference = best;
      since = 0;
    } else if (++since >= s.stall_generations) {
      break;
    }
  }
  return g;
}

bool dominates(const Evaluation& a, const Evaluation& b) {
  bool better = false;
  for (std::size_t i = 0; i < a.fitness.size(); ++i) {
    if (a.fitness[i] > b.fitness[i]) return false;
    if (a.fitness[i] < b.fitness[i]) better = true;
  }
  return better;
}

}  // namespace

SearchResult run_search(const SearchSettings& settings, Objective& objective,
                        const std::vector<Evaluation>& stored, const SearchOptions& options) {
  auto evaluator = std::make_shared<Evaluator>();
  evaluator->objective = &objective;
  evaluator->options = options;
  evaluator->total = settings.evaluations();
  // a resume: the stored evaluations answer the replayed optimiser's calls
  for (const Evaluation& e : stored) {
    evaluator->cache.emplace(e.unit, e.fitness);  // the exact point pagmo asked for
    evaluator->next_index = std::max(evaluator->next_index, e.index + 1);
  }
  SearchResult result;
  try {
    pagmo::problem problem{Problem{evaluator, objective.dimension(), objective.objective_count()}};
    pagmo::population population{problem, settings.population,
                                 static_cast<unsigned>(settings.seed)};
    result.generations = settings.generations;
    if (settings.algorithm == SearchAlgorithm::kCmaes && settings.stall_generations > 0) {
      result.generations = evolve_until_stalled(settings, &population);
    } else {
      population = make_algorithm(settings).evolve(population);
    }
  } catch (const StopSearch&) {
    result.interrupted = true;
  }
  result.cached = evaluator->cached;
  return result;
}

const Evaluation* best_evaluation(const std::vector<Evaluation>& history) {
  const Evaluation* best = nullptr;
  for (const Evaluation& e : history) {
    if (!best) {
      best = &e;
      continue;
    }
    const bool e_ok = e.violation == 0.0, b_ok = best->violation == 0.0;
    if (e_ok != b_ok) {
      if (e_ok) best = &e;
      continue;
    }
    if (!e_ok ? e.violation < best->violation : e.fitness[0] < best->fitness[0]) best = &e;
  }
  return best;
}

std::vector<const Evaluation*> pareto_front(const std::vector<Evaluation>& history) {
  std::vector<const Evaluation*> front;
  for (const Evaluation& e : history) {
    if (e.violation != 0.0) continue;
    const bool dominated = std::any_of(history.begin(), history.end(), [&](const Evaluation& o) {
      return o.violation == 0.0 && dominates(o, e);
    });
    if (!dominated) front.push_back(&e);
  }
  std::sort(front.begin(), front.end(),
            [](const Evaluation* a, const Evaluation* b) { return a->fitness[0] < b->fitness[0]; });
  return front;
}

}  // namespace pamsim
