// table4_springs.h: the fitted Eq. (3) springs of Table IV (Yoshida and Hosoda, "Implementing
// Stretch Reflex in Musculoskeletal Robots Driven by PAMs Using Nonlinear Spring Model"),
// paper units, which several spring-model tests start from.
#pragma once

#include "pam_actuator/spring_model.h"

namespace pamsim_test {

inline pamsim::SpringModel table4_agonist() {
  return pamsim::spring_model_from_paper_units(pamsim::SpringLaw::kEq3, -60.1, 170.1,
                                               {0.911, 0.256, 7.00, -0.201, 0.0, 0.0});
}
inline pamsim::SpringModel table4_antagonist() {
  return pamsim::spring_model_from_paper_units(pamsim::SpringLaw::kEq3, -70.3, 178.5,
                                               {22.4, -0.129, 1.24, 0.871, 0.0, 0.0});
}

}  // namespace pamsim_test
