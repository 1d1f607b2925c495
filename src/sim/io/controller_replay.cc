// controller_replay.cc: the embedded controller over a logged stream of its inputs.
#include "sim/io/controller_replay.h"

#include <cmath>

#include "base/format.h"
#include "base/input_error.h"
#include "base/units.h"
#include "sim/io/gnuplot.h"

namespace pamsim {
namespace controller_replay_rows {

void write_header(const std::vector<std::string>& muscles, std::ostream* csv) {
  *csv << "time_s";
  for (const std::string& m : muscles) {
    *csv << ",p_cmd_" << m << "_MPa,length_est_" << m << "_mm,velocity_" << m << "_mm_s"
         << ",force_meas_" << m << "_N,reflex_" << m << ",tension_reflex_" << m << ",flags_" << m;
  }
  *csv << "\n";
}

void write_row(double time_s, const pamctl_output& out, int n, std::ostream* csv) {
  *csv << format_shortest(time_s);
  for (int j = 0; j < n; ++j) {
    const pamctl_estimate& e = out.estimates[j];
    *csv << "," << format_shortest(units::pa_to_mpa(out.p_cmd_pa[j])) << ","
         << format_shortest(units::m_to_mm(e.length_m)) << ","
         << format_shortest(units::m_to_mm(out.velocity_m_s[j])) << ","
         << format_shortest(e.force_n) << "," << (out.ia_active[j] ? 1 : 0) << ","
         << (out.ib_active[j] ? 1 : 0) << "," << e.flags;
  }
  *csv << "\n";
}

// the library's commands against the log's at one tick
void compare(const pamctl_output& out, const ControlStream& stream, std::size_t tick,
             const std::vector<std::string>& muscles, ReplayComparison* c) {
  for (std::size_t j = 0; j < muscles.size(); ++j) {
    const double logged = stream.muscles[j].p_cmd_pa[tick];
    const double diff = std::fabs(out.p_cmd_pa[j] - logged);
    const bool differs = !(out.p_cmd_pa[j] == logged);
    if (differs && c->first_differing_tick < 0) {
      c->first_differing_tick = static_cast<long>(tick);
      c->first_differing_time_s = stream.time_s[tick];
    }
    if (differs && !(diff <= c->largest_difference_pa)) {
      c->largest_difference_pa = diff;
      c->largest_muscle = muscles[j];
    }
  }
}

}  // namespace controller_replay_rows

using namespace controller_replay_rows;

void check_control_rate(const ControlStream& stream, double period_s, const std::string& path) {
  for (std::size_t k = 1; k < stream.time_s.size(); ++k) {
    const double step = stream.time_s[k] - stream.time_s[k - 1];
    if (std::fabs(step - period_s) <= 1e-6 * period_s) continue;
    throw InputError(path + ": line " + std::to_string(k + 2) + ": time_s steps " +
                     format_value(step) + " s from the line before, the control period is " +
                     format_value(period_s) +
                     " s (another rate, or a gap): resample the log "
                     "to the controller's rate");
  }
}

ReplaySummary replay_controller(const pamctl_config& config,
                                const std::vector<std::string>& muscles,
                                const ControlStream& stream, std::ostream* csv) {
  pamctl_state state{};
  pamctl_reset(&config, &state);
  pamctl_input in{};
  pamctl_output out{};
  const int n = config.muscle_count;
  ReplaySummary summary;
  summary.stretch_triggers_s.resize(n);
  summary.tension_triggers_s.resize(n);
  summary.comparison.compared = n > 0;
  for (const MuscleStream& m : stream.muscles) summary.comparison.compared &= !m.p_cmd_pa.empty();
  write_header(muscles, csv);
  for (std::size_t k = 0; k < stream.time_s.size(); ++k) {
    // the tick's inputs, the library, its outputs
    in.time_s = stream.time_s[k];
    in.enabled = stream.enabled[k] != 0;
    for (int j = 0; j < n; ++j) {
      const MuscleStream& m = stream.muscles[j];
      in.pressure_v[j] = m.pressure_v[k];
      in.gauge_v[j] = m.gauge_v[k];
      in.fiber_rate_m_s[j] = m.fiber_rate_m_s[k];
      in.p_tp_pa[j] = m.p_tp_pa[k];
    }
    pamctl_tick(&config, &state, &in, &out);
    write_row(in.time_s, out, n, csv);
    for (int j = 0; j < n; ++j) {
      if (out.ia_triggered[j]) summary.stretch_triggers_s[j].push_back(in.time_s);
      if (out.ib_triggered[j]) summary.tension_triggers_s[j].push_back(in.time_s);
    }
    summary.status |= out.status;
    if (out.status != 0) ++summary.flagged_ticks;
    if (summary.comparison.compared) compare(out, stream, k, muscles, &summary.comparison);
    ++summary.ticks;
  }
  return summary;
}

void write_replay_plot(const std::string& png_path, const std::string& csv,
                       const pamctl_config& config, const std::vector<std::string>& muscles,
                       const ControlStream& stream) {
  // the replay's rows as they are, and the log's commands beside them (MPa)
  GnuplotJob job;
  job.data_files.push_back({"replay.csv", csv});
  std::string logged;
  for (std::size_t k = 0;
       k < stream.time_s.size() && !stream.muscles.empty() && !stream.muscles[0].p_cmd_pa.empty();
       ++k) {
    logged += gp_num(stream.time_s[k]);
    for (const MuscleStream& m : stream.muscles) {
      logged += "," + gp_num(units::pa_to_mpa(m.p_cmd_pa[k]));
    }
    logged += "\n";
  }
  if (!logged.empty()) job.data_files.push_back({"logged.dat", logged});
  // top: commands; bottom: velocity, threshold, windows
  std::string top = "plot ", bottom = "plot ";
  for (std::size_t j = 0; j < muscles.size(); ++j) {
    const std::string col = std::to_string(2 + 7 * j);
    top += std::string(j ? ", " : "") + "'replay.csv' every ::1 using 1:" + col +
           " with lines lw 2 title " + gp_quote(muscles[j] + " (library)");
    if (!logged.empty()) {
      top += ", 'logged.dat' using 1:" + std::to_string(2 + j) + " with lines dt 2 title " +
             gp_quote(muscles[j] + " (log)");
    }
    bottom += std::string(j ? ", " : "") +
              "'replay.csv' every ::1 using 1:" + std::to_string(4 + 7 * j) + " with lines title " +
              gp_quote(muscles[j]) + ", 'replay.csv' every ::1 using 1:($" +
              std::to_string(6 + 7 * j) + "*50) with steps lt 0 notitle";
  }
  const double v_thr_mm_s = units::m_to_mm(config.reflex.ia.v_thr_m_s);
  if (config.kind == PAMCTL_KIND_REFLEX) {
    bottom += ", " + gp_num(v_thr_mm_s) + " with lines dt 3 title 'v_{thr}'";
  }
  job.script =
      "set datafile separator ','\nset multiplot layout 2,1\nset grid\n"
      "set ylabel 'command [MPa]'\nunset xlabel\n" +
      top + "\n" + "set ylabel 'velocity [mm/s] (windows: steps)'\nset xlabel 'time [s]'\n" +
      bottom + "\nunset multiplot\n";
  run_gnuplot(png_path, job);
}

}  // namespace pamsim
