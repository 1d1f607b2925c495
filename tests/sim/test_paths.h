// test_paths.h: where the command-line and scenario tests find the source tree's files (one
// definition: the sim tests compile a few files to a unit, tests/CMakeLists.txt).
#pragma once

#include <string>

namespace pamsim_test {

inline const std::string kSource = PAMSIM_SOURCE_DIR;
inline const std::string kScenarios = kSource + "/scenarios/";
inline const std::string kDropMass = kScenarios + "drop_mass.toml";
inline const std::string kReaching = kScenarios + "reaching.toml";
// the arm agonist's bladder wall as a scenario key (a plant field)
inline const std::string kAgonistWall = "muscles.agonist.plant.geometry.wall_thickness_mm";

}  // namespace pamsim_test
