// identify_uncertainty.cc: see identify_uncertainty.h.
#include "sim/optimize/identify_uncertainty.h"

#include <algorithm>
#include <cmath>

#include <boost/math/distributions/normal.hpp>

#include "base/format.h"
#include "base/no_value.h"
#include "sim/optimize/identify_residuals.h"
#include "sim/optimize/residual_statistics.h"

namespace pamsim {
namespace {

// The parameters the recordings move (a Jacobian column not vanishing against the largest).
std::vector<Eigen::Index> determined_columns(const Eigen::MatrixXd& jacobian) {
  const Eigen::VectorXd norms = jacobian.colwise().squaredNorm();
  const double largest = norms.size() > 0 ? norms.maxCoeff() : 0.0;
  std::vector<Eigen::Index> free;
  for (Eigen::Index i = 0; i < norms.size(); ++i) {
    if (largest > 0.0 && norms[i] > 1e-12 * largest) free.push_back(i);
  }
  return free;
}

}  // namespace

void fill_uncertainty(const Eigen::MatrixXd& jacobian, const Eigen::VectorXd& r,
                      const std::vector<std::size_t>& segments, const std::vector<double>& unit,
                      double level, IdentifyResult* result) {
  // the standard normal's quantile at 1/2 + level/2 (1.96 for 0.95)
  const double z = boost::math::quantile(boost::math::normal(), 0.5 + 0.5 * level);
  std::vector<IdentifiedParameter>& params = result->parameters;
  result->interval_level = level;
  for (IdentifiedParameter& p : params) {
    p.identifiable = false;
    p.std_error = p.std_error_plain = p.interval_lo = p.interval_hi = kNaN;
  }
  if (jacobian.rows() != r.size() || jacobian.cols() != static_cast<Eigen::Index>(params.size())) {
    return;   // the Jacobian could not be evaluated
  }
  const std::vector<Eigen::Index> free = determined_columns(jacobian);
  Eigen::MatrixXd j(jacobian.rows(), static_cast<Eigen::Index>(free.size()));
  for (std::size_t k = 0; k < free.size(); ++k) {
    j.col(static_cast<Eigen::Index>(k)) = jacobian.col(free[k]);
  }
  const std::vector<double> rv(r.data(), r.data() + r.size());
  result->residual_lag1 = pooled_lag1_autocorrelation(rv, segments);
  result->hac_lags = bartlett_bandwidth(result->residual_lag1, rv.size());
  const Eigen::MatrixXd cov = free.empty() ? Eigen::MatrixXd()
                                           : hac_covariance(j, r, segments, result->hac_lags);
  const Eigen::MatrixXd plain = free.empty() ? Eigen::MatrixXd() : plain_covariance(j, r);
  if (cov.size() == 0 || plain.size() == 0) return;   // none, or jointly undetermined
  for (std::size_t a = 0; a < free.size(); ++a) {
    const auto ka = static_cast<Eigen::Index>(a);
    IdentifiedParameter& p = params[static_cast<std::size_t>(free[a])];
    const double u = unit[static_cast<std::size_t>(free[a])];
    const double se_u = std::sqrt(cov(ka, ka));
    p.identifiable = true;
    p.std_error = se_u * std::abs(slope_at(p.parameter, u));
    p.std_error_plain = std::sqrt(plain(ka, ka)) * std::abs(slope_at(p.parameter, u));
    const double lo = value_at(p.parameter, u - z * se_u);
    const double hi = value_at(p.parameter, u + z * se_u);
    p.interval_lo = std::min(lo, hi);
    p.interval_hi = std::max(lo, hi);
    for (std::size_t b = 0; b < free.size(); ++b) {
      const auto kb = static_cast<Eigen::Index>(b);
      if (a == b) continue;
      const double rho = cov(ka, kb) / std::sqrt(cov(ka, ka) * cov(kb, kb));
      if (std::abs(rho) > 0.9) {
        p.correlated.emplace_back(params[static_cast<std::size_t>(free[b])].parameter.key, rho);
      }
    }
  }
}

void judge_channel(const std::vector<double>& recorded, double given, double explained_factor,
                   ChannelFit* fit) {
  if (std::isfinite(given)) {
    fit->noise_floor = given;
  } else {
    fit->noise_floor = judged_floor(recorded);
  }
  std::vector<double> residuals;
  for (std::size_t i = 0; i < recorded.size() && i < fit->after.size(); ++i) {
    const double d = fit->after[i] - recorded[i];
    if (!std::isnan(d)) residuals.push_back(d);
  }
  fit->whiteness_p = ljung_box(residuals).p_value;
  fit->judged = std::isfinite(fit->noise_floor);
  fit->explained = fit->judged && !(fit->rmse_after > explained_factor * fit->noise_floor);
}

std::vector<std::string> unexplained_channels(const IdentifyResult& result) {
  std::vector<std::string> lines;
  for (const ChannelFit& f : result.fits) {
    if (f.held_out || f.explained || !f.judged) continue;
    lines.push_back("the model does not explain recording " + f.recording + " (" + f.channel +
                    "): RMS " + format_value(std::round(f.rmse_after / f.noise_floor * 10) / 10) +
                    " x the noise");
  }
  return lines;
}

}  // namespace pamsim
