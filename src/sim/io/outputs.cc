// outputs.cc: see outputs.h.
#include "sim/io/outputs.h"

#include <unistd.h>

#include <charconv>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <variant>
#include <vector>

#include <boost/math/distributions/students_t.hpp>

#include "base/atomic_file.h"
#include "base/format.h"
#include "base/input_error.h"
#include "base/units.h"
#include "sim/core/metrics.h"

namespace pamsim {
nlohmann::json number_or_null(double v) {
  return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr);
}

namespace {

nlohmann::json scenario_json(const Scenario& sc) {
  nlohmann::json j = {{"file", sc.path},
                      {"valve_model", valve_model_name(sc.valve_model)},
                      {"controller", sc.controller_kind},
                      {"timestep_s", sc.timestep_s},
                      {"control_hz", sc.control_hz}};
  if (sc.controller) {  // the kind's own fields
    for (const SummaryField& f : sc.controller->summary_fields()) {
      std::visit([&](const auto& value) { j[f.key] = value; }, f.value);
    }
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
      if (c) out += ',';
      if (std::isfinite(v)) {
        out.append(buf, std::to_chars(buf, buf + sizeof(buf), v).ptr);  // format_shortest's form
      } else {
        out += "nan";
      }
    }
    out += '\n';
  }
  return out;
}

nlohmann::json summary_to_json(const TrialSummary& s, const Scenario& sc, bool with_timing) {
  nlohmann::json j;
  j["status"] = s.status;
  if (!s.message.empty()) j["message"] = s.message;
  j["seed"] = s.seed;
  for (const Metric& m : s.metrics) {
    if (!with_timing && is_timing_metric(m.name)) continue;
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

  // over the trials where the metric is defined (timing metrics: provenance.json)
  nlohmann::json metrics = nlohmann::json::object();
  if (!summaries.empty()) {
    const std::vector<Metric>& names = summaries.front().metrics;
    for (std::size_t k = 0; k < names.size(); ++k) {
      if (is_timing_metric(names[k].name)) continue;
      std::vector<double> values;
      for (const auto& s : summaries) {
        const double v = k < s.metrics.size() ? s.metrics[k].value : NAN;
        if (std::isfinite(v)) values.push_back(v);
      }
      const SampleStats st = sample_stats(values);
      metrics[names[k].name] = {{"mean", number_or_null(st.mean)},
                                {"sd", number_or_null(st.sd)},
                                {"ci95_low", number_or_null(st.ci95_low)},
                                {"ci95_high", number_or_null(st.ci95_high)},
                                {"min", number_or_null(st.min)},
                                {"max", number_or_null(st.max)},
                                {"count", st.count}};
    }
  }
  j["metrics"] = metrics;
  j["scenario"] = scenario_json(sc);
  return j;
}

SampleStats sample_stats(const std::vector<double>& values) {
  SampleStats st;
  st.count = static_cast<int>(values.size());
  if (values.empty()) return st;
  double sum = 0;
  st.min = INFINITY;
  st.max = -INFINITY;
  for (const double v : values) {
    sum += v;
    st.min = std::min(st.min, v);
    st.max = std::max(st.max, v);
  }
  st.mean = sum / st.count;
  if (st.count < 2) return st;
  double squares = 0;
  for (const double v : values) squares += (v - st.mean) * (v - st.mean);
  st.sd = std::sqrt(squares / (st.count - 1));
  const double half = ci95_half_width(st.sd, st.count);
  st.ci95_low = st.mean - half;
  st.ci95_high = st.mean + half;
  return st;
}

double ci95_half_width(double sd, int count) {
  if (count < 2 || !std::isfinite(sd)) return NAN;
  // Student's t interval for the mean: mean +- t(0.975, n - 1) sd / sqrt(n)
  const boost::math::students_t t(count - 1);
  return boost::math::quantile(t, 0.975) * sd / std::sqrt(static_cast<double>(count));
}

void refuse_existing_file(const std::string& path, bool force) {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (force || path == "-") return;
  const fs::file_status st = fs::status(path, ec);
  if (!fs::exists(st) || fs::is_fifo(st) || fs::is_character_file(st) || fs::is_block_file(st)) {
    return;
  }
  throw InputError(path + ": exists; add --force to replace it, or choose another output");
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
  std::vector<fs::path> missing;  // innermost first
  for (fs::path p = fs::path(dir).lexically_normal(); !p.empty() && !fs::exists(p, ec);
       p = p.parent_path()) {
    if (!fs::is_symlink(p, ec)) missing.push_back(p);  // (a dangling link: mkdir says so)
    if (p == p.parent_path() || p.parent_path().empty()) break;
  }
  for (auto it = missing.rbegin(); it != missing.rend(); ++it) {
    if (fs::create_directory(*it, ec)) {
      made_.push_back(it->string());
    } else if (ec) {
      break;  // make_directories below says why
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
  write_file_atomically(dir + "/summary.json",
                        summary_to_json(result.summary, sc, false).dump(2) + "\n");
}

}  // namespace pamsim
