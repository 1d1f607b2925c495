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

// The schedule through `column` of a CSV with a time_s column (a log, as
// sim/io/recording_csv.h reads it: its rows whose `column` cell is empty skipped), or, for
// column "MPa", read_schedule_csv's; `hold` as PressureSchedule's. Throws InputError
// "<path>: <problem>" also for a column the file lacks or one not in MPa (not ending _MPa).
PressureSchedule read_schedule_column(const std::string& path, const std::string& column,
                                      bool hold);

}  // namespace pamsim
