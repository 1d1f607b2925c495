// schedule.h: a muscle's commanded pressure over time, the paper's "top controller" p_tp of
// Eq. (12)-(13): what the valve is asked for before any reflex acts. One per muscle, from
// the scenario's muscles.<name>.command table (see scenario/scenario_file.h for its keys):
//   constant  p(t) = p0
//   ramp      p0 until start_s, then linear to p1 over duration_s, then p1 (the reaching
//             task: 0.2 -> 0.6 MPa over 12 s)
//   sine      offset + amplitude sin(2 pi (t - start_s) / period_s + phase) for t >= start_s,
//             offset before (the length-estimation test: 0.2 sin(2 pi t / 5) + 0.6 MPa)
//   steps     levels[i] from times[i] on, levels[0] before times[0]
//   table     piecewise linear through (time_s, MPa) points read from a CSV file
//             (scenario/schedule_csv.h), held constant before the first and after the last point;
//             with `hold`, each point held until the next instead (a zero-order hold, as a
//             regulator holds the command a controller logged at its tick)
// Pressures are gauge [Pa] inside; the scenario gives MPa.
#pragma once

#include <string>
#include <vector>

namespace pamsim {

enum class ScheduleKind { kConstant, kRamp, kSine, kSteps, kTable };

// Every kind, in the order of ScheduleKind.
const std::vector<ScheduleKind>& schedule_kinds();
// "constant" | "ramp" | "sine" | "steps" | "table"
const char* to_string(ScheduleKind kind);
// Throws InputError "<key> must be one of ..., got "<name>"" on anything else.
ScheduleKind parse_schedule_kind(const std::string& name, const std::string& key);

inline constexpr double kHoldToleranceS = 1e-9;

struct PressureSchedule {
  ScheduleKind kind = ScheduleKind::kConstant;
  double p0_pa = 0.4e6;           // constant, ramp start, sine offset
  double p1_pa = 0.4e6;           // ramp end
  double amplitude_pa = 0.0;      // sine
  double period_s = 1.0;          // sine, > 0
  double phase_rad = 0.0;         // sine
  double start_s = 0.0;           // ramp, sine
  double duration_s = 1.0;        // ramp, > 0
  std::vector<double> times_s;    // steps, table: strictly increasing
  std::vector<double> values_pa;  // steps, table: one per time
  std::string source;             // table: the CSV file it came from (for messages)
  std::string column = "MPa";     // table: the file's column of pressures
  bool hold = false;              // table: a zero-order hold through the points, not linear

  // p(t) [Pa]. Constant schedules return p0_pa exactly. A held table's point applies from
  // kHoldToleranceS before its time, so that a tick computed as step x timestep meets the
  // point a log printed at that tick's decimal time.
  double at(double t_s) const;
  // The smallest and largest value p(t) takes (for range checks against the supply).
  double min_pa() const;
  double max_pa() const;
};

// The piecewise-linear schedule through rows (times_s[i], values_pa[i]), at least one, as
// read from the file `source` (scenario/schedule_csv.h reads it).
PressureSchedule table_schedule(std::vector<double> times_s, std::vector<double> values_pa,
                                std::string source);

// Throws InputError "<key>.<field> <problem>" if the schedule's own fields are inconsistent
// (period or duration <= 0, steps times not increasing or sizes differing, non-finite
// values), or if any value leaves [0, max_pa] (the valve's command range).
void validate(const PressureSchedule& schedule, const std::string& key, double max_pa);

}  // namespace pamsim
