// loop_bench.cc: cost of the co-simulation loop against bare MuJoCo, on the 3 s drop-mass
// trial (3000 physics steps of 1 ms), all in one run so the ratios are meaningful:
//   BM_BareMjStep           mj_step alone on the same arm (the PAM force callback included,
//                           pressures fixed at 0.4 MPa, the ball held until 1 s then dropped)
//   BM_TrialLoop/passive    run_trial: + CVODE pneumatics, sensors, controller and logging
//   BM_TrialLoop/reflex     the same with the stretch reflex on (/reflex_ideal on the
//                           ideal plant; /reflex_maxwell_slip and /reflex_nylon_lines with
//                           the hardware models of issue 25 on)
//   BM_TwentyTrials         run_trials(20) wall time on 1 and 2 threads (CPU column: all
//                           threads of the process, so CPU / (threads * Time) is the
//                           share of the cores the workers got)
// and the same for the PAM leg's 1.5 s landing (issue 27; eight muscles, 1500 steps):
//   BM_LegBareMjStep, BM_TrialLoop/landing (no reflex), BM_TrialLoop/landing_reflex,
//   BM_TwentyLandings
// Counters: s_per_step (seconds per physics step, SI-prefixed: "4.1u" = 4.1 us) and
// items_per_second (physics steps per second); for the trial loop also CVODE steps and
// right-hand-side evaluations per physics step; trials_per_s for the batch.
#include <benchmark/benchmark.h>

#include <cmath>
#include <string>

#include "sim/core/pam_callback.h"
#include "sim/core/runner.h"
#include "sim/io/scenario_file.h"
#include "sim/core/trial.h"

namespace pamsim {
namespace {

constexpr double kFixedPressurePa = 0.4e6;
constexpr int kBatchTrials = 20;

Scenario scenario_named(const std::string& file) {
  return load_scenario(std::string(PAMSIM_SOURCE_DIR) + "/scenarios/" + file);
}

// seconds per physics step from the benchmark's time (CPU or real, as the benchmark uses)
void report_steps(benchmark::State& state, long steps_per_iteration) {
  const double steps = static_cast<double>(steps_per_iteration);
  state.counters["s_per_step"] = benchmark::Counter(
      steps, benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
  state.SetItemsProcessed(state.iterations() * steps_per_iteration);
}


// the ball held at rest at `pos`, as the trial's hold does it (trial.cc)
void hold_at(const BoundHold& hold, mjData* d, const double pos[3]) {
  double* q = d->qpos + hold.qpos;
  q[0] = pos[0];
  q[1] = pos[1];
  q[2] = pos[2];
  q[3] = 1.0;
  q[4] = q[5] = q[6] = 0.0;
  for (int k = 0; k < 6; ++k) d->qvel[hold.dof + k] = 0.0;
}

bool bodies_touch(const mjModel* m, const mjData* d, int a, int b) {
  for (int i = 0; i < d->ncon; ++i) {
    const int b1 = m->geom_bodyid[d->contact[i].geom1], b2 = m->geom_bodyid[d->contact[i].geom2];
    if ((b1 == a && b2 == b) || (b1 == b && b2 == a)) return true;
  }
  return false;
}

// A scenario's trial model with data of its own, for mj_step alone over its duration
struct BareLoop {
  explicit BareLoop(const char* file)
      : sc(scenario_named(file)), tm(load_trial_model(sc)), m(tm.model.get()),
        data(make_data(m)), d(data.get()), n_steps(std::lround(sc.duration_s / sc.timestep_s)) {}
  Scenario sc;
  TrialModel tm;
  const mjModel* m;
  MjDataPtr data;
  mjData* d;
  long n_steps;
};

void BM_BareMjStep(benchmark::State& state) {
  BareLoop loop("drop_mass.toml");
  const Scenario& sc = loop.sc;
  const TrialModel& arm = loop.tm;
  const mjModel* m = loop.m;
  mjData* d = loop.d;
  const long n_steps = loop.n_steps;
  const BoundHold& ball = arm.holds.at(0);
  const double drop_time_s = sc.event("release")->when.at_s;
  const int basket = mj_name2id(m, mjOBJ_BODY, "basket");

  for (auto _ : state) {
    // the trial's initial state: calibrated angle, fixed pressures, ball above the basket
    mj_resetData(m, d);
    d->qpos[arm.joint.qpos] = sc.start_position;
    for (std::size_t i = 0; i < arm.muscles.size(); ++i) d->userdata[i] = kFixedPressurePa;
    mj_forward(m, d);
    const double* floor = d->site_xpos + 3 * ball.site;
    const double hold_pos[3] = {floor[0], floor[1],
                                floor[2] + sc.holds.at(0).height_m + ball.radius_m};

    // hold until the release, then let the ball fall into the basket
    for (long step = 0; step < n_steps; ++step) {
      const double t = step * sc.timestep_s;
      if (!(t >= drop_time_s - 1e-12)) hold_at(ball, d, hold_pos);
      mj_step(m, d);
    }
    benchmark::DoNotOptimize(d->qpos[arm.joint.qpos]);
  }
  if (!std::isfinite(d->qpos[arm.joint.qpos]) || d->warning[mjWARN_BADQACC].number > 0) {
    state.SkipWithError("bare mj_step loop diverged");
  } else if (!bodies_touch(m, d, ball.body, basket)) {
    state.SkipWithError("bare mj_step loop: the ball did not land in the basket");
  }
  report_steps(state, n_steps);
}
BENCHMARK(BM_BareMjStep)->Unit(benchmark::kMillisecond);

// Variants of a scenario's hardware (issue 25): none, the plants' braid friction as
// Maxwell-slip elements (travels 0.1 and 0.5 mm), 0.5 mm nylon lines (E 2.5 GPa), the
// gauge board held still, or every instrument ideal (the shipped ones are hardware).
enum class Hardware { kShipped, kMaxwellSlip, kNylonLines, kStillBoard, kIdealInstruments };

void change_hardware(Hardware hardware, Scenario* sc) {
  SensorConfig& s = sc->sensing.sensors;
  if (hardware == Hardware::kStillBoard) s.gauge_hardware.vibration.enabled = false;
  if (hardware == Hardware::kIdealInstruments) {
    s.gauge_hardware.enabled = false;
    s.pressure_hardware.enabled = false;
    s.fiber_hardware.enabled = false;
    s.encoder.enabled = false;
  }
  const double line_radius_m = 0.25e-3, nylon_modulus_pa = 2.5e9;
  for (MuscleSpec& m : sc->muscles) {
    if (hardware == Hardware::kNylonLines) {
      m.line_axial_stiffness_n = nylon_modulus_pa * M_PI * line_radius_m * line_radius_m;
    }
    if (hardware != Hardware::kMaxwellSlip || m.plant_file.empty()) continue;
    m.plant.friction.model = FrictionModel::kMaxwellSlip;
    m.plant.friction.slip.count = 2;
    m.plant.friction.slip.weight = {0.5, 0.5};
    m.plant.friction.slip.breakaway_m = {0.1e-3, 0.5e-3};
  }
}

void BM_TrialLoop(benchmark::State& state, const char* scenario_file, Hardware hardware) {
  Scenario sc = scenario_named(scenario_file);
  change_hardware(hardware, &sc);
  const TrialModel arm = load_trial_model(sc);
  TrialSummary summary;
  for (auto _ : state) {
    const TrialResult r = run_trial(arm, sc, sc.seed);
    summary = r.summary;
    if (r.summary.status != "ok") {
      state.SkipWithError(("trial " + r.summary.status + ": " + r.summary.message).c_str());
      break;
    }
    benchmark::DoNotOptimize(r.summary.metric("min_angle_deg"));
  }
  const long steps = std::lround(summary.metric("steps"));
  report_steps(state, steps);

  // the pneumatics' share: CVODE work per physics step (compare BM_PneumaticsStep)
  const double per = static_cast<double>(steps > 0 ? steps : 1);
  state.counters["cvode_steps_per_step"] = summary.metric("cvode_steps") / per;
  state.counters["rhs_evals_per_step"] = summary.metric("cvode_rhs_evals") / per;
}
BENCHMARK_CAPTURE(BM_TrialLoop, passive, "drop_mass_passive.toml", Hardware::kShipped)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_TrialLoop, reflex, "drop_mass.toml", Hardware::kShipped)
    ->Unit(benchmark::kMillisecond);
// the same trial on the ideal plant (Table IV's law, ideal regulated source): what the
// physical plant and the regulator's loop cost
BENCHMARK_CAPTURE(BM_TrialLoop, reflex_ideal, "drop_mass_ideal.toml", Hardware::kShipped)
    ->Unit(benchmark::kMillisecond);
// what the hardware models cost when on: the Maxwell-slip state, the extensible line's solve
BENCHMARK_CAPTURE(BM_TrialLoop, reflex_maxwell_slip, "drop_mass.toml", Hardware::kMaxwellSlip)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_TrialLoop, reflex_nylon_lines, "drop_mass.toml", Hardware::kNylonLines)
    ->Unit(benchmark::kMillisecond);
// what the instruments as hardware cost: the board's ringing, and all of them
BENCHMARK_CAPTURE(BM_TrialLoop, reflex_still_board, "drop_mass.toml", Hardware::kStillBoard)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_TrialLoop, reflex_ideal_instruments, "drop_mass.toml",
                  Hardware::kIdealInstruments)
    ->Unit(benchmark::kMillisecond);

// kBatchTrials trials of a scenario on state.range(0) threads
void run_batch(benchmark::State& state, const char* scenario_file) {
  const Scenario sc = scenario_named(scenario_file);
  const TrialModel model = load_trial_model(sc);
  const int threads = static_cast<int>(state.range(0));
  for (auto _ : state) {
    const auto results = run_trials(model, sc, kBatchTrials, threads);
    benchmark::DoNotOptimize(results.data());
  }
  state.counters["trials_per_s"] =
      benchmark::Counter(kBatchTrials, benchmark::Counter::kIsIterationInvariantRate);
}

// a batch on 1 and 2 threads, timed by the wall clock with every thread's CPU time
void batch_settings(benchmark::internal::Benchmark* b) {
  b->ArgName("threads")
      ->Arg(1)
      ->Arg(2)
      ->MeasureProcessCPUTime()
      ->UseRealTime()
      ->Unit(benchmark::kMillisecond);
}

void BM_TwentyTrials(benchmark::State& state) { run_batch(state, "drop_mass.toml"); }
BENCHMARK(BM_TwentyTrials)->Apply(batch_settings);

// The leg's landing model with mj_step alone: its start posture and height, every pressure
// fixed at 0.4 MPa (the PAM force callback included)
void BM_LegBareMjStep(benchmark::State& state) {
  BareLoop loop("landing.toml");
  const TrialModel& leg = loop.tm;
  const mjModel* m = loop.m;
  mjData* d = loop.d;
  const long n_steps = loop.n_steps;
  for (auto _ : state) {
    mj_resetData(m, d);
    leg.place_at_start(loop.sc, d);
    for (std::size_t i = 0; i < leg.muscles.size(); ++i) d->userdata[i] = kFixedPressurePa;
    for (long step = 0; step < n_steps; ++step) mj_step(m, d);
    benchmark::DoNotOptimize(d->qpos[0]);
  }
  if (!std::isfinite(d->qpos[0]) || d->warning[mjWARN_BADQACC].number > 0) {
    state.SkipWithError("bare mj_step loop on the leg diverged");
  }
  report_steps(state, n_steps);
}
BENCHMARK(BM_LegBareMjStep)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_TrialLoop, landing, "landing.toml", Hardware::kShipped)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_TrialLoop, landing_reflex, "landing_reflex.toml", Hardware::kShipped)
    ->Unit(benchmark::kMillisecond);

void BM_TwentyLandings(benchmark::State& state) { run_batch(state, "landing_reflex.toml"); }
BENCHMARK(BM_TwentyLandings)->Apply(batch_settings);

}  // namespace
}  // namespace pamsim
