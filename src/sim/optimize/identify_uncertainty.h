// identify_uncertainty.h: how sure `pamsim identify` is of its result (issue 42, items 1 and
// 2), from the residuals and their Jacobian at the identified point (residual_statistics.h):
//  - each parameter's standard error from the prewhitened HAC (sandwich) covariance, which
//    holds for residuals correlated in time as a recording's are, its interval at the file's
//    level (95 %: value(u +- 1.96 se_u)) through the parameter's scale (a log parameter's is
//    asymmetric),
//    and the plain s^2 (J^T J)^-1 error beside it; correlations above 0.9 from the same
//    covariance. A parameter whose Jacobian column vanishes is not determined by the
//    recordings and is kept out; a singular rest leaves all of them undetermined.
//  - each recording's channel judged against its own noise: the noise floor the file gives,
//    else the recorded channel's own (its second differences), the fit's RMS in multiples of
//    it, and the Ljung-Box p-value of its residuals. A channel is "explained" when the RMS is
//    at most the file's explained_noise_factor (default 3) times its floor: a model that
//    explains a recording leaves the recording's noise and its own simulated noise, sqrt(2)
//    times the floor, plus what the instruments add that is not white (creep, ringing,
//    quantisation). Where a fitted channel
//    is not explained, no standard error is to be trusted. A channel with too few samples
//    to estimate its floor, and none given, is not judged (ChannelFit::judged): unknown.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "sim/optimize/identify.h"

namespace pamsim {

// Fills std_error, std_error_plain, interval_lo, interval_hi (at `level`, in (0, 1)),
// identifiable and correlated of result->parameters (their values at `unit`) from the
// residuals `r` and their Jacobian in the unit
// box (r.size() x unit.size()) over `segments` (identify_residuals.h); the HAC bandwidth and
// the residuals' pooled lag-1 autocorrelation into `result`.
void fill_uncertainty(const Eigen::MatrixXd& jacobian, const Eigen::VectorXd& r,
                      const std::vector<std::size_t>& segments, const std::vector<double>& unit,
                      double level, IdentifyResult* result);

// A channel's noise floor (`given`, or NaN: estimated), RMS in floors, residual whiteness and
// verdict, from its recorded samples (NaN: a gap) and the fit's `after` at the same times.
// Explained: the RMS at most `explained_factor` floors.
void judge_channel(const std::vector<double>& recorded, double given, double explained_factor,
                   ChannelFit* fit);

// "the model does not explain recording <r> (<channel>): RMS <k> x the noise" for each
// fitted channel that is not explained; empty if all are.
std::vector<std::string> unexplained_channels(const IdentifyResult& result);

}  // namespace pamsim
