// trajectory_csv.h: reads a trial's trajectory.csv back (the format of outputs.h's
// trajectory_to_csv): a header row of column names, then one row of numbers per control
// tick, comma-separated; "nan" marks a missing value. Used by `pamsim compare`.
#pragma once

#include <string>

#include "sim/core/trial_log.h"

namespace pamsim {

// Throws InputError "<path>: <problem>" if the file cannot be read, the header is empty or
// repeats a name, a row has more or fewer cells than the header ("line 7 has 3 cells, the
// header has 28 columns"), or a cell is not a number ("line 7, column angle_deg: 'x' is not
// a number").
Trajectory read_trajectory_csv(const std::string& path);

}  // namespace pamsim
