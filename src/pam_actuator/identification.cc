// identification.cc: least-squares fits of Eq. (2)-(5), see identification.h.
#include "pam_actuator/identification.h"

#include <algorithm>
#include <cmath>

#include <Eigen/Dense>

#include "base/input_error.h"

namespace pamsim {
namespace {

constexpr double kPressureLevelGapMpa = 0.01;

int count_pressure_levels(const std::vector<TensileRow>& rows) {
  std::vector<double> p;
  for (const TensileRow& r : rows) p.push_back(r.pressure_mpa);
  std::sort(p.begin(), p.end());
  int levels = p.empty() ? 0 : 1;
  for (size_t k = 1; k < p.size(); ++k) {
    if (p[k] - p[k - 1] > kPressureLevelGapMpa) ++levels;
  }
  return levels;
}

// least squares with unit-norm columns; rank checked before solving
Eigen::VectorXd solve_least_squares(const Eigen::MatrixXd& a, const Eigen::VectorXd& b,
                                    const std::string& context, const std::string& what) {
  const Eigen::VectorXd scale = a.colwise().norm().transpose();
  for (int c = 0; c < a.cols(); ++c) {
    if (!(scale[c] > 0.0)) {
      throw InputError(context + ": rank-deficient design for " + what + ": basis term " +
                       std::to_string(c) + " is zero on every row");
    }
  }
  const Eigen::MatrixXd scaled = a * scale.cwiseInverse().asDiagonal();
  Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(scaled);
  qr.setThreshold(1e-10);
  if (qr.rank() < a.cols()) {
    throw InputError(context + ": rank-deficient design for " + what + " (rank " +
                     std::to_string(qr.rank()) + " of " + std::to_string(a.cols()) +
                     "): the data do not vary enough in pressure or deformation");
  }
  return qr.solve(b).cwiseQuotient(scale);
}

}  // namespace

NaturalLengthFit fit_natural_length(const std::vector<TensileRow>& rows,
                                    const std::string& context) {
  NaturalLengthFit fit;
  fit.pressure_levels = count_pressure_levels(rows);
  if (fit.pressure_levels < 2) {
    throw InputError(context +
                     ": a single pressure level: m and h of Eq. (2) need at least "
                     "two distinct pressures (levels closer than 0.01 MPa count as one)");
  }

  // Eq. (1)-(2): l - d = l_n = m p + h, one row per measured point
  Eigen::MatrixXd a(rows.size(), 2);
  Eigen::VectorXd b(rows.size());
  for (size_t r = 0; r < rows.size(); ++r) {
    a(r, 0) = rows[r].pressure_mpa;
    a(r, 1) = 1.0;
    b[r] = rows[r].length_mm - rows[r].deformation_mm;
  }
  const Eigen::VectorXd x = solve_least_squares(a, b, context, "Eq. (2)");
  fit.m_mm_per_mpa = x[0];
  fit.h_mm = x[1];
  return fit;
}

SpringFit fit_spring_model(SpringLaw law, const std::vector<TensileRow>& rows,
                           const std::string& context) {
  const int n = coefficient_count(law);
  const int points = static_cast<int>(rows.size());
  if (points < n) {
    throw InputError(context + ": too few points: " + std::to_string(points) + " rows for the " +
                     std::to_string(n) + " coefficients of " + to_string(law));
  }
  const NaturalLengthFit ln = fit_natural_length(rows, context);

  // Eq. (3)-(5): f = sum_k c_k p^i d^(j+1), in paper units (MPa, mm, N)
  Eigen::MatrixXd a(points, n);
  Eigen::VectorXd f(points);
  for (int r = 0; r < points; ++r) {
    const double p = rows[r].pressure_mpa, d = rows[r].deformation_mm;
    for (int k = 0; k < n; ++k) {
      a(r, k) =
          std::pow(p, pressure_exponent(law, k)) * std::pow(d, deformation_exponent(law, k) + 1);
    }
    f[r] = rows[r].force_n;
  }
  const Eigen::VectorXd c = solve_least_squares(a, f, context, to_string(law));

  // goodness of fit of force
  const Eigen::VectorXd residual = a * c - f;
  const double ss_res = residual.squaredNorm();
  const double ss_tot = (f.array() - f.mean()).square().sum();
  SpringFit fit;
  std::array<double, 6> coef{};
  for (int k = 0; k < n; ++k) coef[k] = c[k];
  fit.model = spring_model_from_paper_units(law, ln.m_mm_per_mpa, ln.h_mm, coef);
  fit.rmse_n = std::sqrt(ss_res / points);
  fit.r2 = ss_tot > 0.0 ? 1.0 - ss_res / ss_tot : 0.0;
  fit.points = points;
  return fit;
}

}  // namespace pamsim
