// controller_replay.h: the embedded controller (src/embedded/pamctl.h) driven by a logged
// stream of its inputs (readings_csv.h), tick by tick, as a board would run it: per tick the
// commands, estimates, reflex windows and flags (replay.csv), the trigger times, and, where
// the log holds the commands a controller sent, the first tick that differs from the
// library's and the largest difference.
#pragma once

#include <ostream>
#include <string>
#include <vector>

#include "embedded/pamctl.h"
#include "sim/io/readings_csv.h"

namespace pamsim {

struct ReplayComparison {
  bool compared = false;           // the log holds every muscle's commands
  long first_differing_tick = -1;  // -1: every command equal, bit for bit
  double first_differing_time_s = 0.0;
  double largest_difference_pa = 0.0;
  std::string largest_muscle;  // where the largest difference is
};

struct ReplaySummary {
  long ticks = 0;
  std::vector<std::vector<double>> stretch_triggers_s;  // per muscle, the Ia windows' starts
  std::vector<std::vector<double>> tension_triggers_s;  // and the Ib windows'
  long flagged_ticks = 0;                               // ticks with any PAMCTL_FLAG_* set
  unsigned status = 0;                                  // the union of every tick's flags
  ReplayComparison comparison;
};

// Refuses (InputError "<path>: line N: ...") a stream whose ticks are not `period_s` apart
// (within 1e-6 of it): a log at another rate, or with a gap, must be resampled first.
void check_control_rate(const ControlStream& stream, double period_s, const std::string& path);

// Runs `config` over `stream` (p_tp_pa given for every muscle), writing replay.csv's header
// and rows to `csv`: time_s, then per muscle p_cmd_<m>_MPa, length_est_<m>_mm,
// velocity_<m>_mm_s (the velocity its stretch reflex acts on), force_meas_<m>_N, reflex_<m>,
// tension_reflex_<m> and flags_<m> (PAMCTL_FLAG_* bits).
ReplaySummary replay_controller(const pamctl_config& config,
                                const std::vector<std::string>& muscles,
                                const ControlStream& stream, std::ostream* csv);

}  // namespace pamsim

namespace pamsim {

// replay.png: each muscle's replayed commands (and the logged ones, dashed, where `stream`
// holds them) over the velocity each stretch reflex acted on with its threshold and windows;
// `csv` is replay_controller's output. Throws std::runtime_error when gnuplot fails.
void write_replay_plot(const std::string& png_path, const std::string& csv,
                       const pamctl_config& config, const std::vector<std::string>& muscles,
                       const ControlStream& stream);

}  // namespace pamsim
