// avbdl_keys.h: an AVBDL plant's parameters (avbdl.h, Pipan et al.) as key rows
// (base/key_table.h), in the plant file's units and layout: [geometry], [bladder], [friction]
// with its [friction.extension] and [friction.contraction]. Each parameter's key with its
// unit, factor to the SI field, range, default and meaning is one row, which the plant file's
// reader (plant_params.h), validate_avbdl_params, `pamsim keys --plant` and the tests' bad
// values all read. A new plant parameter is a field of AvbdlParams and a row here.
#pragma once

#include <vector>

#include "base/key_table.h"
#include "pam_actuator/avbdl.h"

namespace pamsim {

// The tables geometry, bladder, friction, friction.extension, friction.contraction, bound to
// `plant`. Ranges are each key's own; validate_avbdl_params adds the checks that join keys.
std::vector<KeyTable> avbdl_key_tables(AvbdlParams* plant);

}  // namespace pamsim
