// time_and_drop_keys.cc: the rows of [sim] and [drop] (see time_and_drop_keys.h).
#include "sim/scenario/time_and_drop_keys.h"

#include <limits>

namespace pamsim {

KeyTable sim_key_table(Scenario* scenario, double* max_steps) {
  constexpr double inf = std::numeric_limits<double>::infinity();
  KeyTable t{"sim", {}, {}, {}};
  t.numbers = {
      {"timestep_s", "s", 1.0, {0.0, 0.01, true, false}, "physics step", &scenario->timestep_s},
      {"duration_s", "s", 1.0, {0.0, 3600.0, true, false},
       "simulated time of a trial (after every timed event)", &scenario->duration_s},
      {"control_hz", "Hz", 1.0, {0.0, inf, true, false},
       "control, sensing and logging rate, a whole divisor of 1 / sim.timestep_s",
       &scenario->control_hz},
      {"max_steps", "", 1.0, {1.0, 1e10, false, false},
       "the most physics steps a trial may take (at least duration_s / timestep_s)",
       max_steps}};
  return t;
}

KeyTable drop_key_table(DropShorthand* drop) {
  KeyTable t{"drop", {}, {}, {}};
  t.bools = {{"enabled", "shorthand: drop the mass at drop.time_s", &drop->enabled}};
  t.numbers = {
      {"mass_kg", "kg", 1.0, {0.0, 10.0, true, false}, "shorthand: the falling mass",
       &drop->mass_kg},
      {"height_m", "m", 1.0, {0.0, 1.0, false, false},
       "shorthand: its fall height above the basket floor", &drop->height_m},
      {"time_s", "s", 1.0, {0.0, 3600.0, false, true},
       "shorthand: when it is released, before sim.duration_s", &drop->time_s}};
  return t;
}

}  // namespace pamsim
