// pneumatics_bench.cc: cost of the valve + chamber pneumatics per 1 ms physics step for two
// muscles (set_kinematics x2 + advance(t + 1 ms), a new command every 10 ms as from the
// 100 Hz controller, lengths oscillating at 3 Hz as in a moving arm). Counters give CVODE
// steps and right-hand-side evaluations per physics step.
// Args: valve model (0 iso6358, 1 first_order), command policy (0 warm, 1 reinit),
// -log10(rtol). BM_RegulatorLoopStep: the "regulator" valve model at the shipped rtol 1e-4,
// args feedback (0 instant, 1 delayed: a sample every 1 ms acting 5 ms later), sense
// (0 chamber, 1 outlet: a third state per muscle) and command policy (0 warm, 1 reinit);
// (0, 0, 1) is the regulator without its loop's delay or outlet sensing.
#include <benchmark/benchmark.h>

#include <cmath>
#include <memory>

#include "pneumatics/pneumatics.h"
#include "base/units.h"

namespace {

using pamsim::PneumaticParams;
using pamsim::PneumaticSystem;

// one physics step per iteration: a 100 Hz command, lengths at 3 Hz; reports CVODE's work
void run_steps(benchmark::State& state, PneumaticSystem* sys) {
  const double dt = 1e-3;
  const double w = 2.0 * pamsim::units::kPi * 3.0;
  long k = 0;
  const long steps0 = sys->steps();
  const long rhs0 = sys->rhs_evals();
  for (auto _ : state) {
    const double t = sys->time_s();
    // 100 Hz controller: reflex-like command changes
    if (k % 10 == 0) {
      const double u = 0.15e6 * std::sin(2.0 * pamsim::units::kPi * 1.0 * t);
      sys->set_command(0, 0.4e6 + u);
      sys->set_command(1, 0.4e6 - u);
    }
    // arm motion from the physics engine
    const double s = std::sin(w * t);
    const double c = std::cos(w * t);
    sys->set_kinematics(0, 0.165 + 0.005 * s, 0.005 * w * c);
    sys->set_kinematics(1, 0.165 - 0.005 * s, -0.005 * w * c);
    sys->advance(t + dt);
    benchmark::DoNotOptimize(sys->pressure_pa(0));
    ++k;
  }
  state.counters["cvode_steps_per_step"] =
      static_cast<double>(sys->steps() - steps0) / static_cast<double>(k);
  state.counters["rhs_evals_per_step"] =
      static_cast<double>(sys->rhs_evals() - rhs0) / static_cast<double>(k);
}

std::unique_ptr<PneumaticSystem> two_muscles(const PneumaticParams& params,
                                             pamsim::ValveModel model) {
  const pamsim::BraidGeometry braid =
      pamsim::braid_from_initial_shape(0.18, 0.016, pamsim::units::deg_to_rad(25.0));
  return std::make_unique<PneumaticSystem>(params, model,
                                           std::vector<pamsim::BraidGeometry>{braid, braid},
                                           std::vector<double>{0.4e6, 0.4e6});
}

pamsim::CommandChangePolicy policy(long arg) {
  return arg == 0 ? pamsim::CommandChangePolicy::kWarm : pamsim::CommandChangePolicy::kReinit;
}

void BM_PneumaticsStep(benchmark::State& state) {
  PneumaticParams params;
  const auto model =
      state.range(0) == 0 ? pamsim::ValveModel::kIso6358 : pamsim::ValveModel::kFirstOrder;
  params.solver.on_command_change = policy(state.range(1));
  params.solver.relative_tolerance = std::pow(10.0, -static_cast<double>(state.range(2)));
  auto sys = two_muscles(params, model);
  run_steps(state, sys.get());
}

void BM_RegulatorLoopStep(benchmark::State& state) {
  PneumaticParams params;
  if (state.range(0) == 1) {
    params.regulator_feedback = pamsim::RegulatorFeedback::kDelayed;
    params.regulator_proportional_band_pa = 300e3;  // stable with the delay (pneumatics.toml)
  }
  if (state.range(1) == 1) params.regulator_sense = pamsim::RegulatorSense::kOutlet;
  params.solver.on_command_change = policy(state.range(2));
  auto sys = two_muscles(params, pamsim::ValveModel::kRegulator);
  run_steps(state, sys.get());
}

BENCHMARK(BM_PneumaticsStep)
    ->ArgNames({"first_order", "reinit", "rtol_exp"})
    ->Args({0, 0, 6})
    ->Args({0, 1, 6})
    ->Args({0, 0, 5})
    ->Args({0, 1, 5})
    ->Args({0, 0, 4})
    ->Args({0, 1, 4})
    ->Args({1, 0, 5})
    ->Args({1, 1, 5})
    ->Unit(benchmark::kNanosecond);

BENCHMARK(BM_RegulatorLoopStep)
    ->ArgNames({"delayed", "outlet", "reinit"})
    ->Args({0, 0, 1})
    ->Args({0, 1, 1})
    ->Args({1, 0, 1})
    ->Args({1, 1, 1})
    ->Args({0, 0, 0})
    ->Args({1, 1, 0})
    ->Unit(benchmark::kNanosecond);

}  // namespace
