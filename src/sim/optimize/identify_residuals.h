// identify_residuals.h: what `pamsim identify` minimises. A recording's trial is
// its scenario (the base, the file's overrides, the recording's `set`, the parameters) run
// with the scenario's seed; each chosen channel's simulated column is interpolated linearly
// at the recording's sample times (gaps skipped), and each residual is its difference from
// the recording in the channel's noise floors (IdentifyResiduals).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "sim/optimize/identify_db.h"
#include "sim/optimize/identify_file.h"

namespace pamsim {

// The finite difference's step in the unit box (the polish's Jacobian, the plan's
// sensitivities): wide enough to step over the chamber ODE's tolerance, fine enough for
// 0.1 % of a parameter's range.
inline constexpr double kDifferenceStep = 1e-3;

// The points parameter j's central difference of `step` steps to: its two sides of `unit`
// (one of them `unit` itself within `step` of a bound, never a point outside the box, which
// the parameters' ranges may not allow) and their distance.
struct DifferenceSides {
  std::vector<double> plus, minus;
  double width = 0.0;
};
DifferenceSides difference_sides(const std::vector<double>& unit, std::size_t j, double step);

// A recording's trial: its log's time and the chosen channels' columns, or the reason it did
// not run to the end (a divergence, or a value the scenario refuses: InputError; other
// errors propagate, and nothing is stored for the point).
struct SimulatedRecording {
  std::vector<double> time_s;
  std::vector<std::vector<double>> columns;  // per chosen channel, the log's rows
  std::string failure;                       // "" when the trial ran to the end
};

// The chosen channels as the recording's sensors read them at its sample times: gain x
// column(t - delay) + offset (definition's channel parameters at `values`), linear between
// the log's rows; NaN where the recording has no sample. Empty if the trial failed.
std::vector<std::vector<double>> sample_channels(const IdentifyDefinition& def,
                                                 const IdentifyRecording& recording,
                                                 const SimulatedRecording& sim,
                                                 const std::vector<double>& values);

SimulatedRecording simulate_recording(const IdentifyDefinition& def,
                                      const IdentifyRecording& recording,
                                      const std::vector<std::string>& overrides);

// The plant forces [N] of tensile test `t`'s muscle, the base scenario with `overrides`, at
// its rows; empty (with *failure set) if the scenario refuses the overrides.
std::vector<double> tensile_forces(const IdentifyDefinition& def, const IdentifyTensile& t,
                                   const std::vector<std::string>& overrides, std::string* failure);

// Per chosen channel, the RMS of sampled - recorded over its samples, in its unit (NaN for
// an empty `sampled`: its trial failed).
std::vector<double> channel_rmse(const IdentifyRecording& recording,
                                 const std::vector<std::vector<double>>& sampled);

// A residual is
//   sqrt(weight) (simulated - recorded) / sigma_c,
// sigma_c the channel's noise floor (residual_floor: the file's `noise`, else estimated from
// the recording), so that the cost is the chi-square of white noise at the floors: each
// channel weighs by what it can tell (least squares as maximum likelihood), whatever its unit.
// (The channel's standard deviation as sigma_c would let the noisy force and pressure
// channels outweigh a precise angle: the example's fit would end with its angle 45 noise
// floors off at a cost no higher than the truth's.) A tensile test's rows add
// sqrt(weight) (plant force - recorded force) / sigma_F, the plant's force on each row's
// stroke at its recorded pressure and length (tensile_test.h), sigma_F the recorded forces'
// floor found the same way. Residual vectors are kept in the run's database
// (identify_db.h), so a point is simulated once, whichever phase asks, and a resumed run
// simulates nothing twice.
class IdentifyResiduals {
 public:
  IdentifyResiduals(const IdentifyDefinition& def, IdentifyDb& db, int threads);

  std::size_t count() const { return count_; }  // residuals of the fitted recordings
  // The residual vector's series, in order: each fitted recording's channels, then each
  // tensile test; their lengths sum to count() (lags of a series stay within it).
  const std::vector<std::size_t>& segments() const { return segments_; }
  // The residuals at `unit` (clamped to [0, 1]), from the database or simulated (the fitted
  // recordings on `threads` threads) and stored under `phase`; empty if a trial failed.
  std::vector<double> at(const std::vector<double>& unit, const char* phase);
  // The parameters' values at `unit`.
  std::vector<double> values_at(const std::vector<double>& unit) const;
  // d residual / d offset of `column`'s sensor, per residual: sqrt(weight) / floor on the
  // fitted recordings' samples of `column` (the offset adds to each), 0 elsewhere.
  std::vector<double> offset_slope(const std::string& column) const;

  std::int64_t simulated = 0, cached = 0;  // points simulated, points answered from the db
  // Why the first point that failed failed ("" if none did, or it was stored before).
  const std::string& first_failure() const { return first_failure_; }

 private:
  const IdentifyDefinition& def_;
  IdentifyDb& db_;
  int threads_;
  std::size_t count_ = 0;
  std::vector<std::size_t> segments_;
  std::vector<std::size_t> fitted_;         // recordings fitted, in order
  std::vector<std::vector<double>> scale_;  // per recording, per chosen channel
  std::vector<double> tensile_scale_;       // per tensile test
  // the fitted recordings' trials of the last few scenario settings (the channel parameters'
  // differences need no new trial), by the settings' bits
  std::vector<std::pair<std::string, std::vector<SimulatedRecording>>> trials_;
  const std::vector<SimulatedRecording>& trials_at(const std::vector<double>& values);
  bool append_recordings(const std::vector<double>& values, std::vector<double>* out);
  bool append_tensile(const std::vector<double>& values, std::vector<double>* out);
  std::string first_failure_;
};

// A recorded channel's population standard deviation over its samples (NaN: a gap), 1 if it is
// (nearly) constant: the scale of its smallest noise floor.
double channel_scale(const std::vector<double>& samples);

// The smallest noise floor a channel is given, as a fraction of its standard deviation: a
// noise-free recording (simulated, or a smooth channel) is explained by a model within
// explained_noise_factor x 0.1 % of its spread (identify_uncertainty.h).
inline constexpr double kResolvedFraction = 1e-3;

// A recorded channel's noise floor: its white noise from its second differences
// (residual_statistics.h: noise_floor), at least kResolvedFraction of its spread; NaN where it
// has too few samples (under 10).
double judged_floor(const std::vector<double>& samples);

// The floor a channel's residuals are divided by: `given` (the file's noise), else
// judged_floor, else (too few samples) the channel's standard deviation.
double residual_floor(const std::vector<double>& samples, double given);

// The definition's parameters' values at `unit` (each clamped to [0, 1]).
std::vector<double> parameter_values(const IdentifyDefinition& def,
                                     const std::vector<double>& unit);

// Sum of squares; +inf for an empty (failed) vector.
double sum_of_squares(const std::vector<double>& residuals);

}  // namespace pamsim
