// scenario_hil.h: the scenario's [hil] keys (core/scenario.h: HilSpec) as key-table rows
// (base/key_table.h), for the reader and `pamsim keys`.
#pragma once

#include "base/key_table.h"
#include "sim/core/scenario.h"

namespace pamsim {

class ConfigReader;

// [hil], bound to `hil`.
KeyTable hil_key_table(HilSpec* hil);
// Reads [hil] into sc->hil. Throws InputError "<file>: hil.<key> ...".
void read_hil(ConfigReader& in, Scenario* sc);

}  // namespace pamsim
