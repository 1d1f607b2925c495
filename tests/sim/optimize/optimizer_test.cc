// optimizer_test.cc: the search driver (src/sim/optimize/optimizer.h) with objectives defined
// here, not by tuning: a second client plugs in through Objective alone, without touching the
// driver. Checked against closed forms (the bowl's minimum, the Pareto set of two linear
// objectives), against an uninterrupted run (resume by replay), and on hand-made histories.
#include "sim/optimize/optimizer.h"

#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <vector>

namespace pamsim {
namespace {

// A bowl with its minimum at (0.3, 0.7) of the unit box; stores every evaluation as a
// database would, and can ask for a stop after `stop_after` evaluations.
class Bowl final : public Objective {
 public:
  std::vector<Evaluation> stored;
  int calls = 0;
  int stop_after = -1;
  std::atomic<bool> stop{false};

  std::size_t dimension() const override { return 2; }
  std::size_t objective_count() const override { return 1; }
  Evaluation evaluate(std::int64_t index, const std::vector<double>& u) override {
    ++calls;
    Evaluation e;
    e.index = index;
    e.unit = u;
    e.values = u;
    const double f = (u[0] - 0.3) * (u[0] - 0.3) + (u[1] - 0.7) * (u[1] - 0.7);
    e.objectives = {f};
    e.fitness = {f};
    stored.push_back(e);
    if (calls == stop_after) stop = true;
    return e;
  }
};

// Two objectives, u0 and 1 - u0 + u1^2: every point with u1 = 0 is Pareto-optimal.
class TwoObjectives final : public Objective {
 public:
  std::vector<Evaluation> stored;
  std::size_t dimension() const override { return 2; }
  std::size_t objective_count() const override { return 2; }
  Evaluation evaluate(std::int64_t index, const std::vector<double>& u) override {
    Evaluation e;
    e.index = index;
    e.unit = u;
    e.values = u;
    e.objectives = {u[0], 1.0 - u[0] + u[1] * u[1]};
    e.fitness = e.objectives;
    stored.push_back(e);
    return e;
  }
};

SearchSettings cmaes(unsigned generations) {
  SearchSettings s;
  s.algorithm = SearchAlgorithm::kCmaes;
  s.generations = generations;
  s.population = 10;
  s.seed = 7;
  return s;
}

TEST(OptimizerTest, CmaesFindsTheMinimumOfABowlDefinedOutsideTheDriver) {
  Bowl bowl;
  const SearchResult r = run_search(cmaes(40), bowl, {}, {});
  EXPECT_FALSE(r.interrupted);
  EXPECT_EQ(static_cast<std::int64_t>(bowl.stored.size()) + r.cached, cmaes(40).evaluations());
  const Evaluation* best = best_evaluation(bowl.stored);
  ASSERT_NE(best, nullptr);
  EXPECT_NEAR(best->values[0], 0.3, 0.01);
  EXPECT_NEAR(best->values[1], 0.7, 0.01);
}

TEST(OptimizerTest, AStoppedSearchResumedFromItsStoredEvaluationsIsTheUninterruptedOne) {
  Bowl whole;
  run_search(cmaes(6), whole, {}, {});

  Bowl part;
  part.stop_after = 17;
  SearchOptions stopping;
  stopping.stop = &part.stop;
  EXPECT_TRUE(run_search(cmaes(6), part, {}, stopping).interrupted);
  ASSERT_EQ(part.stored.size(), 17u);

  Bowl rest;
  const SearchResult resumed = run_search(cmaes(6), rest, part.stored, {});
  EXPECT_FALSE(resumed.interrupted);
  EXPECT_GE(resumed.cached, 17);
  // nothing evaluated twice, and the same points in the same order
  EXPECT_EQ(part.calls + rest.calls, whole.calls);
  std::vector<Evaluation> joined = part.stored;
  joined.insert(joined.end(), rest.stored.begin(), rest.stored.end());
  ASSERT_EQ(joined.size(), whole.stored.size());
  for (std::size_t i = 0; i < joined.size(); ++i) {
    EXPECT_EQ(joined[i].index, whole.stored[i].index);
    EXPECT_EQ(joined[i].unit, whole.stored[i].unit);
  }
}

// A stall stop ends CMA-ES once its best stops falling (on the bowl, near the minimum, long
// before its generations), and a stopped run resumes to the same end.
TEST(OptimizerTest, AStallStopEndsCmaesWhenItsBestNoLongerFallsAndResumesToTheSameEnd) {
  SearchSettings s = cmaes(300);
  s.stall_generations = 5;
  s.stall_absolute = 1e-6;
  Bowl whole;
  const SearchResult r = run_search(s, whole, {}, {});
  EXPECT_GE(r.generations, 5u);
  EXPECT_LT(r.generations, 300u);
  EXPECT_EQ(static_cast<std::int64_t>(whole.stored.size()) + r.cached,
            static_cast<std::int64_t>(s.population) * (r.generations + 1));
  const Evaluation* best = best_evaluation(whole.stored);
  ASSERT_NE(best, nullptr);
  EXPECT_NEAR(best->values[0], 0.3, 0.01);
  EXPECT_NEAR(best->values[1], 0.7, 0.01);

  Bowl part;
  part.stop_after = 23;
  SearchOptions stopping;
  stopping.stop = &part.stop;
  EXPECT_TRUE(run_search(s, part, {}, stopping).interrupted);
  Bowl rest;
  const SearchResult resumed = run_search(s, rest, part.stored, {});
  EXPECT_EQ(resumed.generations, r.generations);
  EXPECT_EQ(part.calls + rest.calls, whole.calls) << "nothing evaluated twice";
  ASSERT_FALSE(rest.stored.empty());
  EXPECT_EQ(rest.stored.back().unit, whole.stored.back().unit);
}

TEST(OptimizerTest, Nsga2FrontIsNonDominatedAndApproachesTheParetoSet) {
  TwoObjectives two;
  SearchSettings s;
  s.algorithm = SearchAlgorithm::kNsga2;
  s.generations = 40;
  s.population = 16;
  s.seed = 3;
  run_search(s, two, {}, {});
  const std::vector<const Evaluation*> front = pareto_front(two.stored);
  ASSERT_GE(front.size(), 3u);
  for (const Evaluation* a : front) {
    EXPECT_LT(a->unit[1], 0.1);  // the Pareto set is u1 = 0
    for (const Evaluation* b : front) {
      const bool b_dominates_a = b->fitness[0] <= a->fitness[0] && b->fitness[1] <= a->fitness[1] &&
                                 b->fitness != a->fitness;
      EXPECT_FALSE(b_dominates_a);
    }
  }
  for (std::size_t i = 1; i < front.size(); ++i) {
    EXPECT_LE(front[i - 1]->fitness[0], front[i]->fitness[0]);  // sorted by the first
  }
}

Evaluation scored(std::int64_t index, double fitness, double violation) {
  Evaluation e;
  e.index = index;
  e.fitness = {fitness};
  e.violation = violation;
  return e;
}

TEST(OptimizerTest, TheBestIsTheLowestFeasibleOrElseTheLeastViolatingAndTheEarliestOfEquals) {
  EXPECT_EQ(best_evaluation({}), nullptr);
  const std::vector<Evaluation> mixed = {scored(0, -5.0, 0.2), scored(1, 3.0, 0.0),
                                         scored(2, 2.0, 0.0), scored(3, 2.0, 0.0)};
  EXPECT_EQ(best_evaluation(mixed)->index, 2);
  const std::vector<Evaluation> infeasible = {scored(0, 1.0, 0.5), scored(1, 9.0, 0.1),
                                              scored(2, 0.0, 0.1)};
  EXPECT_EQ(best_evaluation(infeasible)->index, 1);
  EXPECT_TRUE(pareto_front(infeasible).empty());
}

}  // namespace
}  // namespace pamsim
