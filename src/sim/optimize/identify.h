// identify.h: `pamsim identify`: the parameters of an identification file fitted
// to its recordings, in two phases over the parameters' unit box: a global search by pagmo2's
// CMA-ES (optimizer.h; `generations` of `population`, in `runs` runs: identify_global.h), then a
// least-squares polish from each run's best point by Ceres Solver's Levenberg-Marquardt
// (bounds [0, 1], central-difference Jacobian), and the parameters' covariance at the result,
// one that holds for residuals correlated in time (identify_uncertainty.h: a prewhitened HAC
// sandwich, with the plain s^2 (J^T J)^-1 beside it), carried to the parameters' units by
// dx/du; each channel is judged against its own noise floor.
// Every residual vector is committed to the run's database as it is computed
// (identify_db.h); a run stopped at any point and started again with the same database
// replays both phases, deterministic, and simulates only what it had not.
#pragma once

#include <atomic>
#include <cstdint>
#include <functional>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include "sim/optimize/identify_db.h"
#include "sim/optimize/identify_file.h"

namespace pamsim {

struct IdentifyRunOptions {
  int threads = 1;
  const std::atomic<bool>* stop = nullptr;  // set: stop after the simulation in flight
  std::function<void(const std::string& phase, std::int64_t points)> on_progress;
};

struct IdentifiedParameter {
  SearchParameter parameter;
  double start = 0.0;  // the model's value before (NaN: unknown)
  double value = 0.0;
  double std_error = 0.0;        // HAC (identify_uncertainty.h); NaN when not determined
  double std_error_plain = 0.0;  // s^2 (J^T J)^-1, for comparison; NaN when not determined
  // the interval of the file's level (identify_file.h: interval, 0.95 unless it says) from
  // std_error; NaN: none
  double interval_lo = 0.0, interval_hi = 0.0;
  bool at_bound = false;     // within 0.1 % of the box's edge
  bool identifiable = true;  // false: the recordings do not determine it
  std::vector<std::pair<std::string, double>> correlated;  // |correlation| > 0.9
  // the model's numerical roughness along the parameter at the result: its residuals' second
  // difference over their first (identify_uncertainty.h); above kRoughnessLimit its standard
  // error is not to be trusted. NaN: not measured (one-sided, or the differences vanish)
  double roughness = std::numeric_limits<double>::quiet_NaN();
};

// A recording's channel before (the base scenario as it stands) and after identification.
struct ChannelFit {
  std::string recording, channel;
  bool held_out = false;
  std::size_t samples = 0;
  double rmse_before = 0.0, rmse_after = 0.0;  // in the channel's unit
  std::vector<double> before, after;           // simulated at the recording's times (NaN: gap)
  // the recorded channel's white noise in its unit, and the Ljung-Box p-value of the
  // residuals after (identify_uncertainty.h); NaN: unknown (too few samples, a tensile test)
  double noise_floor = std::numeric_limits<double>::quiet_NaN();
  double whiteness_p = std::numeric_limits<double>::quiet_NaN();
  bool explained = true;  // RMSE after within explained_noise_factor noise floors
  bool judged = true;     // false: too few samples to estimate the floor, so whether
                          // the model explains the channel is unknown (explained false)
};

// The polish's starts are CMA-ES's best points that lie at least this fraction of the box
// apart, in some parameter, from every start chosen before (IdentifyDefinition::starts).
inline constexpr double kStartSpacing = 0.1;

// Where one of the polish's starts ended (IdentifyDefinition::starts).
struct PolishEnd {
  std::vector<double> start, end;  // in the unit box
  double cost = 0.0;               // sum of squared residuals at the end
  bool converged = false;
  int run = -1;  // the global search's run whose best point it started from; -1: a further start
};

// Two polish ends are at the same point when every parameter the recordings determine is within
// kSameEndErrors of the result's standard errors, or within the polish's difference step of the
// box (without one, kSameEnd of the box); an end whose cost is more than kLocalMinimumMargin
// (chi-square of one degree of freedom at 95 %) above the result's is a local minimum.
inline constexpr double kLocalMinimumMargin = 3.84;
inline constexpr double kSameEndErrors = 2.0;
inline constexpr double kSameEnd = 0.01;

// Whether the global search's independent runs (IdentifyDefinition::runs) ended at one answer:
// a run's polished end agrees with the result when it is at the same point and costs at most
// kLocalMinimumMargin more, or kSettledCostRatio times as much, whichever is more; two that
// agree (the result among them) settle the search.
enum class SearchSettled { kNotChecked, kSettled, kNotSettled };
inline constexpr double kSettledCostRatio = 1.1;

struct IdentifyResult {
  std::vector<double> unit;  // the identified point in the unit box
  std::vector<IdentifiedParameter> parameters;
  std::vector<ChannelFit> fits;
  double cost_global = 0.0, cost_final = 0.0;  // sum of squared residuals (identify_residuals.h)
  std::size_t residuals = 0;
  std::int64_t simulated = 0, cached = 0;                // points simulated, points answered stored
  double global_s = 0.0, polish_s = 0.0, check_s = 0.0;  // wall time of each phase
  double interval_level = 0.95;                          // the parameters' intervals' level
  int hac_lags = 0;  // the HAC covariance's largest Bartlett bandwidth (each series has its own)
  double residual_lag1 = 0.0;    // the residuals' pooled lag-1 autocorrelation
  std::string polish_summary;    // Ceres's brief report
  bool polish_failed = false;    // Ceres ended in FAILURE: the global result stands
  bool polish_converged = true;  // Ceres reported CONVERGENCE (or no polish ran)
  int polish_iterations = 0;     // Levenberg-Marquardt iterations taken
  bool interrupted = false;
  // every start the polish ran, in the order they were chosen (the global search's best
  // first), and which of them the result is (the lowest end)
  std::vector<PolishEnd> starts;
  std::size_t best_start = 0;
  SearchSettled settled = SearchSettled::kNotChecked;  // kNotChecked: one run
  std::vector<unsigned> run_generations;  // the generations each run of the global search ran
};

// Throws InputError "<file>: no point of the search ran ..." when no point's trials all ran
// to the end (a range no scenario allows, a model that diverges everywhere). With no
// parameter nothing is searched: the result is the model as the file gives it held against
// the recordings (a lab's log against the model: cost, fits and their verdicts; no starts).
IdentifyResult run_identify(const IdentifyDefinition& def, IdentifyDb& db,
                            const IdentifyRunOptions& options);

}  // namespace pamsim
