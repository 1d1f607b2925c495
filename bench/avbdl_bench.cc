// avbdl_bench.cc: nanoseconds per call of the physical plant law (Pipan et al.'s AVBDL with
// braid friction, avbdl.h) against the spring law of an ideal plant (Eq. (3),
// spring_model.h): what a physical plant costs the co-simulation per force evaluation.
#include <benchmark/benchmark.h>

#include <string>
#include <vector>

#include "pam_actuator/avbdl.h"
#include "pam_actuator/pam_params.h"
#include "pam_actuator/plant_params.h"
#include "pam_actuator/spring_model.h"

namespace pamsim {
namespace {

constexpr int kInputs = 1024;

// (p, L, dL/dt) spread over the arm's working range: 0.1-0.7 MPa, 135-175 mm, +-100 mm/s
struct State {
  double p_pa, length_m, rate_m_s;
};

std::vector<State> make_inputs() {
  std::vector<State> in;
  for (int k = 0; k < kInputs; ++k) {
    in.push_back({1e5 + 6e5 * ((k * 37) % kInputs) / kInputs,
                  0.135 + 0.040 * ((k * 101) % kInputs) / kInputs,
                  -0.1 + 0.2 * ((k * 13) % kInputs) / kInputs});
  }
  return in;
}

void BM_AvbdlForce(benchmark::State& state) {
  const AvbdlParams plant =
      load_plant_params(std::string(PAMSIM_SOURCE_DIR) + "/models/pams/plant_agonist.toml").avbdl;
  const std::vector<State> in = make_inputs();
  int k = 0;
  for (auto _ : state) {
    const State& s = in[k];
    benchmark::DoNotOptimize(avbdl_force(plant, s.p_pa, s.length_m, s.rate_m_s));
    k = (k + 1) & (kInputs - 1);
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_AvbdlForce);

void BM_SpringForceEq3(benchmark::State& state) {
  const SpringModel law =
      load_pam_params(std::string(PAMSIM_SOURCE_DIR) + "/models/pams/table4_agonist.toml").spring;
  const std::vector<State> in = make_inputs();
  int k = 0;
  for (auto _ : state) {
    const State& s = in[k];
    const double d = s.length_m - natural_length(law, s.p_pa);
    benchmark::DoNotOptimize(d > 0.0 ? spring_force(law, s.p_pa, d) : 0.0);
    k = (k + 1) & (kInputs - 1);
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_SpringForceEq3);

}  // namespace
}  // namespace pamsim
