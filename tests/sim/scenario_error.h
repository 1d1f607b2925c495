// scenario_error.h: the one-line message a scenario gives when loaded and bound with some
// --set overrides, for the tests of bad values (scenario_test.cc,
// scenario_bad_values_test.cc).
#pragma once

#include <string>
#include <vector>

#include "base/input_error.h"
#include "sim/core/trial_model.h"
#include "sim/scenario/scenario_file.h"
#include "sim/test_paths.h"

namespace pamsim_test {

// The message of the InputError thrown by loading `path` with `overrides` and binding its
// model, or "" if none.
inline std::string scenario_error(const std::vector<std::string>& overrides,
                                  const std::string& path = kDropMass) {
  try {
    const pamsim::Scenario sc = pamsim::load_scenario(path, overrides);
    pamsim::load_trial_model(sc);
  } catch (const pamsim::InputError& e) {
    return e.what();
  }
  return "";
}

}  // namespace pamsim_test
