// scenario_key_docs.h: the documentation of every scenario key, one entry each, for `pamsim keys`:
// its unit, default, allowed values and one-line meaning. Keys under a name the scenario
// chooses are written with a placeholder: muscles.<actuator>.params, bodies.<body>.mass_kg,
// holds.<body>.*, events.<event>.*. tests/sim/cli/cli_keys_test.cc holds this list to the keys
// the reader (scenario_file.h) asks for, both ways, and the literal defaults to the reader's.
#pragma once

#include <string>
#include <vector>

#include "base/key_table.h"  // KeyDoc

namespace pamsim {

const std::vector<KeyDoc>& scenario_key_docs();

// The documentation of a concrete key ("muscles.agonist.command.MPa" is documented as
// "muscles.<actuator>.command.MPa"), or nullptr if no documented key matches.
const KeyDoc* scenario_key_doc(const std::string& key);

// True if `key` names a table of documented keys ("events", "muscles.agonist.command"), not
// a key itself.
bool is_scenario_table(const std::string& key);

// Whether a scenario key (dotted, as a file writes it) is one load_trial_model never reads,
// as its row says (KeyTable::trial_only: the run's length and seed, the controller's gains,
// the sensors, the pneumatics, the drop's time and height); a table is when every documented
// key under it is. An undocumented key counts as the model's: a row that misses the flag
// costs a sweep a model load, never a wrong model (trial_model_identity_test holds the flags
// to the built models).
bool trial_only_key(const std::string& key);

}  // namespace pamsim
