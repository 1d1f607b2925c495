// pamctl_bench.cc: nanoseconds per control tick of the embedded controller
// (src/embedded/pamctl.h), the code a board runs, in one run:
//   BM_PamctlTick/2   the drop-mass arm's model reflex (2 muscles, Eq. (3) estimators)
//   BM_PamctlTick/8   the PAM leg's landing with reflexes (8 muscles)
// each fed its own trial's logged readings (pamsim run --readings), tick after tick, looping
// (the state reset at the log's end), so the estimator and the reflexes see real inputs.
#include <benchmark/benchmark.h>

#include <string>
#include <vector>

#include "embedded/pamctl.h"
#include "sim/core/trial.h"
#include "sim/scenario/scenario_file.h"

namespace pamsim {
namespace {

// a shipped scenario's controller as exported, and its trial's inputs per tick
struct LoggedController {
  pamctl_config config{};
  std::vector<pamctl_input> ticks;
};

LoggedController logged_controller(const std::string& name) {
  const Scenario sc = load_scenario(std::string(PAMSIM_SOURCE_DIR) + "/scenarios/" + name);
  const TrialModel model = load_trial_model(sc);
  LoggedController c;
  embedded_controller_config(model, sc, &c.config);
  ControlLog log;
  TrialOptions options;
  options.control_log = &log;
  run_trial(model, sc, sc.seed, options);
  // the log's rows as the library's inputs
  const std::size_t width = ControlLog::kPerTick + ControlLog::kPerMuscle * log.muscle_count;
  for (std::size_t k = 0; k < log.ticks(); ++k) {
    const double* row = log.values.data() + k * width;
    pamctl_input in{};
    in.time_s = row[0];
    in.enabled = row[1] != 0.0;
    for (int j = 0; j < log.muscle_count; ++j) {
      const double* m = row + ControlLog::kPerTick + ControlLog::kPerMuscle * j;
      in.pressure_v[j] = m[0];
      in.gauge_v[j] = m[1];
      in.fiber_rate_m_s[j] = m[2];
      in.p_tp_pa[j] = m[3];
    }
    c.ticks.push_back(in);
  }
  return c;
}

void BM_PamctlTick(benchmark::State& state) {
  static const LoggedController arm = logged_controller("drop_mass.toml");
  static const LoggedController leg = logged_controller("landing_reflex.toml");
  const LoggedController& c = state.range(0) == 2 ? arm : leg;
  pamctl_state s{};
  pamctl_output out{};
  pamctl_init(&c.config, &s);
  std::size_t k = 0;
  for (auto _ : state) {
    pamctl_tick(&c.config, &s, &c.ticks[k], &out);
    benchmark::DoNotOptimize(out.p_cmd_pa[0]);
    if (++k == c.ticks.size()) {
      k = 0;
      pamctl_reset(&c.config, &s);
    }
  }
  state.counters["muscles"] = c.config.muscle_count;
}
BENCHMARK(BM_PamctlTick)->Arg(2)->Arg(8);

}  // namespace
}  // namespace pamsim
