// fiber_hardware.cc: see fiber_hardware.h.
#include "sensing/fiber_hardware.h"

#include <cmath>

#include "base/units.h"
#include "sensing/instrument_keys.h"

namespace pamsim {

void validate(const FiberHardwareConfig& c) {
  FiberHardwareConfig fields = c;  // each key's own range (instrument_keys.h), then the creep
  check_key_rows(fiber_hardware_key_table(&fields));
  validate_prony(c.creep, "sensors.fiber.creep_weights", "sensors.fiber.creep_times_s");
}

FiberHardware::FiberHardware(const FiberHardwareConfig& config, double sample_period_s)
    : quadratic_per_m_(config.nonlinearity_pct / (100.0 * config.span_m)),
      creep_(config.creep, sample_period_s) {}

double FiberHardware::reading_m(double u_m) {
  // the linear conversion of a resistance that is not linear in the strain
  const double nonlinear = u_m * (1.0 + quadratic_per_m_ * u_m);
  // the knit's relaxation under the held displacement
  return creep_.step(nonlinear);
}

}  // namespace pamsim
