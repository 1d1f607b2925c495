// reaching.cc: see reaching.h.
#include "sim/validate/reaching.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>
#include <mutex>
#include <sstream>

#include "base/atomic_file.h"
#include "base/format.h"
#include "base/input_error.h"
#include "base/no_value.h"
#include "sim/core/runner.h"
#include "sim/core/trial_model.h"
#include "base/config_reader.h"
#include "sim/io/gnuplot.h"
#include "sim/io/outputs.h"
#include "sim/scenario/scenario_file.h"
#include "sim/validate/line_breaks.h"
#include "sim/validate/table_cells.h"

namespace pamsim {
namespace {

namespace fs = std::filesystem;

const char* const kMethods[] = {"model", "fiber"};
const char* const kParts[] = {"all", "before_slack", "after_slack"};

// Max and RMS of errors in % of length, pooled.
struct ErrorPool {
  double sum_sq = 0.0, max_abs = 0.0;
  int n = 0;
  void add(double e) {
    if (!std::isfinite(e)) return;  // a diverged trial's tail
    sum_sq += e * e;
    max_abs = std::max(max_abs, std::fabs(e));
    ++n;
  }
  ErrorPct result() const { return {n ? max_abs : kNaN, n ? std::sqrt(sum_sq / n) : kNaN}; }
};

// One muscle's estimates over a trajectory's window: the model's from its log column, the
// fiber's as its rate integrated from the encoder at the window's start (Sec. III-C)
struct MuscleErrors {
  std::vector<double> time_s, model_pct, fiber_pct;
};

MuscleErrors muscle_errors(const Trajectory& tr, const std::string& label, double start_s,
                           double end_s, double dt_s) {
  const std::size_t t = tr.column("time_s"), truth = tr.column("length_" + label + "_mm");
  const std::size_t est = tr.column("length_est_" + label + "_mm");
  const std::size_t rate = tr.column("fiber_rate_" + label + "_mm_s");
  MuscleErrors out;
  double fiber = kNaN;
  for (std::size_t i = 0; i < tr.rows(); ++i) {
    const double time = tr.at(i, t);
    if (time < start_s - 1e-9 || time > end_s + 1e-9) continue;
    // the fiber length: calibrated at the first sample, then its rate over each period
    fiber = std::isnan(fiber) ? tr.at(i, truth) : fiber + tr.at(i, rate) * dt_s;
    const double l = tr.at(i, truth);
    out.time_s.push_back(time);
    out.model_pct.push_back(100.0 * (tr.at(i, est) - l) / l);
    out.fiber_pct.push_back(100.0 * (fiber - l) / l);
  }
  return out;
}

// The first time at or after start_s [s] at which a muscle's line is taut, or +inf.
double first_taut_s(const Trajectory& tr, const std::string& label, double start_s) {
  const std::size_t t = tr.column("time_s"), force = tr.column("force_" + label + "_N");
  for (std::size_t i = 0; i < tr.rows(); ++i) {
    if (tr.at(i, t) >= start_s - 1e-9 && tr.at(i, force) > 0.0) return tr.at(i, t);
  }
  return std::numeric_limits<double>::infinity();
}

}  // namespace

SlackEpisode first_slack_episode(const Trajectory& tr, const std::string& label, double start_s,
                                 double end_s, double min_slack_s) {
  const std::size_t t = tr.column("time_s"), force = tr.column("force_" + label + "_N");
  const std::string meas_name = "force_meas_" + label + "_N";
  const bool read = tr.has_column(meas_name);
  const std::size_t meas = read ? tr.column(meas_name) : 0;
  bool was_taut = false;
  SlackEpisode episode{kNaN, ""};
  for (std::size_t i = 0; i < tr.rows(); ++i) {
    const double time = tr.at(i, t);
    if (time < start_s - 1e-9) continue;
    if (time > end_s + 1e-9) break;
    const double f = tr.at(i, force);
    const bool unread = read && f >= kPulledN && tr.at(i, meas) < kReadN;
    if (f > 0.0 && !unread) {
      was_taut = true;
      episode = {kNaN, ""};
      continue;
    }
    // a line that pulls unread is taut: its gauge may have lost it before the window
    was_taut = was_taut || unread;
    if (!was_taut) continue;
    if (std::isnan(episode.start_s)) episode = {time, unread ? "gauge" : "slack"};
    if (time - episode.start_s >= min_slack_s - 1e-9) return episode;
  }
  return {kNaN, ""};
}

double slack_episode_start(const Trajectory& tr, const std::string& label, double start_s,
                           double end_s, double min_slack_s) {
  return first_slack_episode(tr, label, start_s, end_s, min_slack_s).start_s;
}

namespace {

// One muscle's errors over every trial, pooled per method (model, fiber) and part (all,
// before and after its slack episode); its slack episodes' starts, per trial, in *starts.
void pool_muscle_errors(const ReachingValidationSpec& spec, const std::vector<TrialResult>& trials,
                        const std::string& label, double dt, ErrorPool (&pools)[2][3],
                        std::vector<double>* starts, std::vector<std::string>* causes) {
  for (const TrialResult& r : trials) {
    const SlackEpisode episode = first_slack_episode(r.trajectory, label, spec.window_start_s,
                                                     spec.window_end_s, spec.min_slack_s);
    const double slack = episode.start_s;
    starts->push_back(slack);
    causes->push_back(episode.cause);
    const MuscleErrors e =
        muscle_errors(r.trajectory, label, spec.window_start_s, spec.window_end_s, dt);
    // before: from the line's first taut sample to the episode; after: from the episode
    // on; a trial without an episode has neither
    const double taut = first_taut_s(r.trajectory, label, spec.window_start_s);
    for (std::size_t i = 0; i < e.time_s.size(); ++i) {
      int part = 0;
      if (!std::isnan(slack)) part = e.time_s[i] >= slack ? 2 : (e.time_s[i] >= taut ? 1 : 0);
      for (int method = 0; method < 2; ++method) {
        const double err = method == 0 ? e.model_pct[i] : e.fiber_pct[i];
        pools[method][0].add(err);
        if (part > 0) pools[method][part].add(err);
      }
    }
  }
}

// A row per method and part of one muscle's pooled errors, with the paper's where it has one.
void add_muscle_rows(const ReachingValidationSpec& spec, const MuscleSpec& m,
                     const ErrorPool (&pools)[2][3], std::vector<ReachingRow>* rows) {
  for (int method = 0; method < 2; ++method) {
    for (int part = 0; part < 3; ++part) {
      ReachingRow row;
      row.muscle = m.actuator;
      row.label = m.label;
      row.method = kMethods[method];
      row.part = kParts[part];
      row.sim = pools[method][part].result();
      row.samples = pools[method][part].n;
      std::string key = row.method + "_" + row.muscle;
      if (part > 0) key += std::string("_") + kParts[part];
      const auto paper = spec.paper.find(key);
      if (paper != spec.paper.end()) row.paper = paper->second;
      rows->push_back(row);
    }
  }
}

}  // namespace

ReachingValidationResult run_reaching_validation(const ReachingValidationSpec& spec,
                                                 const ValidationOptions& options) {
  ReachingValidationResult result;
  std::vector<std::string> overrides = options.overrides;
  if (options.seed) overrides.push_back("seed=" + std::to_string(*options.seed));
  result.scenario = load_scenario(spec.scenario_file, overrides);
  const Scenario& sc = result.scenario;
  if (spec.window_end_s > sc.duration_s) {
    throw InputError(spec.file + ": window_s ends at " + format_value(spec.window_end_s) +
                     " s, after the scenario's sim.duration_s = " + format_value(sc.duration_s) +
                     " s");
  }
  const TrialModel model = load_trial_model(sc);
  if (options.started) options.started(spec.trials);

  result.trials.resize(spec.trials);
  std::mutex progress_mutex;
  int done = 0;
  parallel_for(spec.trials, options.threads, [&](int k) {
    result.trials[k] = run_trial(model, sc, sc.seed + static_cast<std::uint64_t>(k));
    if (options.progress) {
      std::lock_guard<std::mutex> lock(progress_mutex);
      options.progress(++done, spec.trials);
    }
  });

  const double dt = 1.0 / sc.control_hz;
  for (const MuscleSpec& m : sc.muscles) {
    for (const TrialResult& r : result.trials) {
      if (!r.trajectory.has_column("force_" + m.label + "_N")) {
        throw InputError(spec.scenario_file + ": its log has no force_" + m.label +
                         "_N column (a reaching scenario logs every muscle)");
      }
    }
    std::vector<double> starts;
    std::vector<std::string> causes;
    // pools per method and part, over every trial
    ErrorPool pools[2][3];
    pool_muscle_errors(spec, result.trials, m.label, dt, pools, &starts, &causes);
    result.slack_start_s.push_back(starts);
    result.episode_cause.push_back(causes);
    add_muscle_rows(spec, m, pools, &result.rows);
  }
  std::vector<const Trajectory*> logs;
  for (const TrialResult& r : result.trials) logs.push_back(&r.trajectory);
  check_line_breaks(sc, logs);
  return result;
}

std::string table5_csv(const ReachingValidationResult& result) {
  std::ostringstream out;
  out << "muscle,method,part,samples,max_error_pct,rmse_pct,paper_max_error_pct,paper_rmse_pct,"
         "slack_start_s,episode_cause\n";
  for (const ReachingRow& row : result.rows) {
    std::size_t m = 0;
    while (m < result.scenario.muscles.size() && result.scenario.muscles[m].actuator != row.muscle)
      ++m;
    out << row.muscle << ',' << row.method << ',' << row.part << ',' << row.samples << ','
        << csv_number(row.sim.max_pct) << ',' << csv_number(row.sim.rmse_pct) << ','
        << (row.paper ? csv_number(row.paper->max_pct) : "") << ','
        << (row.paper ? csv_number(row.paper->rmse_pct) : "") << ','
        << csv_number(result.slack_start_s[m].front()) << ',' << result.episode_cause[m].front()
        << '\n';
  }
  return out.str();
}

std::string table5_markdown(const ReachingValidationResult& result,
                            const ReachingValidationSpec& spec) {
  std::ostringstream out;
  // "-": no sample fell in that part
  const auto cell = [](const ErrorPct& e, int samples) {
    return samples == 0 ? std::string("-") : markdown_error_pct(e);
  };
  out << "# Table V in simulation: length estimation in the reaching task, error in % of length\n\n"
      << "Each cell: simulation max / RMSE over " << spec.trials << " trials, "
      << format_value(spec.window_start_s) << "-" << format_value(spec.window_end_s)
      << " s (paper max / RMSE, Yoshida and Hosoda's Table V and Sec. IV-B; - where it gives "
         "none).\n\n";
  out << "| method | part |";
  for (const MuscleSpec& m : result.scenario.muscles) out << ' ' << m.actuator << " |";
  out << "\n| --- | --- |";
  for (std::size_t i = 0; i < result.scenario.muscles.size(); ++i) out << " --- |";
  out << '\n';
  for (const char* method : kMethods) {
    for (const char* part : kParts) {
      out << "| "
          << (std::string(method) == "model" ? "model (the estimator's law)" : "fiber sensor")
          << " | " << part << " |";
      for (const MuscleSpec& m : result.scenario.muscles) {
        for (const ReachingRow& row : result.rows) {
          if (row.muscle != m.actuator || row.method != method || row.part != part) continue;
          out << ' ' << cell(row.sim, row.samples);
          if (row.paper) out << " (" << cell(*row.paper, 1) << ')';
          out << " |";
        }
      }
      out << '\n';
    }
  }
  int ok = 0;
  for (const TrialResult& r : result.trials) ok += r.summary.status == "ok";
  out << "\nTrials that ran to the end: " << ok << " of " << result.trials.size()
      << ". Slack episodes (a line that has been taut goes " << format_value(spec.min_slack_s)
      << " s without a signal: at zero tension (slack), or pulling while its gauge reads "
         "nothing (gauge: the line has left the board); before = from the line's first taut "
         "sample to the episode), start per trial [s]:\n\n";
  for (std::size_t m = 0; m < result.scenario.muscles.size(); ++m) {
    out << "- " << result.scenario.muscles[m].actuator << ":";
    for (std::size_t k = 0; k < result.slack_start_s[m].size(); ++k) {
      const double s = result.slack_start_s[m][k];
      out << ' '
          << (std::isnan(s) ? "none" : format_value(s) + " (" + result.episode_cause[m][k] + ")");
    }
    out << '\n';
  }
  return out.str();
}

void write_reaching_validation(const ReachingValidationResult& result,
                               const ReachingValidationSpec& spec, const std::string& out_dir,
                               bool draw) {
  make_directories(out_dir);
  const Scenario& sc = result.scenario;
  const Trajectory& tr = result.trials.front().trajectory;
  GnuplotJob job;
  job.width_px = 1200;
  job.height_px = 900;
  std::string shading, plots;
  const char* colours[] = {"#c0392b", "#2471a3", "#7d3c98", "#117a65"};
  for (std::size_t m = 0; m < sc.muscles.size(); ++m) {
    const MuscleErrors e = muscle_errors(tr, sc.muscles[m].label, spec.window_start_s,
                                         spec.window_end_s, 1.0 / sc.control_hz);
    std::string data;
    for (std::size_t i = 0; i < e.time_s.size(); ++i) {
      data +=
          gp_num(e.time_s[i]) + ' ' + gp_num(e.model_pct[i]) + ' ' + gp_num(e.fiber_pct[i]) + '\n';
    }
    const std::string name = "m" + std::to_string(m) + ".dat";
    job.data_files.push_back({name, data});
    const std::string colour = colours[m % 4];
    const double slack = result.slack_start_s[m].front();
    if (!std::isnan(slack)) {
      shading += "set object rect from " + gp_num(slack) + ", graph 0 to " +
                 gp_num(spec.window_end_s) + ", graph 1 fc rgb '" + colour +
                 "' fs transparent solid 0.12 noborder\n";
      shading += "set arrow from " + gp_num(slack) + ", graph 0 to " + gp_num(slack) +
                 ", graph 1 nohead dt 2 lc rgb '" + colour + "'\n";
    }
    const std::string who = sc.muscles[m].actuator;
    plots += (plots.empty() ? "" : ", ") + gp_quote(name) +
             " using 1:2 with lines lw 1.5 lc rgb '" + colour + "' title " +
             gp_quote("model, " + who) + ", " + gp_quote(name) +
             " using 1:3 with lines dt 2 lc rgb '" + colour + "' title " +
             gp_quote("fiber sensor, " + who);
  }
  job.script = "set title " +
               gp_quote(
                   "Reaching task: length estimation error (Fig. 7); shaded: "
                   "after the line's slack episode") +
               "\nset grid\nset key outside bottom center horizontal\nset xlabel 'time (s)'\n"
               "set ylabel 'error (% of length)'\n" +
               shading + "plot " + plots + "\n";
  if (draw) run_gnuplot((fs::path(out_dir) / "fig7.png").string(), job);
  write_file_atomically((fs::path(out_dir) / "table5.csv").string(), table5_csv(result));
  write_file_atomically((fs::path(out_dir) / "table5.md").string(), table5_markdown(result, spec));
}

}  // namespace pamsim
