// identification.h: the least-squares identification of Yoshida and Hosoda, Sec. II-B: fit
// m, h of Eq. (2) and the coefficients of Eq. (3), (4) or (5) to static tensile data.
#pragma once

#include <string>
#include <vector>

#include "pam_actuator/spring_model.h"
#include "pam_actuator/tensile_test.h"

namespace pamsim {

// Eq. (2) fit: l_n = m p + h, from every row's natural length l_n = l - d [mm].
struct NaturalLengthFit {
  double m_mm_per_mpa = 0.0;
  double h_mm = 0.0;
  int pressure_levels = 0;  // distinct pressures (levels closer than 0.01 MPa merge)
};

// Throws InputError (message starts with `context`, e.g. the file name) when fewer than
// two distinct pressures are present: m and h are then undetermined.
NaturalLengthFit fit_natural_length(const std::vector<TensileRow>& rows,
                                    const std::string& context);

struct SpringFit {
  SpringModel model;    // SI, Eq. (2) and the chosen law
  double rmse_n = 0.0;  // root mean square force residual [N]
  double r2 = 0.0;      // coefficient of determination of force
  int points = 0;
};

// Fits Eq. (2) and the law's coefficients by linear least squares on the basis
// p^i d^(j+1) (paper units, column-scaled, column-pivoting QR). Throws InputError naming
// `context` for fewer rows than unknowns, a single pressure, or a rank-deficient design
// (e.g. eq4 needs three distinct pressures for its p^2 term).
SpringFit fit_spring_model(SpringLaw law, const std::vector<TensileRow>& rows,
                           const std::string& context);

}  // namespace pamsim
