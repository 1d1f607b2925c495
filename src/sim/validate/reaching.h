// reaching.h: the papers' reaching-task validation (Yoshida and Hosoda, Sec. II-C, III-C,
// IV-B, Table V, Fig. 7): the arm's reaching scenario repeated over seeds; the model-based
// length estimate (Eq. (9)-(10)) and the fiber sensor against the encoder, per muscle, over
// a window (the ramps) and before / after the muscle's slack episode. The protocol is a file
// (scenarios/validate_reaching.toml; its keys at load_reaching_validation). The fiber sensor
// reads only the rate of length change: its length is the rate integrated from the encoder's
// length at the window's start (the paper calibrated it so).
#pragma once

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "sim/core/scenario.h"
#include "sim/core/trial.h"
#include "sim/validate/bands.h"
#include "sim/validate/error_budget.h"
#include "sim/validate/validation_options.h"

namespace pamsim {

struct ReachingValidationSpec {
  std::string file;
  std::string scenario_file;
  int trials = 5;
  double window_start_s = 0.0, window_end_s = 0.0;
  double min_slack_s = 0.1;
  std::map<std::string, ErrorPct> paper;  // "model_agonist", "fiber_antagonist_after_slack"
  std::vector<BudgetSource> budget;       // [[budget_source]]
  std::vector<Bracket> brackets;          // [[bracket]]: the rig's unsized parts (bands.h)
  std::uint64_t bracket_seed = 1;
};

// The protocol file's keys, paths relative to it:
//   scenario      the reaching scenario, required (per muscle: length_<m>_mm, the encoder;
//                 length_est_<m>_mm; fiber_rate_<m>_mm_s; force_<m>_N, the line's tension)
//   trials        repetitions, seeds seed .. seed + trials - 1, in [1, 1000]; default 5
//   window_s      [start, end] of the comparison [s], 0 <= start < end
//   min_slack_s   a slack episode starts where a line that was taut inside the window has
//                 zero tension for at least this long [s], > 0; default 0.1. "Before" is
//                 from the line's first taut sample in the window to the episode, "after"
//                 from the episode to the window's end; a trial without an episode adds to
//                 neither (only to "all")
//   [paper]       <method>_<muscle>[_before_slack|_after_slack] = [max, RMSE] (% of
//                 length), method "model" or "fiber", muscle the scenario's muscle name
//   [[budget_source]] the hardware's error sources for --budget (error_budget.h)
//   [[bracket]], bracket_seed  the rig's unsized parts for --bands, --sensitivity (bands.h)
//   base          another protocol file this one changes (reaching_protocol.cc): every key
//                 from it, this file's replacing them, a [[budget_source]] or [[bracket]] of
//                 the same name in place; then scenario is optional
// Throws InputError "<file>: <key> <problem>". `protocol_overrides` ("key=value" of the
// protocol file's own keys) are applied first.
ReachingValidationSpec load_reaching_validation(
    const std::string& path, const std::vector<std::string>& protocol_overrides = {});

// One line of Table V: a method on a muscle over a part of the window, pooled over trials
// (max of |error|, RMSE of every finite sample).
struct ReachingRow {
  std::string muscle;  // the scenario's muscle (actuator) name
  std::string label;   // its column label ("ago")
  std::string method;  // "model" | "fiber"
  std::string part;    // "all" | "before_slack" | "after_slack"
  ErrorPct sim;
  int samples = 0;
  std::optional<ErrorPct> paper;
};

struct ReachingValidationResult {
  Scenario scenario;
  std::vector<TrialResult> trials;
  // per muscle (the scenario's order), per trial: the slack episode's start [s], or NaN, and
  // its cause ("slack": the line; "gauge": the line pulls and its gauge reads nothing; "")
  std::vector<std::vector<double>> slack_start_s;
  std::vector<std::vector<std::string>> episode_cause;
  std::vector<ReachingRow> rows;
};

// Runs the trials on `options.threads` threads (options.seed: the first seed) and computes
// the rows. Throws InputError for bad overrides, a scenario whose log lacks a needed
// column, or a window outside its duration.
ReachingValidationResult run_reaching_validation(const ReachingValidationSpec& spec,
                                                 const ValidationOptions& options);

// The first slack episode of a muscle in one trajectory: the time [s] at which a line that
// was taut inside [start, end] sends no signal for min_slack_s, or NaN. No signal, as the
// paper saw it ("slackness and failure to send voltage signals", Sec. IV-B): the line at
// zero tension (cause "slack"), or pulling at least kPulledN while its gauge's force
// (force_meas_<label>_N, where logged) reads under kReadN (cause "gauge": the line has left
// the board, gauge_contact.h).
struct SlackEpisode {
  double start_s;
  std::string cause;  // "slack" | "gauge" | "" (none)
};
inline constexpr double kPulledN = 5.0;  // 20 sigma of the gauge's noise on the agonist
inline constexpr double kReadN = 1.0;
SlackEpisode first_slack_episode(const Trajectory& trajectory, const std::string& label,
                                 double start_s, double end_s, double min_slack_s);
double slack_episode_start(const Trajectory& trajectory, const std::string& label, double start_s,
                           double end_s, double min_slack_s);

// out_dir/table5.csv (muscle, method, part, samples, max_error_pct, rmse_pct,
// paper_max_error_pct, paper_rmse_pct, slack_start_s and episode_cause: the first trial's),
// out_dir/table5.md
// (Table V's layout, the paper's values beside) and out_dir/fig7.png (the first trial's
// errors over time, slack episodes shaded; not without `draw`). Each file whole or not at all.
void write_reaching_validation(const ReachingValidationResult& result,
                               const ReachingValidationSpec& spec, const std::string& out_dir,
                               bool draw = true);

std::string table5_csv(const ReachingValidationResult& result);
std::string table5_markdown(const ReachingValidationResult& result,
                            const ReachingValidationSpec& spec);

}  // namespace pamsim
