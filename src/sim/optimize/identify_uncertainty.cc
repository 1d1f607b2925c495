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
    p.correlated.clear();
  }
  if (jacobian.rows() != r.size() || jacobian.cols() != static_cast<Eigen::Index>(params.size())) {
    return;  // the Jacobian could not be evaluated
  }
  const std::vector<Eigen::Index> free = determined_columns(jacobian);
  Eigen::MatrixXd j(jacobian.rows(), static_cast<Eigen::Index>(free.size()));
  for (std::size_t k = 0; k < free.size(); ++k) {
    j.col(static_cast<Eigen::Index>(k)) = jacobian.col(free[k]);
  }
  const std::vector<double> rv(r.data(), r.data() + r.size());
  result->residual_lag1 = pooled_lag1_autocorrelation(rv, segments);
  const std::vector<int> bandwidths = segment_bandwidths(rv, segments);
  result->hac_lags =
      bandwidths.empty() ? 0 : *std::max_element(bandwidths.begin(), bandwidths.end());
  const Eigen::MatrixXd cov =
      free.empty() ? Eigen::MatrixXd() : hac_covariance(j, r, segments, bandwidths);
  const Eigen::MatrixXd plain = free.empty() ? Eigen::MatrixXd() : plain_covariance(j, r);
  if (cov.size() == 0 || plain.size() == 0) return;  // none, or jointly undetermined
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

double difference_roughness(const std::vector<double>& minus, const std::vector<double>& at,
                            const std::vector<double>& plus) {
  double first = 0.0, second = 0.0;
  for (std::size_t i = 0; i < at.size(); ++i) {
    first += (plus[i] - minus[i]) * (plus[i] - minus[i]);
    second += (plus[i] - 2.0 * at[i] + minus[i]) * (plus[i] - 2.0 * at[i] + minus[i]);
  }
  return first > 0.0 ? std::sqrt(second / first) : kNaN;
}

void fill_roughness(const ResidualsAt& residuals_at, const std::vector<double>& unit,
                    IdentifyResult* result) {
  const std::vector<double> at = residuals_at(unit);
  for (std::size_t j = 0; j < unit.size() && j < result->parameters.size(); ++j) {
    const DifferenceSides s = difference_sides(unit, j, kDifferenceStep);
    if (at.empty() || s.plus[j] == unit[j] || s.minus[j] == unit[j]) continue;
    const std::vector<double> plus = residuals_at(s.plus), minus = residuals_at(s.minus);
    if (plus.size() != at.size() || minus.size() != at.size()) continue;
    result->parameters[j].roughness = difference_roughness(minus, at, plus);
  }
}

namespace {

// parameter j's secant of `step` into column j of `jacobian`; false if a trial failed
bool set_secant(const ResidualsAt& residuals_at, const std::vector<double>& unit, std::size_t j,
                double step, Eigen::MatrixXd* jacobian) {
  const DifferenceSides s = difference_sides(unit, j, step);
  const std::vector<double> plus = residuals_at(s.plus), minus = residuals_at(s.minus);
  if (plus.size() != static_cast<std::size_t>(jacobian->rows()) || minus.size() != plus.size()) {
    return false;
  }
  for (Eigen::Index i = 0; i < jacobian->rows(); ++i) {
    (*jacobian)(i, static_cast<Eigen::Index>(j)) = (plus[i] - minus[i]) / s.width;
  }
  return true;
}

// parameter j's half interval in the unit box (z standard errors)
double half_interval(const IdentifiedParameter& p, double u, double z) {
  return z * p.std_error / std::abs(slope_at(p.parameter, u));
}

}  // namespace

void fill_interval_uncertainty(const ResidualsAt& residuals_at, Eigen::MatrixXd jacobian,
                               const Eigen::VectorXd& r, const std::vector<std::size_t>& segments,
                               const std::vector<double>& unit, double level,
                               IdentifyResult* result) {
  std::vector<double> plain;  // the derivative's, kept for comparison
  for (const IdentifiedParameter& p : result->parameters) plain.push_back(p.std_error_plain);
  const double z = boost::math::quantile(boost::math::normal(), 0.5 + 0.5 * level);
  for (std::size_t j = 0; j < unit.size() && j < result->parameters.size(); ++j) {
    if (!result->parameters[j].identifiable) continue;
    double step = std::clamp(half_interval(result->parameters[j], unit[j], z), kDifferenceStep,
                             kLargestSecant);
    for (;;) {
      if (!set_secant(residuals_at, unit, j, step, &jacobian)) break;  // the last errors stand
      fill_uncertainty(jacobian, r, segments, unit, level, result);
      const double half = half_interval(result->parameters[j], unit[j], z);
      if (!(half > step * (1.0 + kIntervalSettled)) || step >= kLargestSecant) break;
      step = std::min(kLargestSecant, std::max(2.0 * step, half));
    }
  }
  for (std::size_t j = 0; j < plain.size(); ++j) result->parameters[j].std_error_plain = plain[j];
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

namespace {

// "the search did not settle: runs ended at costs 4102, 152384 (run 1, 2); run with more
// runs (runs = 3) or generations"
std::string unsettled_line(const IdentifyResult& result) {
  std::string costs;
  int runs = 0;
  for (const PolishEnd& end : result.starts) {
    if (end.run < 0) continue;
    costs += (costs.empty() ? "" : ", ") + format_value(end.cost);
    ++runs;
  }
  return "the search did not settle: its " + std::to_string(runs) + " runs ended at costs " +
         costs + "; run with more runs (runs = " + std::to_string(runs + 1) + ") or generations";
}

}  // namespace

std::string distrust_reason(const IdentifyResult& result) {
  if (unexplained_channels(result).empty()) return "";
  return result.settled == SearchSettled::kNotSettled ? "the search did not settle"
                                                      : "the model does not explain the recordings";
}

std::vector<std::string> unexplained_channels(const IdentifyResult& result) {
  std::vector<std::string> lines;
  for (const ChannelFit& f : result.fits) {
    if (f.held_out || f.explained || !f.judged) continue;
    lines.push_back("the model does not explain recording " + f.recording + " (" + f.channel +
                    "): RMS " + format_value(std::round(f.rmse_after / f.noise_floor * 10) / 10) +
                    " x the noise");
  }
  if (!lines.empty() && result.settled == SearchSettled::kNotSettled) {
    return {unsettled_line(result)};
  }
  return lines;
}

}  // namespace pamsim
