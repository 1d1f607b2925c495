// law_only.cc: Eq. (3) of Yoshida and Hosoda evaluated and inverted through pamsim::pam_actuator.
// Prints the force at 0.4 MPa, 10 mm and the deformation recovered from it; exit 0 when the
// inversion returns the deformation to 1e-9 mm.
#include <cmath>
#include <cstdio>

#include "pam_actuator/spring_model.h"
#include "base/units.h"

int main() {
  using namespace pamsim;
  // Table IV's agonist: m [mm/MPa], h [mm], a0..a3 (models/pams/table4_agonist.toml)
  const SpringModel law = spring_model_from_paper_units(SpringLaw::kEq3, -60.1, 170.1,
                                                        {0.911, 0.256, 7.00, -0.201, 0, 0});
  const double p_pa = units::mpa_to_pa(0.4), d_m = units::mm_to_m(10.0);
  const double f_n = spring_force(law, p_pa, d_m);
  const DeformationEstimate back = invert_spring_model(law, p_pa, f_n);
  std::printf("f(0.4 MPa, 10 mm) = %.6f N; inverted: d = %.9f mm (%s)\n", f_n,
              units::m_to_mm(back.d_m), to_string(back.status));
  return back.status == InversionStatus::kOk && std::abs(units::m_to_mm(back.d_m) - 10.0) < 1e-9
             ? 0
             : 1;
}
