// identify_uncertainty.h: how sure `pamsim identify` is of its result, from the residuals
// and their Jacobian at the identified point (residual_statistics.h): each parameter's
// standard error and interval (fill_uncertainty), each channel judged against its own noise
// (judge_channel), each Jacobian column checked for numerical noise (kRoughnessLimit).
#pragma once

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "sim/optimize/identify.h"

namespace pamsim {

// Each parameter's standard error from the prewhitened HAC (sandwich) covariance, which
// holds for residuals correlated in time as a recording's are, its interval at the file's
// level (95 %: value(u +- 1.96 se_u)) through the parameter's scale (a log parameter's is
// asymmetric), and the plain s^2 (J^T J)^-1 error beside it; correlations above 0.9 from the
// same covariance. A parameter whose Jacobian column vanishes is not determined by the
// recordings and is kept out; a singular rest leaves all of them undetermined.
// Fills std_error, std_error_plain, interval_lo, interval_hi (at `level`, in (0, 1)),
// identifiable and correlated of result->parameters (their values at `unit`) from the
// residuals `r` and their Jacobian in the unit
// box (r.size() x unit.size()) over `segments` (identify_residuals.h); the HAC bandwidth and
// the residuals' pooled lag-1 autocorrelation into `result`.
void fill_uncertainty(const Eigen::MatrixXd& jacobian, const Eigen::VectorXd& r,
                      const std::vector<std::size_t>& segments, const std::vector<double>& unit,
                      double level, IdentifyResult* result);

// Each parameter's Jacobian column is checked for numerical noise (Moré and Wild's test of a
// simulation's computational noise, SIAM J. Sci. Comput. 33(3), 2011): a chamber solver's
// error control or an instrument's quantiser makes the model's prediction a rough function
// of its parameters at the difference step's scale. Such a column measures the roughness as
// much as the parameter's effect, overstates the information and so understates the
// standard error (the worked example's dead time at the shipped solver tolerance: 2.4
// standard errors off the truth's 6 ms). So the errors are then taken again from each
// parameter's secant over its own interval (fill_interval_uncertainty), the roughness
// reported beside them.
//
// Above this roughness (the RMS of r(u + h) - 2 r(u) + r(u - h) over that of
// r(u + h) - r(u - h)) a parameter's standard error is not to be trusted. Independent
// numerical noise of SD e on each trial, over a column h |J| long, gives
// sqrt(6 e^2 / (4 h^2 |J|^2 + 2 e^2)): 1 where the noise makes a third of the column's squared
// length (the standard error about a fifth too small), sqrt(3) where it makes all of it; a
// model smooth at the step's scale gives h |r''| / (2 |r'|), near 0.
inline constexpr double kRoughnessLimit = 1.0;

// The roughness of a model's residuals along one parameter from its central difference:
// RMS(plus - 2 at + minus) / RMS(plus - minus); NaN if the first difference vanishes.
double difference_roughness(const std::vector<double>& minus, const std::vector<double>& at,
                            const std::vector<double>& plus);

// The residuals at a point of the unit box (empty: its trial failed).
using ResidualsAt = std::function<std::vector<double>(const std::vector<double>& unit)>;

// Each parameter's roughness at `unit` (IdentifiedParameter::roughness) from its central
// difference of kDifferenceStep (the polish's Jacobian asked for the same points); parameters
// with a one-sided difference are left NaN.
void fill_roughness(const ResidualsAt& residuals_at, const std::vector<double>& unit,
                    IdentifyResult* result);

// The standard errors and intervals again (fill_uncertainty), each determined parameter's
// column of `jacobian` (the derivative's) replaced in turn by its secant over its own interval,
// r(u + s) - r(u - s) over 2 s in the unit box: s starts at z standard errors (at least
// kDifferenceStep) and doubles (at most to kLargestSecant) while the interval it gives is
// wider than s by more than kIntervalSettled. An interval from a derivative assumes the model
// linear over the interval; the secant holds it to that: for a model that is, it is the
// derivative; for one whose prediction is rough at the difference step's scale (a solver's
// error control, a sampled-data loop's kinks, above), it measures the parameter's effect
// where the derivative also measured the roughness, information the recordings do not hold.
// std_error_plain stays the derivative's, the plain s^2 (J^T J)^-1 it is compared with. A
// failed trial leaves the errors of the last secants that ran.
inline constexpr double kIntervalSettled = 0.05;
inline constexpr double kLargestSecant = 0.25;
void fill_interval_uncertainty(const ResidualsAt& residuals_at, Eigen::MatrixXd jacobian,
                               const Eigen::VectorXd& r, const std::vector<std::size_t>& segments,
                               const std::vector<double>& unit, double level,
                               IdentifyResult* result);

// Each recording's channel is judged against its own noise: the noise floor the file gives,
// else the recorded channel's own (its second differences), the fit's RMS in multiples of
// it, and the Ljung-Box p-value of its residuals. A channel is "explained" when the RMS is
// at most the file's explained_noise_factor (default 3) times its floor: a model that
// explains a recording leaves the recording's noise and its own simulated noise, sqrt(2)
// times the floor, plus what the instruments add that is not white (creep, ringing,
// quantisation). Where a fitted channel is not explained, no standard error is to be
// trusted. A channel with too few samples to estimate its floor, and none given, is not
// judged (ChannelFit::judged): unknown.
// A channel's noise floor (`given`, or NaN: estimated), RMS in floors, residual whiteness and
// verdict, from its recorded samples (NaN: a gap) and the fit's `after` at the same times.
// Explained: the RMS at most `explained_factor` floors.
void judge_channel(const std::vector<double>& recorded, double given, double explained_factor,
                   ChannelFit* fit);

// "the model does not explain recording <r> (<channel>): RMS <k> x the noise" for each
// fitted channel that is not explained; empty if all are. When the runs ended apart
// (SearchSettled::kNotSettled) one line instead: "the search did not settle: runs ended at
// costs ...; run with more runs (runs = ...) or generations".
std::vector<std::string> unexplained_channels(const IdentifyResult& result);

// Why the result as a whole is not to be trusted: "" when every fitted channel is explained;
// "the search did not settle" when the runs ended apart; else "the model does not explain the
// recordings".
std::string distrust_reason(const IdentifyResult& result);

}  // namespace pamsim
