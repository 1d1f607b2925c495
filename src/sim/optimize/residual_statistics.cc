// residual_statistics.cc: see residual_statistics.h.
#include "sim/optimize/residual_statistics.h"

#include <algorithm>
#include <cmath>

#include <boost/math/distributions/chi_squared.hpp>

#include "base/no_value.h"

namespace pamsim {
namespace {

double median(std::vector<double> v) {
  const std::size_t mid = v.size() / 2;
  std::nth_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(mid), v.end());
  const double upper = v[mid];
  if (v.size() % 2 == 1) return upper;
  return 0.5 * (upper + *std::max_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(mid)));
}

}  // namespace

double noise_floor(const std::vector<double>& series) {
  std::vector<double> d2;
  for (std::size_t i = 2; i < series.size(); ++i) {
    const double a = series[i - 2], b = series[i - 1], c = series[i];
    if (!std::isnan(a) && !std::isnan(b) && !std::isnan(c)) d2.push_back(c - 2.0 * b + a);
  }
  if (d2.size() < 8) return kNaN;
  const double m = median(d2);
  std::vector<double> deviation;
  for (double d : d2) deviation.push_back(std::fabs(d - m));
  // 1.4826 MAD is the standard deviation of a normal sample; Var(d2) = 6 sigma^2
  return 1.4826 * median(deviation) / std::sqrt(6.0);
}

std::vector<double> autocorrelation(const std::vector<double>& r, int max_lag) {
  const std::size_t n = r.size();
  double mean = 0.0;
  for (double v : r) mean += v;
  mean /= static_cast<double>(n);
  double c0 = 0.0;
  for (double v : r) c0 += (v - mean) * (v - mean);
  std::vector<double> rho(static_cast<std::size_t>(max_lag) + 1, 0.0);
  rho[0] = 1.0;
  for (std::size_t k = 1; k < rho.size() && k < n; ++k) {
    double ck = 0.0;
    for (std::size_t t = k; t < n; ++t) ck += (r[t] - mean) * (r[t - k] - mean);
    rho[k] = c0 > 0.0 ? ck / c0 : 0.0;
  }
  return rho;
}

WhitenessTest ljung_box(const std::vector<double>& r, int lags) {
  const double n = static_cast<double>(r.size());
  WhitenessTest test;
  test.lags = lags > 0 ? lags : std::max(1, std::min(20, static_cast<int>(r.size() / 5)));
  if (r.size() < static_cast<std::size_t>(test.lags) + 2) {
    test.p_value = kNaN;
    return test;
  }
  const std::vector<double> rho = autocorrelation(r, test.lags);
  for (int k = 1; k <= test.lags; ++k) test.q += rho[k] * rho[k] / (n - k);
  test.q *= n * (n + 2.0);
  const boost::math::chi_squared chi2(test.lags);
  test.p_value = boost::math::cdf(boost::math::complement(chi2, test.q));
  return test;
}

double pooled_lag1_autocorrelation(const std::vector<double>& r,
                                   const std::vector<std::size_t>& segments) {
  double num = 0.0, den = 0.0;
  std::size_t start = 0;
  for (std::size_t length : segments) {
    double mean = 0.0;
    for (std::size_t t = start; t < start + length; ++t) mean += r[t];
    mean /= std::max<double>(1.0, static_cast<double>(length));
    for (std::size_t t = start; t < start + length; ++t) {
      den += (r[t] - mean) * (r[t] - mean);
      if (t > start) num += (r[t] - mean) * (r[t - 1] - mean);
    }
    start += length;
  }
  return den > 0.0 ? num / den : 0.0;
}

std::vector<int> segment_bandwidths(const std::vector<double>& r,
                                    const std::vector<std::size_t>& segments) {
  std::vector<int> lags;
  std::size_t start = 0;
  for (std::size_t length : segments) {
    const std::vector<double> one(r.begin() + static_cast<std::ptrdiff_t>(start),
                                  r.begin() + static_cast<std::ptrdiff_t>(start + length));
    lags.push_back(bartlett_bandwidth(pooled_lag1_autocorrelation(one, {length}), length));
    start += length;
  }
  return lags;
}

int bartlett_bandwidth(double rho, std::size_t n) {
  if (!(rho > 0.0)) return 0;
  rho = std::min(rho, 0.97);  // a random walk has no finite long-run variance
  const double a = 4.0 * rho * rho / ((1.0 - rho) * (1.0 - rho) * (1.0 + rho) * (1.0 + rho));
  const double lags = 1.1447 * std::cbrt(a * static_cast<double>(n));
  return static_cast<int>(std::min(std::floor(lags), static_cast<double>(n / 4)));
}

namespace {

// The scores' VAR(1) matrix A (g_t = A g_{t-1} + v_t, lags within segments), its spectral
// radius held at most 0.97 (Andrews & Monahan's guard: (I - A)^-1 stays finite).
Eigen::MatrixXd score_ar1(const Eigen::MatrixXd& g, const std::vector<std::size_t>& segments) {
  const Eigen::Index p = g.cols();
  Eigen::MatrixXd lagged = Eigen::MatrixXd::Zero(p, p), cross = Eigen::MatrixXd::Zero(p, p);
  Eigen::Index start = 0;
  for (std::size_t length : segments) {
    const auto len = static_cast<Eigen::Index>(length);
    if (len > 1) {
      const auto seg = g.middleRows(start, len);
      cross += seg.bottomRows(len - 1).transpose() * seg.topRows(len - 1);
      lagged += seg.topRows(len - 1).transpose() * seg.topRows(len - 1);
    }
    start += len;
  }
  const Eigen::FullPivLU<Eigen::MatrixXd> lu(lagged);
  if (!lu.isInvertible()) return Eigen::MatrixXd::Zero(p, p);
  Eigen::MatrixXd a = cross * lu.inverse();
  const double radius = a.eigenvalues().cwiseAbs().maxCoeff();
  if (radius > 0.97) a *= 0.97 / radius;
  return a;
}

// Bartlett-weighted sum of the autocovariances of `v`'s rows in each segment over lags
// 0..its own bandwidth
Eigen::MatrixXd long_run(const Eigen::MatrixXd& v, const std::vector<std::size_t>& segments,
                         const std::vector<int>& bandwidths) {
  Eigen::MatrixXd sum = Eigen::MatrixXd::Zero(v.cols(), v.cols());
  Eigen::Index start = 0;
  for (std::size_t k = 0; k < segments.size(); ++k) {
    const auto len = static_cast<Eigen::Index>(segments[k]);
    const int lags = bandwidths[k];
    const auto seg = v.middleRows(start, len);
    sum += seg.transpose() * seg;
    for (Eigen::Index l = 1; l <= lags && l < len; ++l) {
      const double w = 1.0 - static_cast<double>(l) / (lags + 1.0);
      const Eigen::MatrixXd gamma = seg.bottomRows(len - l).transpose() * seg.topRows(len - l);
      sum += w * (gamma + gamma.transpose());
    }
    start += len;
  }
  return sum;
}

}  // namespace

Eigen::MatrixXd hac_covariance(const Eigen::MatrixXd& jacobian, const Eigen::VectorXd& r,
                               const std::vector<std::size_t>& segments, int lags) {
  return hac_covariance(jacobian, r, segments, std::vector<int>(segments.size(), lags));
}

Eigen::MatrixXd hac_covariance(const Eigen::MatrixXd& jacobian, const Eigen::VectorXd& r,
                               const std::vector<std::size_t>& segments,
                               const std::vector<int>& bandwidths) {
  if (bandwidths.size() != segments.size() || segments.empty()) return {};
  const int lags = *std::max_element(bandwidths.begin(), bandwidths.end());
  const Eigen::Index n = jacobian.rows(), p = jacobian.cols();
  const Eigen::FullPivLU<Eigen::MatrixXd> lu(jacobian.transpose() * jacobian);
  if (n <= p || !lu.isInvertible()) return {};
  const Eigen::MatrixXd bread = lu.inverse();
  const Eigen::MatrixXd g = r.asDiagonal() * jacobian;  // row t: g_t^T = r_t J_t
  // prewhitened (Andrews & Monahan 1992): v_t = g_t - A g_{t-1} within each segment, the
  // Bartlett sum over v, recoloured by (I - A)^-1
  const Eigen::MatrixXd a = lags > 0 ? score_ar1(g, segments) : Eigen::MatrixXd::Zero(p, p);
  Eigen::MatrixXd v = g;
  Eigen::Index start = 0;
  for (std::size_t length : segments) {
    const auto len = static_cast<Eigen::Index>(length);
    for (Eigen::Index t = start + 1; t < start + len; ++t) {
      v.row(t) = g.row(t) - g.row(t - 1) * a.transpose();
    }
    start += len;
  }
  const Eigen::MatrixXd recolour = (Eigen::MatrixXd::Identity(p, p) - a).inverse();
  const Eigen::MatrixXd meat = recolour * long_run(v, segments, bandwidths) * recolour.transpose();
  // the small-sample factor n / (n - p), as the plain estimate's s^2 has
  return bread * meat * bread * (static_cast<double>(n) / static_cast<double>(n - p));
}

Eigen::MatrixXd plain_covariance(const Eigen::MatrixXd& jacobian, const Eigen::VectorXd& r) {
  const Eigen::Index n = jacobian.rows(), p = jacobian.cols();
  const Eigen::FullPivLU<Eigen::MatrixXd> lu(jacobian.transpose() * jacobian);
  if (n <= p || !lu.isInvertible()) return {};
  return lu.inverse() * (r.squaredNorm() / static_cast<double>(n - p));
}

}  // namespace pamsim
