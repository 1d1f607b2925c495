// spring_model_bench.cc: nanoseconds per spring-model inversion (length estimation),
// Eq. (3) closed form and the Eq. (4) / (5) cubic, over varied (p, f) inputs.
#include <benchmark/benchmark.h>

#include <array>
#include <vector>

#include "pam_actuator/spring_model.h"

namespace pamsim {
namespace {

constexpr int kInputs = 1024;

// (p, f) pairs spread over the working range, forces produced by the law itself
struct Inputs {
  std::vector<double> p_pa, f_n;
};

Inputs make_inputs(const SpringModel& model) {
  Inputs in;
  for (int k = 0; k < kInputs; ++k) {
    const double p = 1e5 + 7e5 * ((k * 37) % kInputs) / kInputs;          // 0.1-0.8 MPa
    const double d = 0.5e-3 + 29.5e-3 * ((k * 101) % kInputs) / kInputs;  // 0.5-30 mm
    in.p_pa.push_back(p);
    in.f_n.push_back(spring_force(model, p, d));
  }
  return in;
}

SpringModel table4_agonist() {
  return spring_model_from_paper_units(SpringLaw::kEq3, -60.1, 170.1,
                                       {0.911, 0.256, 7.00, -0.201, 0.0, 0.0});
}

// Eq. (4) with the Table IV terms plus small p^2 and d^2 terms (a genuine cubic)
SpringModel eq4_model() {
  return spring_model_from_paper_units(SpringLaw::kEq4, -60.1, 170.1,
                                       {0.911, 0.256, 7.00, 0.002, -0.201, 1.5});
}

SpringModel eq5_model() {
  return spring_model_from_paper_units(SpringLaw::kEq5, -60.1, 170.1,
                                       {3.0, 0.005, 0.01, 0.5, 10.0, 0.0});
}

void run(benchmark::State& state, const SpringModel& model) {
  const Inputs in = make_inputs(model);
  int k = 0;
  for (auto _ : state) {
    DeformationEstimate e = invert_spring_model(model, in.p_pa[k], in.f_n[k]);
    benchmark::DoNotOptimize(e);
    k = (k + 1) & (kInputs - 1);
  }
  state.SetItemsProcessed(state.iterations());
}

void BM_InvertEq3(benchmark::State& state) { run(state, table4_agonist()); }
void BM_InvertEq4(benchmark::State& state) { run(state, eq4_model()); }
void BM_InvertEq5(benchmark::State& state) { run(state, eq5_model()); }
BENCHMARK(BM_InvertEq3);
BENCHMARK(BM_InvertEq4);
BENCHMARK(BM_InvertEq5);

}  // namespace
}  // namespace pamsim
