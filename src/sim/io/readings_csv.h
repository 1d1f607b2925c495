// readings_csv.h: a controller's stream of inputs, tick by tick: what `pamsim run --readings`
// writes (readings.csv: the embedded controller's inputs exactly as the simulator handed
// them, and the commands it returned) and what `pamsim controller replay` reads back, from
// that file, from a trial's trajectory.csv or from a lab's log with the same columns (the
// columns are listed at readings_columns).
#pragma once

#include <string>
#include <vector>

#include "sim/core/trial.h"

namespace pamsim {

// One muscle's columns over the ticks; a column the log lacks is left empty.
struct MuscleStream {
  std::vector<double> pressure_v;
  std::vector<double> gauge_v;
  std::vector<double> fiber_rate_m_s;  // zeros when the log has no fiber column
  std::vector<double> p_tp_pa;         // empty: the log has none
  std::vector<double> p_cmd_pa;        // empty: the log has none
};

struct ControlStream {
  std::vector<double> time_s;
  std::vector<char> enabled;  // all 1 when the log has no column
  bool has_enabled = false;
  std::vector<MuscleStream> muscles;  // in the order asked for
  int missing_readings = 0;           // NaN or empty reading cells
};

// Columns, one row per control tick (any other column is ignored):
//   time_s                                 required
//   enabled                                0 or 1: events switched the reflexes off; default 1
//   pressure_sensor_<m>_V, gauge_<m>_V     required for every muscle m
//   fiber_rate_<m>_m_s | fiber_rate_<m>_mm_s   the fiber sensor's rate; default 0 (none)
//   p_tp_<m>_Pa | p_tp_<m>_MPa             the scheduled goal pressure; default: the scenario's
//   p_cmd_<m>_Pa | p_cmd_<m>_MPa           the commands a controller sent, to compare with
// readings.csv holds the SI columns (m_s, Pa), written as the shortest decimal text that reads
// back to the same double: the one lossless form. A "nan" or empty reading cell is a missing
// reading, handed on as NaN (the embedded controller's documented handling) and counted; any
// other cell that is not a number is refused.
//
// The header of readings.csv for these muscles' labels.
std::vector<std::string> readings_columns(const std::vector<std::string>& muscles);

// Writes `log` as readings.csv, atomically. Throws std::runtime_error when it cannot write.
void write_readings_csv(const std::string& path, const std::vector<std::string>& muscles,
                        const ControlLog& log);

// Reads `text` (named `path` in messages) for the muscles labelled `muscles`. Throws
// InputError "<path>: <problem>" naming the line and column: no time_s or a muscle's required
// column, a repeated column, a row whose cell count is not the header's, a cell that is not a
// number, an enabled cell other than 0 or 1, no rows.
ControlStream read_control_stream(const std::string& text, const std::string& path,
                                  const std::vector<std::string>& muscles);

}  // namespace pamsim
