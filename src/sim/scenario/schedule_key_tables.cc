// schedule_key_tables.cc: the rows of muscles.<actuator>.command (schedule_key_tables.h).
#include "sim/scenario/schedule_key_tables.h"

#include <string>

#include "base/units.h"

namespace pamsim {
namespace {

constexpr double kMPa = units::kPaPerMPa;
const char* const kTable = "muscles.<actuator>.command";
constexpr std::size_t kMaxSteps = 100000;  // a steps schedule's most levels

NumberRow pressure_row(const std::string& name, const std::string& doc, double* target) {
  NumberRow row{name, "MPa", kMPa, kNonNegativeRange, doc, target};
  row.required = true;
  return row;
}

NumberRow start_row(PressureSchedule& s) {
  return {"start_s", "s", 1.0, kNonNegativeRange, "when it starts (the start pressure before)",
          &s.start_s};
}

}  // namespace

KeyTable schedule_kind_key_table(PressureSchedule* schedule) {
  KeyTable t{kTable, {}, {}, {}};
  std::vector<std::string> names;
  for (ScheduleKind kind : schedule_kinds()) names.emplace_back(to_string(kind));
  t.choices = {
      {"kind", names, "the commanded pressure's schedule (core/schedule.h)",
       [schedule](const std::string& name) { schedule->kind = parse_schedule_kind(name, "kind"); },
       [schedule] { return std::string(to_string(schedule->kind)); }}};
  return t;
}

KeyTable schedule_key_table(ScheduleKind kind, PressureSchedule* schedule) {
  PressureSchedule& s = *schedule;
  KeyTable t{kTable, {}, {}, {}};
  switch (kind) {
    case ScheduleKind::kConstant:
      t.numbers = {pressure_row("MPa", "the commanded pressure", &s.p0_pa)};
      break;
    case ScheduleKind::kRamp: {
      NumberRow duration{"duration_s",          "s",          1.0, kPositiveRange,
                         "the ramp's duration", &s.duration_s};
      duration.required = true;
      t.numbers = {pressure_row("from_MPa", "the ramp's start", &s.p0_pa),
                   pressure_row("to_MPa", "the ramp's end", &s.p1_pa), start_row(s), duration};
      break;
    }
    case ScheduleKind::kSine: {
      NumberRow period{"period_s", "s", 1.0, kPositiveRange, "the sine's period", &s.period_s};
      period.required = true;
      NumberRow phase{"phase_deg", "deg", units::kPi, kAnyRange, "the sine's phase at start_s",
                      &s.phase_rad};
      phase.divisor = 180.0;  // units::deg_to_rad's rounding
      t.numbers = {pressure_row("offset_MPa", "the sine's mean", &s.p0_pa),
                   pressure_row("amplitude_MPa", "the sine's amplitude", &s.amplitude_pa), period,
                   phase, start_row(s)};
      break;
    }
    case ScheduleKind::kSteps:
      t.lists = {{"times_s", "s", 1.0, kNonNegativeRange, kMaxSteps,
                  "the steps' times, increasing: MPa[i] from times_s[i] on, MPa[0] before",
                  &s.times_s, "(required)", 1},
                 {"MPa", "MPa", kMPa, kNonNegativeRange, kMaxSteps,
                  "the steps' pressures, one per time", &s.values_pa, "(required)", 1}};
      break;
    case ScheduleKind::kTable:
      t.texts = {{"file",
                  "a CSV \"time_s,MPa\": a piecewise linear schedule through its rows "
                  "(scenario/schedule_csv.h); or a wider CSV with time_s and `column`",
                  &s.source, "(required)", true, true},
                 {"column",
                  "the file's column of pressures [MPa]: \"MPa\" in a file of the two columns "
                  "\"time_s,MPa\", or a name ending in _MPa in a wider one, such as a log's "
                  "p_cmd_ago_MPa (its empty cells skipped)",
                  &s.column}};
      t.bools = {{"hold",
                  "true: each row held until the next (a zero-order hold, as a regulator holds "
                  "the command logged at a controller's tick); false: linear between rows",
                  &s.hold}};
      break;
  }
  return t;
}

KeyTable pressure_shorthand_key_table(PressureSchedule* schedule, const std::string& actuator) {
  return as_shorthand(schedule_key_table(ScheduleKind::kConstant, schedule), "pressure",
                      actuator + "_MPa", "a constant muscles.<actuator>.command");
}

}  // namespace pamsim
