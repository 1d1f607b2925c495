// muscle_law.cc: see muscle_law.h.
#include "sim/core/muscle_law.h"

#include <algorithm>

namespace pamsim {

double plant_free_length(const MuscleSpec& muscle, double p_pa) {
  if (!muscle.plant_file.empty()) return avbdl_free_length(muscle.plant, p_pa);
  return natural_length(muscle.pam.spring, p_pa);
}

double plant_static_force(const MuscleSpec& muscle, double p_pa, double length_m) {
  if (!muscle.plant_file.empty()) {
    return std::max(avbdl_static_force(muscle.plant, p_pa, length_m), 0.0);
  }
  return spring_force(muscle.pam.spring, p_pa, length_m - natural_length(muscle.pam.spring, p_pa));
}

double plant_length_at_force(const MuscleSpec& muscle, double p_pa, double f_n) {
  if (!(f_n > 0)) return -1.0;
  if (!muscle.plant_file.empty()) return avbdl_length_at_force(muscle.plant, p_pa, f_n);
  const DeformationEstimate est = invert_spring_model(muscle.pam.spring, p_pa, f_n);
  if (est.status != InversionStatus::kOk) return -1.0;
  return natural_length(muscle.pam.spring, p_pa) + est.d_m;
}

}  // namespace pamsim
