// schedule_key_tables.h: a muscle's commanded pressure (muscles.<actuator>.command, the
// paper's top controller p_tp of Eq. (12)-(13); core/schedule.h) as key-table rows
// (base/key_table.h): its kind, then one table per kind with that kind's keys. Each key's
// unit, range, default and meaning is one row, which the scenario reader
// (scenario_muscles.cc), `pamsim keys` and the tests read. What joins keys stays with
// validate(PressureSchedule): a pressure within the valve's command range, increasing times,
// one pressure per time; a table's CSV file (a path) is read by hand.
#pragma once

#include <string>
#include <vector>

#include "base/key_table.h"
#include "sim/core/schedule.h"

namespace pamsim {

// muscles.<actuator>.command's kind, bound to `schedule`'s kind.
KeyTable schedule_kind_key_table(PressureSchedule* schedule);

// The keys of `kind`'s schedule, bound to `schedule` (constant: MPa; ramp: from_MPa, to_MPa,
// start_s, duration_s; sine: offset_MPa, amplitude_MPa, period_s, phase_deg, start_s; steps:
// times_s and MPa lists; table: file, the CSV's path).
KeyTable schedule_key_table(ScheduleKind kind, PressureSchedule* schedule);

// The shorthand pressure.<actuator>_MPa (pamsim 0.1 files): the constant schedule's MPa row,
// renamed, bound to `schedule` (`actuator` may be the placeholder "<actuator>").
KeyTable pressure_shorthand_key_table(PressureSchedule* schedule, const std::string& actuator);

}  // namespace pamsim
