// identify_residuals.cc: see identify_residuals.h.
#include "sim/optimize/identify_residuals.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "base/input_error.h"
#include "base/no_value.h"
#include "sim/core/runner.h"
#include "sim/core/trial.h"
#include "sim/core/trial_model.h"
#include "sim/optimize/residual_statistics.h"
#include "sim/scenario/scenario_file.h"

namespace pamsim {
namespace {

// `column` at time t, linear between the rows of `time_s` (its ends beyond them); `row` is
// where the search starts and is left at (times asked in increasing order)
double interpolate(const std::vector<double>& time_s, const std::vector<double>& column, double t,
                   std::size_t* row) {
  const std::size_t n = time_s.size();
  if (t <= time_s[0]) return column[0];
  while (*row + 1 < n && time_s[*row + 1] <= t) ++*row;
  if (*row + 1 >= n) return column[n - 1];
  const double t0 = time_s[*row], t1 = time_s[*row + 1];
  const double w = t1 > t0 ? (t - t0) / (t1 - t0) : 0.0;
  return column[*row] + w * (column[*row + 1] - column[*row]);
}

// A point's settings as a key: their bits
std::string bits_key(const std::vector<double>& values) {
  return std::string(reinterpret_cast<const char*>(values.data()), values.size() * sizeof(double));
}

}  // namespace

SimulatedRecording simulate_recording(const IdentifyDefinition& def, const IdentifyRecording& r,
                                      const std::vector<std::string>& overrides) {
  SimulatedRecording out;
  try {
    const Scenario sc = load_scenario_text(def.base_text, def.base_path, overrides);
    const TrialResult trial = run_trial(load_trial_model(sc), sc, sc.seed, true);
    if (trial.summary.status != "ok") {
      out.failure = trial.summary.status + ": " + trial.summary.message;
      return out;
    }
    const Trajectory& log = trial.trajectory;
    for (std::size_t row = 0; row < log.rows(); ++row) out.time_s.push_back(log.at(row, 0));
    for (std::size_t c : r.channels) {
      const std::size_t column = log.column(r.data.channels[c]);
      std::vector<double> v(log.rows());
      for (std::size_t row = 0; row < v.size(); ++row) v[row] = log.at(row, column);
      out.columns.push_back(std::move(v));
    }
  } catch (const InputError& e) {  // a value the scenario refuses, or a model that fails
    out.failure = e.what();
  }
  return out;
}

std::vector<std::vector<double>> sample_channels(const IdentifyDefinition& def,
                                                 const IdentifyRecording& r,
                                                 const SimulatedRecording& sim,
                                                 const std::vector<double>& values) {
  std::vector<std::vector<double>> out;
  if (!sim.failure.empty()) return out;
  for (std::size_t i = 0; i < r.channels.size(); ++i) {
    const ChannelTransform t = def.transform_at(r, i, values);
    const std::vector<double>& rec = r.data.samples[r.channels[i]];
    std::vector<double> v(rec.size(), kNaN);
    std::size_t row = 0;
    for (std::size_t k = 0; k < v.size(); ++k) {
      const double simulated =
          interpolate(sim.time_s, sim.columns[i], r.data.time_s[k] - t.delay_s, &row);
      if (!std::isnan(rec[k])) v[k] = t.gain * simulated + t.offset;
    }
    out.push_back(std::move(v));
  }
  return out;
}

std::vector<double> tensile_forces(const IdentifyDefinition& def, const IdentifyTensile& t,
                                   const std::vector<std::string>& overrides,
                                   std::string* failure) {
  try {
    const Scenario sc = load_scenario_text(def.base_text, def.base_path, overrides);
    for (const MuscleSpec& m : sc.muscles) {
      if (m.actuator == t.muscle) return plant_forces_along(m.plant, t.rows);
    }
    *failure = "no muscle " + t.muscle;
  } catch (const InputError& e) {
    *failure = e.what();
  }
  return {};
}

std::vector<double> channel_rmse(const IdentifyRecording& r,
                                 const std::vector<std::vector<double>>& sampled) {
  std::vector<double> out;
  for (std::size_t i = 0; i < r.channels.size(); ++i) {
    const std::vector<double>& rec = r.data.samples[r.channels[i]];
    double sum = 0;
    int n = 0;
    for (std::size_t k = 0; k < rec.size() && !sampled.empty(); ++k) {
      if (std::isnan(rec[k])) continue;
      sum += (sampled[i][k] - rec[k]) * (sampled[i][k] - rec[k]);
      ++n;
    }
    out.push_back(n > 0 ? std::sqrt(sum / n) : kNaN);
  }
  return out;
}

IdentifyResiduals::IdentifyResiduals(const IdentifyDefinition& def, IdentifyDb& db, int threads)
    : def_(def), db_(db), threads_(threads) {
  for (std::size_t i = 0; i < def.recordings.size(); ++i) {
    const IdentifyRecording& r = def.recordings[i];
    std::vector<double> scales;
    for (std::size_t k = 0; k < r.channels.size(); ++k) {
      const std::size_t c = r.channels[k];
      scales.push_back(residual_floor(r.data.samples[c], r.noise[k]));
      if (!r.held_out) segments_.push_back(r.data.sample_count(c));
    }
    scale_.push_back(std::move(scales));
    if (!r.held_out) fitted_.push_back(i);
  }
  for (const IdentifyTensile& t : def.tensile) {
    std::vector<double> forces;
    for (const TensileRow& row : t.rows) forces.push_back(row.force_n);
    tensile_scale_.push_back(residual_floor(forces, kNaN));
    segments_.push_back(t.rows.size());
  }
  for (std::size_t length : segments_) count_ += length;
}

bool IdentifyResiduals::append_tensile(const std::vector<double>& values,
                                       std::vector<double>* out) {
  for (std::size_t k = 0; k < def_.tensile.size(); ++k) {
    const IdentifyTensile& t = def_.tensile[k];
    std::string failure;
    const std::vector<double> forces = tensile_forces(def_, t, def_.overrides_at(values), &failure);
    if (forces.empty()) {
      if (first_failure_.empty()) first_failure_ = failure;
      return false;
    }
    const double w = std::sqrt(t.weight);
    for (std::size_t i = 0; i < forces.size(); ++i) {
      out->push_back(w * (forces[i] - t.rows[i].force_n) / tensile_scale_[k]);
    }
  }
  return true;
}

std::vector<double> IdentifyResiduals::values_at(const std::vector<double>& unit) const {
  return parameter_values(def_, unit);
}

std::vector<double> parameter_values(const IdentifyDefinition& def,
                                     const std::vector<double>& unit) {
  std::vector<double> values;
  for (std::size_t i = 0; i < unit.size(); ++i) {
    values.push_back(value_at(def.parameters[i], std::clamp(unit[i], 0.0, 1.0)));
  }
  return values;
}

std::vector<double> IdentifyResiduals::at(const std::vector<double>& unit_in, const char* phase) {
  std::vector<double> unit = unit_in;
  for (double& u : unit) u = std::clamp(u, 0.0, 1.0);
  if (const auto stored = db_.find(unit)) {
    if (!stored->empty() && stored->size() != count_) {
      throw std::runtime_error(db_.path() + ": a stored point has " +
                               std::to_string(stored->size()) + " residuals, not " +
                               std::to_string(count_) + " (a damaged database)");
    }
    ++cached;
    return *stored;
  }
  const std::vector<double> values = values_at(unit);
  std::vector<double> residuals;
  if (!append_recordings(values, &residuals) || !append_tensile(values, &residuals)) {
    residuals.clear();
  }
  ++simulated;
  db_.insert(unit, phase, sum_of_squares(residuals), residuals);
  return residuals;
}

const std::vector<SimulatedRecording>& IdentifyResiduals::trials_at(
    const std::vector<double>& values) {
  const std::string key = bits_key(def_.scenario_values(values));
  for (const auto& [k, trials] : trials_) {
    if (k == key) return trials;
  }
  std::vector<SimulatedRecording> sims(fitted_.size());
  parallel_for(static_cast<int>(fitted_.size()), threads_, [&](int k) {
    const IdentifyRecording& r = def_.recordings[fitted_[static_cast<std::size_t>(k)]];
    sims[static_cast<std::size_t>(k)] = simulate_recording(def_, r, def_.overrides_at(r, values));
  });
  constexpr std::size_t kKept = 4;  // a Jacobian's channel columns reuse its centre's trials
  if (trials_.size() == kKept) trials_.erase(trials_.begin());
  trials_.emplace_back(key, std::move(sims));
  return trials_.back().second;
}

bool IdentifyResiduals::append_recordings(const std::vector<double>& values,
                                          std::vector<double>* out) {
  const std::vector<SimulatedRecording>& sims = trials_at(values);
  for (std::size_t k = 0; k < fitted_.size(); ++k) {
    if (!sims[k].failure.empty()) {
      if (first_failure_.empty()) first_failure_ = sims[k].failure;
      return false;
    }
    const IdentifyRecording& r = def_.recordings[fitted_[k]];
    const std::vector<std::vector<double>> sampled = sample_channels(def_, r, sims[k], values);
    const double w = std::sqrt(r.weight);
    for (std::size_t i = 0; i < r.channels.size(); ++i) {
      const std::vector<double>& rec = r.data.samples[r.channels[i]];
      for (std::size_t j = 0; j < rec.size(); ++j) {
        if (!std::isnan(rec[j]))
          out->push_back(w * (sampled[i][j] - rec[j]) / scale_[fitted_[k]][i]);
      }
    }
  }
  return true;
}

std::vector<double> IdentifyResiduals::offset_slope(const std::string& column) const {
  std::vector<double> out;
  for (std::size_t k = 0; k < fitted_.size(); ++k) {  // append_recordings' order
    const IdentifyRecording& r = def_.recordings[fitted_[k]];
    const double w = std::sqrt(r.weight);
    for (std::size_t i = 0; i < r.channels.size(); ++i) {
      const double slope =
          r.data.channels[r.channels[i]] == column ? w / scale_[fitted_[k]][i] : 0.0;
      for (double v : r.data.samples[r.channels[i]]) {
        if (!std::isnan(v)) out.push_back(slope);
      }
    }
  }
  out.resize(count_, 0.0);  // the tensile tests' residuals
  return out;
}

double judged_floor(const std::vector<double>& samples) {
  return std::max(noise_floor(samples), kResolvedFraction * channel_scale(samples));
}

double residual_floor(const std::vector<double>& samples, double given) {
  if (std::isfinite(given)) return given;
  const double floor = judged_floor(samples);
  return std::isfinite(floor) ? floor : channel_scale(samples);
}

double channel_scale(const std::vector<double>& samples) {
  double sum = 0;
  int n = 0;
  for (double v : samples) {
    if (!std::isnan(v)) sum += v, ++n;
  }
  const double mean = sum / n;
  double var = 0;
  for (double v : samples) {
    if (!std::isnan(v)) var += (v - mean) * (v - mean) / n;
  }
  return var > 1e-24 ? std::sqrt(var) : 1.0;
}

double sum_of_squares(const std::vector<double>& residuals) {
  if (residuals.empty()) return std::numeric_limits<double>::infinity();
  double s = 0;
  for (double r : residuals) s += r * r;
  return s;
}

DifferenceSides difference_sides(const std::vector<double>& unit, std::size_t j, double step) {
  DifferenceSides s{unit, unit, 0.0};
  if (unit[j] + step <= 1.0) s.plus[j] += step;
  if (unit[j] - step >= 0.0) s.minus[j] -= step;
  s.width = s.plus[j] - s.minus[j];
  return s;
}

}  // namespace pamsim
