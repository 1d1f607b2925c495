// pneumatics_bench.cc: cost of the valve + chamber pneumatics per 1 ms physics step for two
// muscles (set_kinematics x2 + advance(t + 1 ms), a new command every 10 ms as from the
// 100 Hz controller, lengths oscillating at 3 Hz as in a moving arm). Counters give CVODE
// steps and right-hand-side evaluations per physics step.
// Args: valve model (0 iso6358, 1 first_order), command policy (0 warm, 1 reinit),
// -log10(rtol).
#include <benchmark/benchmark.h>

#include <cmath>
#include <memory>

#include "pam_actuator/pneumatics.h"
#include "base/units.h"

namespace {

using pamsim::PneumaticParams;
using pamsim::PneumaticSystem;

void BM_PneumaticsStep(benchmark::State& state) {
  PneumaticParams params;
  const auto model = state.range(0) == 0 ? pamsim::ValveModel::kIso6358
                                         : pamsim::ValveModel::kFirstOrder;
  params.solver.on_command_change = state.range(1) == 0 ? pamsim::CommandChangePolicy::kWarm
                                                        : pamsim::CommandChangePolicy::kReinit;
  params.solver.relative_tolerance = std::pow(10.0, -static_cast<double>(state.range(2)));
  const pamsim::BraidGeometry braid =
      pamsim::braid_from_initial_shape(0.18, 0.016, pamsim::units::deg_to_rad(25.0));
  auto sys = std::make_unique<PneumaticSystem>(params, model,
                                               std::vector<pamsim::BraidGeometry>{braid, braid},
                                               std::vector<double>{0.4e6, 0.4e6});
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

}  // namespace
