// outputs.cc: see outputs.h.
#include "sim/io/outputs.h"

#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <vector>

#include "pam_actuator/atomic_file.h"
#include "pam_actuator/input_error.h"
#include "pam_actuator/units.h"

namespace pamsim {
namespace {

nlohmann::json number_or_null(double v) {
  return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr);
}

nlohmann::json scenario_json(const Scenario& sc) {
  nlohmann::json j = {
      {"file", sc.path},
      {"valve_model", valve_model_name(sc.valve_model)},
      {"controller", sc.controller == ControllerKind::kNone ? "none" : "stretch_reflex"},
      {"timestep_s", sc.timestep_s},
      {"control_hz", sc.control_hz}};
  if (sc.controller == ControllerKind::kStretchReflex) {
    const ReflexConfig& r = sc.reflex.reflex;
    j["reflex_enabled"] = r.enabled;
    j["reflex_sensor"] = to_string(r.sensor);
    j["v_thr_mm_s"] = r.v_thr_mm_s;
    j["k_MPa_s_per_mm"] = r.k_MPa_s_per_mm;
  }
  if (const EventSpec* release = sc.event("release")) {
    if (release->when.kind == ConditionKind::kTime)
      j["drop_time_s"] = number_or_null(release->when.at_s);
  }
  return j;
}

}  // namespace

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
  for (const Metric& m : s.metrics) {
    j[m.name] = m.integer ? nlohmann::json(static_cast<long>(m.value)) : number_or_null(m.value);
  }
  j["scenario"] = scenario_json(sc);
  return j;
}

nlohmann::json aggregate_summaries(const std::vector<TrialSummary>& summaries, const Scenario& sc) {
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
    const std::vector<Metric>& names = summaries.front().metrics;
    for (std::size_t k = 0; k < names.size(); ++k) {
      double sum = 0, lo = INFINITY, hi = -INFINITY;
      int n = 0;
      for (const auto& s : summaries) {
        const double v = k < s.metrics.size() ? s.metrics[k].value : NAN;
        if (!std::isfinite(v)) continue;
        sum += v;
        lo = std::min(lo, v);
        hi = std::max(hi, v);
        ++n;
      }
      metrics[names[k].name] = {{"mean", n ? nlohmann::json(sum / n) : nlohmann::json(nullptr)},
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

FolderGuard::FolderGuard(const std::string& dir) {
  namespace fs = std::filesystem;
  std::error_code ec;
  std::vector<fs::path> missing;   // innermost first
  for (fs::path p = fs::path(dir).lexically_normal(); !p.empty() && !fs::exists(p, ec);
       p = p.parent_path()) {
    if (!fs::is_symlink(p, ec)) missing.push_back(p);   // (a dangling link: mkdir says so)
    if (p == p.parent_path() || p.parent_path().empty()) break;
  }
  for (auto it = missing.rbegin(); it != missing.rend(); ++it) {
    if (fs::create_directory(*it, ec)) {
      made_.push_back(it->string());
    } else if (ec) {
      break;   // make_directories below says why
    }
  }
  try {
    make_directories(dir);
  } catch (...) {
    remove_made();
    throw;
  }
}

FolderGuard::~FolderGuard() { remove_made(); }

void FolderGuard::remove_made() {
  // innermost first, and only while empty: whatever was put there meanwhile stays
  for (auto it = made_.rbegin(); it != made_.rend(); ++it) {
    if (::rmdir(it->c_str()) != 0) break;
  }
  made_.clear();
}

void write_trial_outputs(const std::string& dir, const TrialResult& result, const Scenario& sc) {
  make_directories(dir);
  write_file_atomically(dir + "/trajectory.csv", trajectory_to_csv(result.trajectory));
  write_file_atomically(dir + "/summary.json", summary_to_json(result.summary, sc).dump(2) + "\n");
}

}  // namespace pamsim
