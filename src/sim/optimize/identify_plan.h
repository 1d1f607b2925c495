// identify_plan.h: `pamsim identify --plan`: which of the file's [[candidate]] experiments
// would most shrink the parameters' uncertainty, at the identified point, by the D-optimal
// criterion on the Fisher information (plan_candidates).
#pragma once

#include <string>
#include <vector>

#include <Eigen/Dense>

#include "sim/optimize/identify.h"

namespace pamsim {

// The D-optimal gain of adding information `added` to `now` (both n x n, symmetric, `now`
// positive definite) and each parameter's standard deviation (in the unit box) after.
struct InformationGain {
  double d_gain = 0.0;
  Eigen::VectorXd sd;
};
InformationGain information_gain(const Eigen::MatrixXd& now, const Eigen::MatrixXd& added);

struct PlannedCandidate {
  std::string name;
  double d_gain = 0.0;
  std::vector<double> sd_after;  // per parameter, in its unit
};

struct IdentifyPlan {
  std::vector<std::string> keys;  // the parameters
  // per parameter, in its unit (the prior's where nothing sees it)
  std::vector<double> sd_now;
  std::vector<PlannedCandidate> ranked;  // best first (ties: the file's order)
  // "<candidate>: <why>" for a candidate whose trial failed
  std::vector<std::string> failures;
  // "<recording>: <why>" for a fitted recording or tensile test whose trial failed at a side
  // of a difference: its information is missing from F_now, so every gain is overstated
  std::vector<std::string> left_out;
};

// Each recording's (and candidate's) sensitivities dy/du, its channels' samples against the
// parameters in the unit box, come from central differences of kDifferenceStep (one-sided at
// a bound; a sensor's parameter re-samples the same trial), divided by each channel's noise
// floor: F = S^T S is its Fisher information for white noise of that floor. The information
// now is the prior I (each parameter somewhere in its range: a standard deviation of the
// whole range) plus the fitted recordings' and tensile tests' (a tensile test's floor: its
// RMSE after the fit). A candidate is ranked by the D-optimal criterion, the gain
// 0.5 ln det(F_now + F_c) - 0.5 ln det(F_now) (nats: the log of the factor by which the
// confidence region's volume shrinks), and for each parameter the candidate that leaves the
// smallest standard deviation sqrt([(F_now + F_c)^-1]_jj) dx/du is named. These are the
// plain, white-noise figures: a recording's correlated residuals make every one of them
// optimistic alike (identify_uncertainty.h), which does not change the ranking much.
// The file's candidates ranked at `result`'s point (its fits give the channels' noise
// floors); the trials on `threads` threads.
IdentifyPlan plan_candidates(const IdentifyDefinition& def, const IdentifyResult& result,
                             int threads);

// plan.csv: candidate,rank,information_gain,parameter,sd_now,sd_after (one row per
// candidate and parameter); plan.md: the ranking and, per parameter, the best candidate.
std::string plan_csv(const IdentifyPlan& plan);
std::string plan_markdown(const IdentifyPlan& plan);
// One console line per candidate, then one per parameter.
std::vector<std::string> plan_lines(const IdentifyPlan& plan);

}  // namespace pamsim
