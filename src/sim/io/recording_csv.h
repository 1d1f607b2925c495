// recording_csv.h: a lab's recording of a trial, as `pamsim identify` reads it: a CSV file
// whose header names `time_s` and any of the columns `pamsim run` writes to trajectory.csv
// (angle_deg, p_meas_<label>_MPa, force_meas_<label>_N, gauge_<label>_V, ...; the channel
// table lists them, trial_channels.h), in that file's units. Any sampling rate, also uneven; an
// empty cell is a sample that channel lacks (a gap, or a channel that started late). Lines starting
// with
// '#' and blank lines are skipped.
// Refused, naming the file and line: no `time_s` column, no other column, a column named
// twice, a row with another number of cells than the header, a cell that is not a finite
// number ("nan", "inf", text), a time that does not increase strictly, a time before 0, a
// channel with no samples, fewer than two rows.
#pragma once

#include <string>
#include <vector>

namespace pamsim {

struct Recording {
  std::string path;
  std::vector<double> time_s;
  std::vector<std::string> channels;         // the header's columns but time_s, in order
  std::vector<std::vector<double>> samples;  // per channel, per row; NaN where the cell is empty

  std::size_t channel(const std::string& name) const;   // index, or channels.size()
  std::size_t sample_count(std::size_t channel) const;  // its non-empty cells
};

// Throws InputError "<path>: <problem>" or "<path>: line <n>: <problem>".
Recording read_recording_csv(const std::string& path);

}  // namespace pamsim
