// scenario_errors.h: checking that a shipped scenario refuses bad values by key (the test
// helpers scenario_test.cc, scenario_bad_values_test.cc, scenario_keys_test.cc,
// tension_reflex_scenario_test.cc and leg_test.cc share).
#pragma once

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "base/input_error.h"
#include "sim/core/trial_model.h"
#include "sim/scenario/scenario_file.h"
#include "sim/test_paths.h"

namespace pamsim_test {

// The message of the InputError that reading scenarios/`scenario` (or `scenario` itself, an
// absolute path) with `overrides` and binding its model throws, or "" if none.
inline std::string error_of(const std::string& scenario,
                            const std::vector<std::string>& overrides) {
  const std::string path = scenario.rfind('/', 0) == 0 ? scenario : kScenarios + scenario;
  try {
    const pamsim::Scenario sc = pamsim::load_scenario(path, overrides);
    pamsim::load_trial_model(sc);
  } catch (const pamsim::InputError& e) {
    return e.what();
  }
  return "";
}

struct BadValue {
  std::vector<std::string> assignments;
  std::string key;  // the message names it
};

// Each case is refused with one line that names the scenario file and the key.
inline void expect_each_named(const std::string& scenario, const std::vector<BadValue>& cases) {
  for (const BadValue& c : cases) {
    const std::string what = scenario + " --set " + c.assignments.front();
    const std::string message = error_of(scenario, c.assignments);
    EXPECT_NE(message.find(c.key), std::string::npos) << what << " -> \"" << message << "\"";
    EXPECT_NE(message.find(scenario), std::string::npos) << what << " -> " << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << "one line: " << message;
  }
}

}  // namespace pamsim_test
