// schedule_csv.h: the CSV file of a muscles.<m>.command of kind "table": its rows, read and
// checked here, become a core schedule (core/schedule.h, table_schedule).
#pragma once

#include <string>

#include "sim/core/schedule.h"

namespace pamsim {

// Reads a piecewise-linear schedule from a CSV file with the header "time_s,MPa" (blank
// lines and lines starting with '#' skipped). Throws InputError "<path>: line N: <problem>"
// for a missing file, a bad header, a cell that is not a finite number, fewer than one row,
// or a time that does not increase strictly.
PressureSchedule read_schedule_csv(const std::string& path);

}  // namespace pamsim
