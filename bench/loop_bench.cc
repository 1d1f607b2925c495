// loop_bench.cc: cost of the co-simulation loop against bare MuJoCo, on the 3 s drop-mass
// trial (3000 physics steps of 1 ms), all in one run so the ratios are meaningful:
//   BM_BareMjStep           mj_step alone on the same arm (the PAM force callback included,
//                           pressures fixed at 0.4 MPa, the ball held until 1 s then dropped)
//   BM_AffineActuatorMjStep the same loop with each PAM MuJoCo's own affine actuator (its
//                           force linearised at the start): the floor, no callback
//   BM_PamForceCallback     the force callback alone (ns per call) on the arm's AVBDL agonist,
//                           the pressure moved each call so no memo answers it
//   BM_TrialLoop/passive    run_trial: + CVODE pneumatics, sensors, controller and logging
//   BM_TrialLoop/reflex     the same with the stretch reflex on (/reflex_ideal on the
//                           ideal plant; /reflex_maxwell_slip and /reflex_nylon_lines with
//                           Maxwell-slip braid friction or nylon lines, Hardware below)
//   BM_TwentyTrials         run_trials(20) wall time on 1 and 2 threads (CPU column: all
//                           threads of the process, so CPU / (threads * Time) is the
//                           share of the cores the workers got)
// and the same for the PAM leg's 1.5 s landing (eight muscles, 1500 steps):
//   BM_LegBareMjStep, BM_TrialLoop/landing (no reflex), BM_TrialLoop/landing_reflex,
//   BM_TwentyLandings
// Counters: s_per_step (seconds per physics step, SI-prefixed: "4.1u" = 4.1 us) and
// items_per_second (physics steps per second); for the trial loop also CVODE steps and
// right-hand-side evaluations per physics step; trials_per_s for the batch.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "sim/core/pam_callback.h"
#include "sim/core/runner.h"
#include "sim/scenario/scenario_file.h"
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
      : sc(scenario_named(file)),
        tm(load_trial_model(sc)),
        m(tm.model.get()),
        data(make_data(m)),
        d(data.get()),
        n_steps(std::lround(sc.duration_s / sc.timestep_s)) {}
  Scenario sc;
  TrialModel tm;
  const mjModel* m;
  MjDataPtr data;
  mjData* d;
  long n_steps;
};

// The drop-mass trial's physics alone on model `m` (the arm's or a variant of it): the
// calibrated angle, fixed pressures, the ball held above the basket until the release, then
// dropped into it; the run skipped with an error if it diverged or missed the basket.
void drop_loop(benchmark::State& state, const BareLoop& loop, const mjModel* m) {
  const Scenario& sc = loop.sc;
  const TrialModel& arm = loop.tm;
  mjData* d = loop.d;
  const BoundHold& ball = arm.holds.at(0);
  const double drop_time_s = sc.event("release")->when.at_s;
  const int basket = mj_name2id(m, mjOBJ_BODY, "basket");
  for (auto _ : state) {
    mj_resetData(m, d);
    d->qpos[arm.joint.qpos] = sc.start_position;
    for (std::size_t i = 0; i < arm.muscles.size(); ++i) d->userdata[i] = kFixedPressurePa;
    mj_forward(m, d);
    const double* floor = d->site_xpos + 3 * ball.site;
    const double hold_pos[3] = {floor[0], floor[1],
                                floor[2] + sc.holds.at(0).height_m + ball.radius_m};
    for (long step = 0; step < loop.n_steps; ++step) {
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
  report_steps(state, loop.n_steps);
}

void BM_BareMjStep(benchmark::State& state) {
  BareLoop loop("drop_mass.toml");
  drop_loop(state, loop, loop.m);
}
BENCHMARK(BM_BareMjStep)->Unit(benchmark::kMillisecond);

// The bare loop's floor: each PAM actuator replaced by MuJoCo's own affine bias, its force
// linearised about the start state (F0 + k (L - L0), k = dF/dL there), so mj_step calls no
// user callback while the arm, held by springs of the muscles' stiffness, moves much as it
// does with them (the ball is dropped the same way, so the contacts are alike).
void BM_AffineActuatorMjStep(benchmark::State& state) {
  BareLoop loop("drop_mass.toml");
  const TrialModel& arm = loop.tm;
  MjModelPtr copy(mj_copyModel(nullptr, loop.m));
  mjModel* m = copy.get();
  mjData* d = loop.d;
  const auto start = [&](double offset_rad) {
    mj_resetData(loop.m, d);
    d->qpos[arm.joint.qpos] = loop.sc.start_position + offset_rad;
    for (std::size_t i = 0; i < arm.muscles.size(); ++i) d->userdata[i] = kFixedPressurePa;
    mj_forward(loop.m, d);
  };
  std::vector<double> force_lo, length_lo;
  start(-1e-3);
  for (const BoundMuscle& b : arm.muscles) {
    force_lo.push_back(d->actuator_force[b.actuator]);
    length_lo.push_back(d->actuator_length[b.actuator]);
  }
  start(0.0);
  for (std::size_t i = 0; i < arm.muscles.size(); ++i) {
    const int a = arm.muscles[i].actuator;
    const double f0 = d->actuator_force[a], l0 = d->actuator_length[a];
    const double k = (f0 - force_lo[i]) / (l0 - length_lo[i]);
    m->actuator_biastype[a] = mjBIAS_AFFINE;
    mjtNum* bias = m->actuator_biasprm + static_cast<long>(a) * mjNBIAS;
    std::fill(bias, bias + mjNBIAS, 0.0);
    bias[0] = f0 - k * l0;
    bias[1] = k;
  }
  drop_loop(state, loop, m);
}
BENCHMARK(BM_AffineActuatorMjStep)->Unit(benchmark::kMillisecond);

// The PAM force callback alone, on the drop-mass arm's agonist (the AVBDL plant with its
// friction) at the start state; the chamber pressure steps by 1 Pa each call so that every
// call computes the law (a physics step calls it once per muscle).
void BM_PamForceCallback(benchmark::State& state) {
  BareLoop loop("drop_mass.toml");
  const TrialModel& arm = loop.tm;
  mjData* d = loop.d;
  arm.place_at_start(loop.sc, d);
  for (std::size_t i = 0; i < arm.muscles.size(); ++i) d->userdata[i] = kFixedPressurePa;
  mj_forward(loop.m, d);
  const int agonist = arm.muscles.at(0).actuator;
  long call = 0;
  for (auto _ : state) {
    d->userdata[0] = kFixedPressurePa + static_cast<double>(call++ % 1000);
    benchmark::DoNotOptimize(pam_actuator_force(loop.m, d, agonist));
  }
  if (!(pam_actuator_force(loop.m, d, agonist) < 0.0)) {
    state.SkipWithError("the agonist pulls nothing at the start state");
  }
}
BENCHMARK(BM_PamForceCallback)->Unit(benchmark::kNanosecond);

// Variants of a scenario's hardware: none, the plants' braid friction as
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
  b->ArgName("threads")->Arg(1)->Arg(2)->MeasureProcessCPUTime()->UseRealTime()->Unit(
      benchmark::kMillisecond);
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
