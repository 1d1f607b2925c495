// sensor_keys.h: the sensors' scenario keys sensors.* (noise, ADCs, the pressure low-pass) as
// rows (base/key_table.h), bound to the SensorConfig they fill: each key's name with its unit
// (the papers' MPa and mm/s), factor to the SI field, range, default and meaning in one row,
// which the scenario reader (read_key_rows), validate() (check_key_rows), `pamsim keys` and
// the tests' bad values read. The instruments as hardware (sensors.gauge.*, .pressure.*,
// .fiber.*, .encoder.*) are read in sim/scenario/scenario_sensors.cc.
#pragma once

#include "base/key_table.h"
#include "sensing/sensors.h"

namespace pamsim {

// Table "sensors", its keys bound to `sensors`. The ranges are each key's own; validate()
// adds what depends on other keys (an ADC's span, a cutoff under the control rate's Nyquist).
KeyTable sensor_key_table(SensorConfig* sensors);

}  // namespace pamsim
