// residual_statistics.h: what a least-squares fit's residuals say about the fit and about
// how far to trust its covariance, for residuals that are series in time (a recording's
// channel sampled at 50-100 Hz), not independent draws: its noise floor, Ljung & Box's
// (1978) whiteness test and the HAC covariance of Newey & West (1987), Andrews (1991) and
// Andrews & Monahan (1992).
#pragma once

#include <cstddef>
#include <vector>

#include <Eigen/Dense>

namespace pamsim {

// sigma of the white noise on a smooth series (NaN: a gap, skipped with its neighbours);
// NaN with fewer than 8 usable second differences. A channel's white-noise level estimated
// from the recording itself, the robust spread of its second differences (a smooth signal's
// second difference is ~0, white noise's has variance 6 sigma^2):
// sigma = 1.4826 MAD(d2 x) / sqrt(6).
double noise_floor(const std::vector<double>& series);

// The autocorrelation of `r` at lags 0..max_lag (rho_0 = 1), about its mean.
std::vector<double> autocorrelation(const std::vector<double>& r, int max_lag);

struct WhitenessTest {
  int lags = 0;
  double q = 0.0;        // the Ljung-Box statistic
  double p_value = 1.0;  // P(chi^2_lags >= q): small means not white; NaN: too few samples
};

// Ljung-Box over lags 1..`lags` (default: min(20, n / 5), at least 1); p_value NaN unless
// n > lags + 1. The portmanteau whiteness test of Ljung & Box (1978), Q = n (n + 2)
// sum_k rho_k^2 / (n - k) over lags 1..m, chi-square with m degrees of freedom under white
// residuals (MATLAB's `resid` shows the same autocorrelations).
WhitenessTest ljung_box(const std::vector<double>& r, int lags = 0);

// The residuals' lag-1 autocorrelation pooled over consecutive segments of `r` (their
// lengths, summing to r.size()).
double pooled_lag1_autocorrelation(const std::vector<double>& r,
                                   const std::vector<std::size_t>& segments);

// Andrews' Bartlett bandwidth for n residuals of lag-1 autocorrelation rho (0 for rho <= 0),
// at most n / 4.
int bartlett_bandwidth(double rho, std::size_t n);

// Each segment's own bandwidth: bartlett_bandwidth of its residuals' lag-1 autocorrelation
// and length. Pooled over segments, a recording's few strongly correlated channels (an angle
// whose residual is its logger's rounding, constant while the arm rests) vanish among white
// ones of larger residuals, and their parameters' variance with them.
std::vector<int> segment_bandwidths(const std::vector<double>& r,
                                    const std::vector<std::size_t>& segments);

// The heteroskedasticity- and autocorrelation-consistent (sandwich) covariance of the
// estimate, Newey & West (1987) with the Bartlett kernel,
//   cov = (J^T J)^-1 [sum_{|l| <= L} (1 - |l| / (L + 1)) sum_t g_t g_{t-l}^T] (J^T J)^-1,
// g_t = J_t^T r_t, lags taken within a segment (one recording's channel) only, the
// scores prewhitened by a VAR(1) first and recoloured after (Andrews & Monahan 1992: the
// plain Bartlett sum falls 20-30 % short of an AR(1)'s long-run variance at rho = 0.8
// and n = 400, and its intervals cover 87 %, not 95 %); the
// bandwidth L by Andrews' (1991) AR(1) plug-in rule for the Bartlett kernel,
//   L = 1.1447 (a n)^(1/3), a = 4 rho^2 / ((1 - rho)^2 (1 + rho)^2),
// rho the residuals' lag-1 autocorrelation pooled over the segments. For independent
// residuals it tends to the plain s^2 (J^T J)^-1; for correlated ones that one is too
// small by about (1 + rho) / (1 - rho) (an AR(1) of rho = 0.8: 9 times in variance).
// The sandwich covariance for residuals r (n) and their Jacobian J (n x p) over
// `segments`, with bandwidth `lags` (L) in every segment, or each segment's own
// (`bandwidths`, prewhitened when any is above 0). Returns an empty matrix if J^T J is
// singular, or there are no segments or not one bandwidth for each.
Eigen::MatrixXd hac_covariance(const Eigen::MatrixXd& jacobian, const Eigen::VectorXd& r,
                               const std::vector<std::size_t>& segments, int lags);
Eigen::MatrixXd hac_covariance(const Eigen::MatrixXd& jacobian, const Eigen::VectorXd& r,
                               const std::vector<std::size_t>& segments,
                               const std::vector<int>& bandwidths);

// The plain covariance s^2 (J^T J)^-1, s^2 = r^T r / (n - p); empty if singular or n <= p.
Eigen::MatrixXd plain_covariance(const Eigen::MatrixXd& jacobian, const Eigen::VectorXd& r);

}  // namespace pamsim
