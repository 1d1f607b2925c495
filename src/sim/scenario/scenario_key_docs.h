// scenario_key_docs.h: the documentation of every scenario key, one entry each, for `pamsim keys`:
// its unit, default, allowed values and one-line meaning. Keys under a name the scenario
// chooses are written with a placeholder: muscles.<actuator>.params, bodies.<body>.mass_kg,
// holds.<body>.*, events.<event>.*. tests/sim/cli_keys_test.cc holds this list to the keys
// the reader (scenario_file.h) asks for, both ways, and the literal defaults to the reader's.
#pragma once

#include <string>
#include <vector>

namespace pamsim {

struct KeyDoc {
  std::string key;       // dotted, with placeholders
  std::string unit;      // "s", "MPa", "" (none)
  std::string fallback;  // the default as TOML text ("0.001", "\"iso6358\""), or in
                         // parentheses where it is not one value ("(Table II)", "(required)")
  std::string allowed;   // the values the reader accepts
  std::string meaning;
};

const std::vector<KeyDoc>& scenario_key_docs();

// The documentation of a concrete key ("muscles.agonist.command.MPa" is documented as
// "muscles.<actuator>.command.MPa"), or nullptr if no documented key matches.
const KeyDoc* scenario_key_doc(const std::string& key);

// True if `key` names a table of documented keys ("events", "muscles.agonist.command"), not
// a key itself.
bool is_scenario_table(const std::string& key);

}  // namespace pamsim
