// outputs.cc: see outputs.h.
#include "sim/io/outputs.h"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>

#include "pam_actuator/atomic_file.h"
#include "pam_actuator/input_error.h"
#include "pam_actuator/units.h"

namespace pamsim {
namespace {

nlohmann::json number_or_null(double v) {
  return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr);
}

nlohmann::json scenario_json(const Scenario& sc) {
  return {{"file", sc.path},
          {"valve_model", valve_model_name(sc.valve_model)},
          {"reflex_enabled", sc.reflex.reflex.enabled},
          {"reflex_sensor", to_string(sc.reflex.reflex.sensor)},
          {"v_thr_mm_s", sc.reflex.reflex.v_thr_mm_s},
          {"k_MPa_s_per_mm", sc.reflex.reflex.k_MPa_s_per_mm},
          {"drop_time_s", sc.drop_time_s},
          {"timestep_s", sc.timestep_s},
          {"control_hz", sc.control_hz}};
}

}  // namespace

std::vector<std::pair<std::string, double>> trial_metrics(const TrialSummary& s) {
  return {
      {"start_angle_deg", s.start_angle_deg},
      {"min_angle_deg", s.min_angle_deg},
      {"min_angle_time_s", s.min_angle_time_s},
      {"peak_drop_deg", s.peak_drop_deg},
      {"final_angle_deg", s.final_angle_deg},
      {"impact_time_s", s.impact_time_s},
      {"steps", static_cast<double>(s.steps)},
      {"sim_time_s", s.sim_time_s},
      {"wall_time_s", s.wall_time_s},
      {"realtime_factor", s.realtime_factor},
      {"reflex_triggers_ago", static_cast<double>(s.reflex_triggers_ago)},
      {"reflex_triggers_anta", static_cast<double>(s.reflex_triggers_anta)},
      {"first_trigger_time_s", s.first_trigger_time_s},
      {"mistrips", static_cast<double>(s.mistrips)},
      {"recovery_time_s", s.recovery_time_s},
      {"length_est_rmse_mm", s.length_est_rmse_mm},
      {"length_est_max_error_mm", s.length_est_max_error_mm},
      {"cvode_steps", static_cast<double>(s.cvode_steps)},
      {"cvode_rhs_evals", static_cast<double>(s.cvode_rhs_evals)},
  };
}

bool is_timing_metric(const std::string& name) {
  return name == "wall_time_s" || name == "realtime_factor";
}

std::string trajectory_to_csv(const Trajectory& tr) {
  std::string out;
  for (std::size_t c = 0; c < tr.columns.size(); ++c) {
    out += (c ? "," : "") + tr.columns[c];
  }
  out += "\n";
  char buf[32];
  for (std::size_t r = 0; r < tr.rows(); ++r) {
    for (std::size_t c = 0; c < tr.columns.size(); ++c) {
      const double v = tr.at(r, c);
      if (std::isfinite(v)) {
        std::snprintf(buf, sizeof(buf), "%.10g", v);
      } else {
        std::snprintf(buf, sizeof(buf), "nan");
      }
      if (c) out += ',';
      out += buf;
    }
    out += '\n';
  }
  return out;
}

nlohmann::json summary_to_json(const TrialSummary& s, const Scenario& sc) {
  nlohmann::json j;
  j["status"] = s.status;
  if (!s.message.empty()) j["message"] = s.message;
  j["seed"] = s.seed;
  for (const auto& [name, value] : trial_metrics(s)) j[name] = number_or_null(value);
  j["steps"] = s.steps;
  j["reflex_triggers_ago"] = s.reflex_triggers_ago;
  j["reflex_triggers_anta"] = s.reflex_triggers_anta;
  j["mistrips"] = s.mistrips;
  j["cvode_steps"] = s.cvode_steps;
  j["cvode_rhs_evals"] = s.cvode_rhs_evals;
  j["scenario"] = scenario_json(sc);
  return j;
}

nlohmann::json aggregate_summaries(const std::vector<TrialSummary>& summaries,
                                   const Scenario& sc) {
  nlohmann::json j;
  j["trials"] = summaries.size();
  std::map<std::string, int> status_counts;
  nlohmann::json seeds = nlohmann::json::array();
  for (const auto& s : summaries) {
    ++status_counts[s.status];
    seeds.push_back(s.seed);
  }
  j["seeds"] = seeds;
  j["status_counts"] = status_counts;

  // mean, min and max over the trials where the metric is defined
  nlohmann::json metrics = nlohmann::json::object();
  if (!summaries.empty()) {
    std::vector<std::vector<std::pair<std::string, double>>> table;
    table.reserve(summaries.size());
    for (const auto& s : summaries) table.push_back(trial_metrics(s));
    const auto& names = table.front();
    for (std::size_t k = 0; k < names.size(); ++k) {
      double sum = 0, lo = INFINITY, hi = -INFINITY;
      int n = 0;
      for (const auto& row : table) {
        const double v = row[k].second;
        if (!std::isfinite(v)) continue;
        sum += v;
        lo = std::min(lo, v);
        hi = std::max(hi, v);
        ++n;
      }
      metrics[names[k].first] = {{"mean", n ? nlohmann::json(sum / n) : nlohmann::json(nullptr)},
                                 {"min", n ? nlohmann::json(lo) : nlohmann::json(nullptr)},
                                 {"max", n ? nlohmann::json(hi) : nlohmann::json(nullptr)},
                                 {"count", n}};
    }
  }
  j["metrics"] = metrics;
  j["scenario"] = scenario_json(sc);
  return j;
}

void make_directories(const std::string& dir) {
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec || !std::filesystem::is_directory(dir)) {
    throw InputError(dir + ": cannot create output folder (" + ec.message() + ")");
  }
}

void write_trial_outputs(const std::string& dir, const TrialResult& result, const Scenario& sc) {
  make_directories(dir);
  write_file_atomically(dir + "/trajectory.csv", trajectory_to_csv(result.trajectory));
  write_file_atomically(dir + "/summary.json", summary_to_json(result.summary, sc).dump(2) + "\n");
}

}  // namespace pamsim
