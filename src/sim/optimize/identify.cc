// identify.cc: see identify.h.
#include "sim/optimize/identify.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <memory>

#include <ceres/ceres.h>

#include "base/input_error.h"
#include "base/no_value.h"
#include "sim/core/runner.h"
#include "sim/optimize/identify_global.h"
#include "sim/optimize/identify_outputs.h"
#include "sim/optimize/identify_residuals.h"
#include "sim/optimize/identify_uncertainty.h"

namespace pamsim {
namespace {

using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

// Ceres's view of the residuals: one parameter block of size 1 per parameter, the Jacobian by
// differences of an absolute step in the unit box, central inside it and one-sided within
// kDifferenceStep of an edge (never a point outside the box, which the parameters' ranges
// may not allow). Ceres's own numeric differences scale the step with the coordinate, which
// near 0 is far finer than the chamber ODE's tolerance.
class UnitBoxCost : public ceres::CostFunction {
 public:
  UnitBoxCost(IdentifyResiduals& residuals, std::size_t n) : residuals_(residuals) {
    for (std::size_t i = 0; i < n; ++i) mutable_parameter_block_sizes()->push_back(1);
    set_num_residuals(static_cast<int>(residuals.count()));
  }

  bool Evaluate(double const* const* params, double* out, double** jacobians) const override {
    const std::size_t n = parameter_block_sizes().size();
    std::vector<double> unit(n);
    for (std::size_t i = 0; i < n; ++i) unit[i] = params[i][0];
    const std::vector<double> r0 = residuals_.at(unit, "polish");
    if (r0.empty()) return false;
    std::copy(r0.begin(), r0.end(), out);
    if (!jacobians) return true;
    for (std::size_t j = 0; j < n; ++j) {
      if (jacobians[j] && !column(unit, j, r0, jacobians[j])) return false;
    }
    return true;
  }

 private:
  // d r / d u_j into `column` (num_residuals values)
  bool column(const std::vector<double>& unit, std::size_t j, const std::vector<double>& r0,
              double* column) const {
    const DifferenceSides s = difference_sides(unit, j, kDifferenceStep);
    const std::vector<double> rp = s.plus[j] != unit[j] ? residuals_.at(s.plus, "polish") : r0;
    const std::vector<double> rm = s.minus[j] != unit[j] ? residuals_.at(s.minus, "polish") : r0;
    if (rp.empty() || rm.empty()) return false;
    for (std::size_t i = 0; i < r0.size(); ++i) column[i] = (rp[i] - rm[i]) / s.width;
    return true;
  }

  IdentifyResiduals& residuals_;
};

// The least-squares problem over `unit` (its storage), bounded to the box.
struct PolishProblem {
  std::vector<double> unit;
  ceres::Problem problem;
  std::vector<double*> blocks;
  PolishProblem(IdentifyResiduals& residuals, const std::vector<double>& start) : unit(start) {
    for (double& u : unit) blocks.push_back(&u);
    problem.AddResidualBlock(new UnitBoxCost(residuals, unit.size()), nullptr, blocks);
    for (double* b : blocks) {
      problem.SetParameterLowerBound(b, 0, 0.0);
      problem.SetParameterUpperBound(b, 0, 1.0);
    }
  }
};

// Aborts the solve once options.stop is set.
struct StopCallback : ceres::IterationCallback {
  const std::atomic<bool>* stop;
  explicit StopCallback(const std::atomic<bool>* s) : stop(s) {}
  ceres::CallbackReturnType operator()(const ceres::IterationSummary&) override {
    return stop && stop->load() ? ceres::SOLVER_ABORT : ceres::SOLVER_CONTINUE;
  }
};

// Levenberg-Marquardt from p.unit; its brief report, interruption and failure into `result`.
void polish(const IdentifyDefinition& def, PolishProblem& p, const IdentifyRunOptions& options,
            IdentifyResult* result) {
  if (def.polish_iterations == 0) {
    result->polish_summary = "no polish (polish_iterations = 0)";
    return;
  }
  ceres::Solver::Options o;
  o.minimizer_type = ceres::TRUST_REGION;
  o.trust_region_strategy_type = ceres::LEVENBERG_MARQUARDT;
  o.linear_solver_type = ceres::DENSE_QR;
  o.max_num_iterations = def.polish_iterations;
  o.num_threads = 1;  // the recordings of each point run in parallel instead
  // With bounds, Ceres searches along each step before it tries it (a projected Armijo line
  // search, trust_region_minimizer.cc). With its default cubic interpolation the search asks
  // for the gradient at each trial step, here a whole Jacobian of differences (two trials per
  // parameter), wasted whenever the step is then rejected; quadratic interpolation fits
  // through the cost and slope at the start and needs only the cost at a trial step.
  o.line_search_interpolation_type = ceres::QUADRATIC;
  StopCallback stop(options.stop);
  o.callbacks.push_back(&stop);
  ceres::Solver::Summary summary;
  ceres::Solve(o, &p.problem, &summary);
  result->interrupted = result->interrupted || summary.termination_type == ceres::USER_FAILURE;
  result->polish_failed = summary.termination_type == ceres::FAILURE;
  result->polish_converged = summary.termination_type == ceres::CONVERGENCE;
  // Ceres lists the starting point as iteration 0
  result->polish_iterations = std::max(0, static_cast<int>(summary.iterations.size()) - 1);
  result->polish_summary = summary.BriefReport();
}

// The polish from every start in turn: every end in result->starts; the problem whose end is
// lowest (the earlier start of equals; a start whose trials failed, never) returned, its
// polish's report in *result.
std::unique_ptr<PolishProblem> polish_from_starts(const IdentifyDefinition& def,
                                                  IdentifyResiduals& residuals,
                                                  const std::vector<GlobalStart>& starts,
                                                  const IdentifyRunOptions& options,
                                                  IdentifyResult* result) {
  std::unique_ptr<PolishProblem> best;
  for (std::size_t k = 0; k < starts.size(); ++k) {
    auto problem = std::make_unique<PolishProblem>(residuals, starts[k].unit);
    IdentifyResult report;
    if (!result->interrupted) polish(def, *problem, options, &report);
    result->interrupted = result->interrupted || report.interrupted;
    PolishEnd end{starts[k].unit, problem->unit, 0.0, report.polish_converged, starts[k].run};
    for (double& u : end.end) u = std::clamp(u, 0.0, 1.0);
    end.cost = sum_of_squares(residuals.at(end.end, "polish"));
    // lower, or the first end whose trials ran (a failed start's cost is NaN)
    const double lowest = best ? result->starts[result->best_start].cost : kNaN;
    if (!best || end.cost < lowest || (std::isnan(lowest) && !std::isnan(end.cost))) {
      best = std::move(problem);
      result->best_start = k;
      result->polish_summary = report.polish_summary;
      result->polish_failed = report.polish_failed;
      result->polish_converged = report.polish_converged;
      result->polish_iterations = report.polish_iterations;
    }
    result->starts.push_back(std::move(end));
    if (result->interrupted) break;
  }
  return best;
}

// The residuals and their Jacobian at p.unit, dense (residuals x parameters); an empty
// Jacobian if they cannot be evaluated.
void evaluate_dense(PolishProblem& p, Eigen::MatrixXd* jacobian, Eigen::VectorXd* residuals) {
  ceres::CRSMatrix crs;
  std::vector<double> r;
  double cost = 0.0;
  if (!p.problem.Evaluate(ceres::Problem::EvaluateOptions(), &cost, &r, nullptr, &crs)) return;
  *jacobian = Eigen::MatrixXd::Zero(crs.num_rows, crs.num_cols);
  for (std::size_t row = 0; row + 1 < crs.rows.size(); ++row) {
    for (auto k = static_cast<std::size_t>(crs.rows[row]);
         k < static_cast<std::size_t>(crs.rows[row + 1]); ++k) {
      (*jacobian)(static_cast<Eigen::Index>(row), crs.cols[k]) = crs.values[k];
    }
  }
  *residuals = Eigen::Map<const Eigen::VectorXd>(r.data(), static_cast<Eigen::Index>(r.size()));
}

// RMS of a - b, NaN if a is empty (its trial or plant failed)
double rms_difference(const std::vector<double>& a, const std::vector<double>& b) {
  if (a.empty()) return kNaN;
  double sum = 0;
  for (std::size_t i = 0; i < a.size(); ++i) sum += (a[i] - b[i]) * (a[i] - b[i]);
  return std::sqrt(sum / static_cast<double>(a.size()));
}

// Every tensile test's forces before (the base scenario) and after: "tensile_<muscle>", force_N.
void add_tensile_fits(const IdentifyDefinition& def, const std::vector<double>& values,
                      std::vector<ChannelFit>* fits) {
  for (const IdentifyTensile& t : def.tensile) {
    std::vector<double> recorded;
    for (const TensileRow& r : t.rows) recorded.push_back(r.force_n);
    std::string failure;
    const std::vector<double> before = tensile_forces(def, t, def.overrides, &failure);
    const std::vector<double> after = tensile_forces(def, t, def.overrides_at(values), &failure);
    fits->push_back({"tensile_" + t.muscle,
                     "force_N",
                     false,
                     t.rows.size(),
                     rms_difference(before, recorded),
                     rms_difference(after, recorded),
                     {},
                     {}});
  }
}

// Every recording's channels before (the base scenario) and after (the identified values).
// With no parameter, before and after are one trial.
std::vector<ChannelFit> channel_fits(const IdentifyDefinition& def,
                                     const std::vector<double>& values, int threads) {
  const std::size_t n = def.recordings.size();
  const std::size_t after = def.parameters.empty() ? 0 : n;
  std::vector<SimulatedRecording> sims(n + after);
  parallel_for(static_cast<int>(n + after), threads, [&](int k) {
    const IdentifyRecording& r = def.recordings[static_cast<std::size_t>(k) % n];
    std::vector<std::string> before = def.overrides;
    const std::vector<std::string> conditions = r.conditions();
    before.insert(before.end(), conditions.begin(), conditions.end());
    sims[static_cast<std::size_t>(k)] =
        simulate_recording(def, r, k < static_cast<int>(n) ? before : def.overrides_at(r, values));
  });
  // before: the sensors as ideal (gain 1, no offset, no delay)
  std::vector<double> ideal = values;
  for (std::size_t k = 0; k < ideal.size(); ++k) {
    const ChannelParameter::Kind kind = def.channel_parameters[k].kind;
    if (kind != ChannelParameter::Kind::kNone)
      ideal[k] = kind == ChannelParameter::Kind::kGain ? 1.0 : 0.0;
  }
  std::vector<ChannelFit> fits;
  for (std::size_t i = 0; i < n; ++i) {
    const IdentifyRecording& r = def.recordings[i];
    const auto sampled_before = sample_channels(def, r, sims[i], ideal);
    const auto sampled_after = sample_channels(def, r, sims[after + i], values);
    const std::vector<double> before = channel_rmse(r, sampled_before);
    const std::vector<double> after = channel_rmse(r, sampled_after);
    for (std::size_t c = 0; c < r.channels.size(); ++c) {
      ChannelFit f{r.name,     r.data.channels[r.channels[c]],
                   r.held_out, r.data.sample_count(r.channels[c]),
                   before[c],  after[c],
                   {},         {}};
      if (!sampled_before.empty()) f.before = sampled_before[c];
      if (!sampled_after.empty()) f.after = sampled_after[c];
      judge_channel(r.data.samples[r.channels[c]], r.noise[c], def.explained_noise_factor, &f);
      fits.push_back(std::move(f));
    }
  }
  add_tensile_fits(def, values, &fits);
  return fits;
}

// No parameter: the model as the file gives it, its cost and its channels' verdicts.
IdentifyResult hold_against_recordings(const IdentifyDefinition& def, IdentifyResiduals& residuals,
                                       int threads) {
  IdentifyResult result;
  result.residuals = residuals.count();
  const auto t0 = Clock::now();
  result.cost_global = result.cost_final = sum_of_squares(residuals.at({}, "check"));
  if (!std::isfinite(result.cost_final)) {
    throw InputError(def.file + ": the model's trials did not run to the end (" +
                     residuals.first_failure() + ")");
  }
  result.polish_summary = "no parameter to fit";
  result.fits = channel_fits(def, {}, threads);
  result.check_s = seconds_since(t0);
  result.simulated = residuals.simulated;
  result.cached = residuals.cached;
  return result;
}

}  // namespace

IdentifyResult run_identify(const IdentifyDefinition& def, IdentifyDb& db,
                            const IdentifyRunOptions& options) {
  IdentifyResiduals residuals(def, db, options.threads);
  if (def.parameters.empty()) return hold_against_recordings(def, residuals, options.threads);
  IdentifyResult result;
  result.residuals = residuals.count();
  auto t0 = Clock::now();
  const std::vector<GlobalStart> polish_starts =
      global_search(def, residuals, options, &result.interrupted, &result.run_generations);
  result.cost_global = sum_of_squares(residuals.at(polish_starts.front().unit, "global"));
  result.global_s = seconds_since(t0);
  t0 = Clock::now();
  const std::unique_ptr<PolishProblem> problem =
      polish_from_starts(def, residuals, polish_starts, options, &result);
  result.unit = result.starts[result.best_start].end;
  result.cost_final = result.starts[result.best_start].cost;
  if (!std::isfinite(result.cost_final) && !result.interrupted) {
    throw InputError(def.file +
                     ": no point of the search ran its recordings' trials to the end "
                     "(the first failure: " +
                     residuals.first_failure() + ")");
  }
  result.polish_s = seconds_since(t0);
  result.simulated = residuals.simulated;
  result.cached = residuals.cached;
  if (result.interrupted) return result;
  t0 = Clock::now();
  const std::vector<double> values = residuals.values_at(result.unit);
  const std::vector<double> starts = start_values(def);
  for (std::size_t i = 0; i < values.size(); ++i) {
    IdentifiedParameter p;
    p.parameter = def.parameters[i];
    p.start = starts[i];
    p.value = values[i];
    p.at_bound = result.unit[i] < 1e-3 || result.unit[i] > 1.0 - 1e-3;
    result.parameters.push_back(p);
  }
  Eigen::MatrixXd jacobian;
  Eigen::VectorXd at_result;
  evaluate_dense(*problem, &jacobian, &at_result);
  fill_uncertainty(jacobian, at_result, residuals.segments(), result.unit, def.interval, &result);
  const ResidualsAt residuals_at = [&](const std::vector<double>& unit) {
    return residuals.at(unit, "interval");
  };
  fill_roughness(residuals_at, result.unit, &result);
  fill_interval_uncertainty(residuals_at, jacobian, at_result, residuals.segments(), result.unit,
                            def.interval, &result);
  result.settled = judge_settled(def, result);
  result.fits = channel_fits(def, values, options.threads);
  result.check_s = seconds_since(t0);
  result.simulated = residuals.simulated;
  result.cached = residuals.cached;  // (the checks' simulations are not stored)
  return result;
}

}  // namespace pamsim
