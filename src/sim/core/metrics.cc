// metrics.cc: see metrics.h.
#include "sim/core/metrics.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

#include "base/input_error.h"
#include "base/no_value.h"
#include "base/units.h"
#include "sim/core/sensor_metrics.h"

namespace pamsim {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();
constexpr double kRecoveryBandDeg = 2.0;

int event_index(const Scenario& sc, const std::string& name) {
  const EventSpec* e = sc.event(name);
  return e ? static_cast<int>(e - sc.events.data()) : -1;
}

double event_time(const FinishedTrial& r, int index) {
  return index < 0 ? kNaN : r.event_time_s[static_cast<std::size_t>(index)];
}

// Root mean square and largest magnitude of a[r] - b[r] over rows where it is finite;
// `scale` divides each difference by b (per cent of the true value) when set.
struct ErrorStats {
  double sum_sq = 0.0;
  double max_abs = 0.0;
  long count = 0;
  void add(double e) {
    if (!std::isfinite(e)) return;
    sum_sq += e * e;
    max_abs = std::max(max_abs, std::fabs(e));
    ++count;
  }
  double rms() const { return count ? std::sqrt(sum_sq / count) : kNaN; }
  double max() const { return count ? max_abs : kNaN; }
};

double final_value(const FinishedTrial& r, std::size_t col) {
  const std::size_t n = r.log->rows();
  return n ? r.log->at(n - 1, col) : kNaN;
}

// drop: the falling mass's start, lowest and final angle, impact and recovery
class DropMetrics final : public MetricSet {
 public:
  explicit DropMetrics(const Scenario& sc)
      : release_(event_index(sc, "release")), impact_(event_index(sc, "impact")) {
    if (release_ < 0 || impact_ < 0) {
      throw InputError(sc.path +
                       ": metrics \"drop\" needs events named \"release\" and "
                       "\"impact\" (the [drop] table makes them)");
    }
  }
  bool wants_steps() const override { return true; }
  void on_step(double t, double angle, const std::vector<double>& event_time_s) override {
    if (!std::isfinite(event_time_s[release_])) return;
    if (angle < min_angle_) {
      min_angle_ = angle;
      min_angle_time_s_ = t;
    }
  }
  void finish(const FinishedTrial& r, std::vector<Metric>* out) const override {
    const bool released = std::isfinite(event_time(r, release_));
    const bool dipped = released && std::isfinite(min_angle_);
    const double start = released ? units::rad_to_deg(r.event_position[release_]) : kNaN;
    const double min = dipped ? units::rad_to_deg(min_angle_) : kNaN;
    const double final_angle = final_value(r, r.layout->joint_position);
    const double impact = event_time(r, impact_);
    out->push_back({"start_angle_deg", start});
    out->push_back({"min_angle_deg", min});
    out->push_back({"min_angle_time_s", dipped ? min_angle_time_s_ : kNaN});
    out->push_back({"peak_drop_deg", dipped ? start - min : kNaN});
    out->push_back({"final_angle_deg", final_angle});
    out->push_back({"impact_time_s", impact});
    out->push_back({"recovery_time_s", recovery_time(r, impact, final_angle)});
    const bool retained = std::isfinite(impact) && r.event_holds_at_end[impact_];
    out->push_back({"mass_retained", retained ? 1.0 : 0.0, true});
  }

 private:
  // from the impact until the angle stays within the band of its final value
  static double recovery_time(const FinishedTrial& r, double impact, double final_angle) {
    if (!std::isfinite(impact)) return kNaN;
    double last_outside = impact;
    for (std::size_t row = 0; row < r.log->rows(); ++row) {
      const double t = r.log->at(row, r.layout->time);
      if (t >= impact &&
          std::fabs(r.log->at(row, r.layout->joint_position) - final_angle) > kRecoveryBandDeg) {
        last_outside = t;
      }
    }
    return last_outside - impact;
  }

  int release_;
  int impact_;
  double min_angle_ = kInfinity;
  double min_angle_time_s_ = kNaN;
};

// reflex: triggers per muscle, the first, and mistrips before the impact
class ReflexMetrics final : public MetricSet {
 public:
  explicit ReflexMetrics(const Scenario& sc) : impact_(event_index(sc, "impact")) {}
  void finish(const FinishedTrial& r, std::vector<Metric>* out) const override {
    const auto* triggers = r.controller_event("stretch_trigger");
    double first = kNaN;
    int mistrips = 0, after_impact = 0;
    const double impact = event_time(r, impact_);
    for (std::size_t j = 0; j < r.labels.size(); ++j) {
      const std::size_t n = triggers ? (*triggers)[j].size() : 0;
      out->push_back({"reflex_triggers_" + r.labels[j], static_cast<double>(n), true});
      for (std::size_t k = 0; k < n; ++k) {
        const double t = (*triggers)[j][k];
        if (k == 0 && !(t >= first)) first = t;
        if (t >= impact) {
          ++after_impact;
        } else {
          ++mistrips;
        }
      }
    }
    out->push_back({"first_trigger_time_s", first});
    out->push_back({"mistrips", static_cast<double>(mistrips), true});
    out->push_back({"retriggers_after_impact", std::max(after_impact - 1, 0) * 1.0, true});
  }

 private:
  int impact_;
};

// events: when each of the scenario's events fired (NaN if it never did): a landing's "fall"
// (a trunk below a height, action "end"), a drop's "impact"
class EventMetrics final : public MetricSet {
 public:
  explicit EventMetrics(const Scenario& sc) {
    for (const EventSpec& e : sc.events) names_.push_back("event_" + e.name + "_time_s");
  }
  void finish(const FinishedTrial& r, std::vector<Metric>* out) const override {
    for (std::size_t k = 0; k < names_.size(); ++k) {
      out->push_back({names_[k], k < r.event_time_s.size() ? r.event_time_s[k] : kNaN});
    }
  }

 private:
  std::vector<std::string> names_;
};

// tension: the lines' peak pulls (and in per cent of a line's working limit and of its break
// load, where the scenario gives them) and the tension reflexes' triggers
class TensionMetrics final : public MetricSet {
 public:
  explicit TensionMetrics(const Scenario& sc) {
    for (const MuscleSpec& m : sc.muscles) {
      limit_n_[m.label] = m.line_limit_n;
      break_n_[m.label] = m.line_break_n;
    }
  }
  void finish(const FinishedTrial& r, std::vector<Metric>* out) const override {
    const auto* triggers = r.controller_event("tension_trigger");
    double first = kNaN;
    for (std::size_t j = 0; j < r.labels.size(); ++j) {
      const double peak = j < r.peak_tension_n.size() ? r.peak_tension_n[j] : kNaN;
      out->push_back({"peak_tension_" + r.labels[j] + "_N", peak});
      for (const auto& [loads, name] :
           {std::pair{&limit_n_, "line_load_"}, std::pair{&break_n_, "line_break_load_"}}) {
        const auto load = loads->find(r.labels[j]);
        if (load == loads->end() || std::isnan(load->second)) continue;
        out->push_back({name + r.labels[j] + "_pct", 100.0 * peak / load->second});
      }
      const std::size_t n = triggers ? (*triggers)[j].size() : 0;
      out->push_back({"tension_triggers_" + r.labels[j], static_cast<double>(n), true});
      if (n > 0 && !((*triggers)[j].front() >= first)) first = (*triggers)[j].front();
    }
    out->push_back({"first_tension_trigger_time_s", first});
  }

 private:
  std::map<std::string, double> limit_n_;  // by label
  std::map<std::string, double> break_n_;  // by label
};

// length_estimate: the estimate against the encoder, all muscles pooled [mm]
class LengthEstimateMetrics final : public MetricSet {
 public:
  void finish(const FinishedTrial& r, std::vector<Metric>* out) const override {
    ErrorStats mm, pct;
    std::vector<std::size_t> estimate, truth;  // per muscle
    for (std::size_t j = 0; j < r.labels.size(); ++j) {
      estimate.push_back(r.layout->column_of("length_est_{m}_mm", j));
      truth.push_back(r.layout->column_of("length_{m}_mm", j));
    }
    for (std::size_t row = 0; row < r.log->rows(); ++row) {
      for (std::size_t j = 0; j < r.labels.size(); ++j) {
        const double error = r.log->at(row, estimate[j]) - r.log->at(row, truth[j]);
        mm.add(error);
        pct.add(100.0 * error / r.log->at(row, truth[j]));
      }
    }
    out->push_back({"length_est_rmse_mm", mm.rms()});
    out->push_back({"length_est_max_error_mm", mm.max()});
    out->push_back({"length_est_rmse_pct", pct.rms()});
    out->push_back({"length_est_max_error_pct", pct.max()});
  }
};

// tracking: pressure and length-estimate errors per muscle, the joint's range
class TrackingMetrics final : public MetricSet {
 public:
  void finish(const FinishedTrial& r, std::vector<Metric>* out) const override {
    const Trajectory& log = *r.log;
    for (std::size_t j = 0; j < r.labels.size(); ++j) {
      const std::size_t p = r.layout->column_of("p_{m}_MPa", j);
      const std::size_t p_cmd = r.layout->column_of("p_cmd_{m}_MPa", j);
      const std::size_t length = r.layout->column_of("length_{m}_mm", j);
      const std::size_t length_est = r.layout->column_of("length_est_{m}_mm", j);
      ErrorStats pressure, length_pct;
      for (std::size_t row = 0; row < log.rows(); ++row) {
        pressure.add(log.at(row, p) - log.at(row, p_cmd));
        const double truth = log.at(row, length);
        length_pct.add(100.0 * (log.at(row, length_est) - truth) / truth);
      }
      const std::string& m = r.labels[j];
      out->push_back({"pressure_rmse_" + m + "_MPa", pressure.rms()});
      out->push_back({"length_est_rmse_" + m + "_pct", length_pct.rms()});
      out->push_back({"length_est_max_error_" + m + "_pct", length_pct.max()});
    }

    // the joint: start, final, lowest and highest
    double lo = kNaN, hi = kNaN;
    for (std::size_t row = 0; row < log.rows(); ++row) {
      const double q = log.at(row, r.layout->joint_position);
      if (!(q >= lo)) lo = q;
      if (!(q <= hi)) hi = q;
    }
    const std::string q = r.hinge ? "angle_" : "position_";
    const std::string unit = r.hinge ? "_deg" : "_mm";
    out->push_back({q + "start" + unit, log.rows() ? log.at(0, r.layout->joint_position) : kNaN});
    out->push_back({q + "final" + unit, final_value(r, r.layout->joint_position)});
    out->push_back({q + "min" + unit, lo});
    out->push_back({q + "max" + unit, hi});
  }
};

// trial and solver: always there
class TrialMetrics final : public MetricSet {
 public:
  void finish(const FinishedTrial& r, std::vector<Metric>* out) const override {
    out->push_back({"steps", static_cast<double>(r.steps), true});
    out->push_back({"sim_time_s", r.sim_time_s});
    out->push_back({"wall_time_s", r.wall_time_s});
    out->push_back({"realtime_factor", r.wall_time_s > 0 ? r.sim_time_s / r.wall_time_s : kNaN});
  }
};

class SolverMetrics final : public MetricSet {
 public:
  void finish(const FinishedTrial& r, std::vector<Metric>* out) const override {
    out->push_back({"cvode_steps", static_cast<double>(r.cvode_steps), true});
    out->push_back({"cvode_rhs_evals", static_cast<double>(r.cvode_rhs_evals), true});
  }
};

}  // namespace

double TrialSummary::metric(const std::string& name) const {
  for (const Metric& m : metrics) {
    if (m.name == name) return m.value;
  }
  return kNaN;
}

const std::vector<std::vector<double>>* FinishedTrial::controller_event(
    const std::string& name) const {
  for (std::size_t k = 0; events && event_times_s && k < events->size(); ++k) {
    if ((*events)[k].name == name && k < event_times_s->size()) return &(*event_times_s)[k];
  }
  return nullptr;
}

bool is_timing_metric(const std::string& name) {
  return name == "wall_time_s" || name == "realtime_factor";
}

const std::vector<std::string>& metric_set_names() {
  static const std::vector<std::string> names = {
      "drop", "reflex", "length_estimate", "tracking", "tension", "sensors", "events"};
  return names;
}

std::vector<std::unique_ptr<MetricSet>> make_metric_sets(const Scenario& sc, const mjModel* model) {
  std::vector<std::unique_ptr<MetricSet>> sets;
  for (const std::string& name : sc.metrics) {
    if (name == "drop") {
      sets.push_back(std::make_unique<DropMetrics>(sc));
    } else if (name == "reflex") {
      sets.push_back(std::make_unique<ReflexMetrics>(sc));
    } else if (name == "length_estimate") {
      sets.push_back(std::make_unique<LengthEstimateMetrics>());
    } else if (name == "tracking") {
      sets.push_back(std::make_unique<TrackingMetrics>());
    } else if (name == "tension") {
      sets.push_back(std::make_unique<TensionMetrics>(sc));
    } else if (name == "sensors") {
      sets.push_back(std::make_unique<SensorMetrics>(model));
    } else if (name == "events") {
      sets.push_back(std::make_unique<EventMetrics>(sc));
    } else {
      throw InputError(sc.path + ": metrics names an unknown set \"" + name +
                       "\" (known: drop, reflex, length_estimate, tracking, tension, sensors, "
                       "events)");
    }
  }
  sets.push_back(std::make_unique<TrialMetrics>());
  sets.push_back(std::make_unique<SolverMetrics>());
  return sets;
}

void require_unique_metric_names(const Scenario& sc, std::vector<std::string> names) {
  std::sort(names.begin(), names.end());
  const auto twice = std::adjacent_find(names.begin(), names.end());
  if (twice != names.end()) {
    throw InputError(sc.path + ": metrics name two metrics " + *twice +
                     " (rename the model's sensor that gives it)");
  }
}

std::vector<std::string> metric_names(const Scenario& sc, const std::vector<std::string>& labels,
                                      bool hinge, const mjModel* model) {
  // every set writes the same names whatever the data: finish a trial with no rows
  const LogLayout layout = make_log_layout(hinge, {}, labels);
  Trajectory log;
  log.columns = layout.columns;
  FinishedTrial record;
  record.scenario = &sc;
  record.log = &log;
  record.layout = &layout;
  record.labels = labels;
  record.hinge = hinge;
  record.event_time_s.assign(sc.events.size(), kNaN);
  record.event_position.assign(sc.events.size(), kNaN);
  record.event_holds_at_end.assign(sc.events.size(), 0);
  std::vector<Metric> metrics;
  for (const auto& set : make_metric_sets(sc, model)) set->finish(record, &metrics);
  std::vector<std::string> names;
  for (const Metric& m : metrics) names.push_back(m.name);
  return names;
}

}  // namespace pamsim
