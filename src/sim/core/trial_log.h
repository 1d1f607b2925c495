// trial_log.h: a trial's log, one row per control tick, with its columns laid out from the
// channel table (trial_channels.h: names with units, per-muscle columns carrying the muscle's
// label) for the trial's joint, held bodies, muscles and the controller's declared channels.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "reflex/controller.h"
#include "sim/core/trial_channels.h"

namespace pamsim {

// The log, row-major; columns named by its layout.
struct Trajectory {
  std::vector<std::string> columns;
  std::vector<double> values;  // row-major
  std::size_t rows() const { return columns.empty() ? 0 : values.size() / columns.size(); }
  double at(std::size_t row, std::size_t col) const { return values[row * columns.size() + col]; }
  std::size_t column(const std::string& name) const;  // throws std::out_of_range
  bool has_column(const std::string& name) const;
};

inline constexpr std::size_t kNoColumn = static_cast<std::size_t>(-1);

// Where a column's value comes from: a row of the channel table for one instance (the muscle,
// the held body, 0 for a single column), or a channel the controller declares.
struct LogColumn {
  std::size_t row = 0;  // index in trial_channel_table()
  std::size_t instance = 0;
  bool controller = false;  // the controller's channel `channel` for muscle `instance`
  std::size_t channel = 0;
};

struct LogLayout {
  std::vector<std::string> columns;
  std::vector<LogColumn> sources;                  // per column
  std::vector<std::string> controller_quantities;  // per declared channel: "reflex"
  std::size_t time = 0, joint_position = 1, joint_velocity = 2;
  // The column of table row `row_name` ("length_est_{m}_mm") for muscle or body `instance`;
  // throws std::logic_error when the layout has none.
  std::size_t column_of(const std::string& row_name, std::size_t instance = 0) const;
};

// `hinge`: the joint's kind; `bodies`: the held bodies' names; `labels`: the muscles';
// `channels`: what the controller's kind logs per muscle.
LogLayout make_log_layout(bool hinge, const std::vector<std::string>& bodies,
                          const std::vector<std::string>& labels,
                          const std::vector<ControllerChannel>& channels = {});

// One row of the log: every column's value from `o`, into `row` (layout.columns.size()).
void write_log_row(const LogLayout& layout, const TrialObservation& o, double* row);

// One quantity of an observation by its name without the muscle ("p_meas_MPa", "reflex"),
// in its column's unit: one value per muscle, or one for a single column (a held body's
// height is a single column by its full name).
struct ObservedQuantity {
  std::string name;
  std::string unit;
  bool per_muscle = false;
  bool measured = false;  // what a controller on the robot sees (ChannelRow::measured)
  std::vector<double> values;
};

// Every quantity of the layout's columns, read from `o` as the log would write it.
std::vector<ObservedQuantity> observed_quantities(const LogLayout& layout,
                                                  const TrialObservation& o);

// One column (or, for the table, one row) as the reference of trajectory.csv's columns shows
// it (`pamsim keys --channels`).
struct ChannelDoc {
  std::string column;  // "force_{m}_N" for a row, "force_ago_N" for a layout's column
  std::string unit;
  double si_per_unit = 1.0;  // SI = value * si_per_unit
  std::string meaning;
  std::string source;
  bool measured = false;
};

// The table's rows; with a layout and the controller's channels it was made with, each of its
// columns (the controller's with their own meanings).
std::vector<ChannelDoc> channel_docs();
std::vector<ChannelDoc> channel_docs(const LogLayout& layout,
                                     const std::vector<ControllerChannel>& channels);

}  // namespace pamsim
