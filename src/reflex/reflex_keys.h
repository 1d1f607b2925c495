// reflex_keys.h: the reflexes' scenario keys as rows (base/key_table.h), bound to the
// structs they fill: reflex.* of the stretch (Ia) reflex, Eq. (12)-(14), and reflex.ib.* of
// the tension (Ib) reflex. Each key's name with its unit (the paper's: mm/s, MPa s/mm),
// factor to the SI field, range, default and meaning live in its row; the scenario reader
// (read_key_rows), validate() (check_key_rows), `pamsim keys` and the tests' bad values all
// come from these rows.
#pragma once

#include "base/key_table.h"
#include "reflex/stretch_reflex_controller.h"

namespace pamsim {

// Table "reflex": reflex.enabled, and with `stretch` the Ia reflex's keys; reflex.lowpass_hz
// fills *velocity_lowpass_hz (the low-pass the sensing applies for the controller). Choosing
// reflex.sensor sets Table II's threshold and gain for that sensor, which the keys then
// override.
KeyTable stretch_reflex_key_table(ReflexConfig* reflex, double* velocity_lowpass_hz,
                                  bool stretch = true);

// Table "reflex.ib": the Ib reflex's keys. The threshold and the gain are required in a
// scenario (no paper gives them for a PAM).
KeyTable tension_reflex_key_table(TensionReflexParams* ib);

}  // namespace pamsim
