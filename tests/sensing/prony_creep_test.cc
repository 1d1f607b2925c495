// prony_creep_test.cc: the Prony-series creep (prony_creep.h) against its closed forms: a
// load step creeps as 1 + sum g_i (1 - exp(-t / tau_i)) at every tick, its removal recovers
// as sum g_i (1 - exp(-t1 / tau_i)) exp(-(t - t1) / tau_i), a load held for ever reads the
// long-term factor, no terms means no creep, and every bad value names its key.
#include "sensing/prony_creep.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "base/input_error.h"
#include "base/control_step.h"

namespace pamsim {
namespace {

using pamsim_test::kControlDt;

const std::vector<PronyTerm> kTerms = {{0.02, 1.0}, {0.05, 60.0}, {0.08, 1800.0}};

double creep_after(double t) {
  double out = 1.0;
  for (const PronyTerm& p : kTerms) out += p.weight * (1.0 - std::exp(-t / p.time_s));
  return out;
}

TEST(PronyCreepTest, ALoadStepCreepsAsTheClosedFormAtEveryTick) {
  PronyCreep creep(kTerms, kControlDt);
  for (int k = 1; k <= 60000; ++k) {  // 10 minutes at 100 Hz
    const double out = creep.step(2.0);
    if (k % 997 == 0 || k == 1) {
      ASSERT_NEAR(out, 2.0 * creep_after(k * kControlDt), 1e-12) << "tick " << k;
    }
  }
}

TEST(PronyCreepTest, RemovingTheLoadRecoversAsTheClosedForm) {
  PronyCreep creep(kTerms, kControlDt);
  const int loaded = 30000;  // 300 s under load
  for (int k = 0; k < loaded; ++k) creep.step(1.0);
  const double t1 = loaded * kControlDt;
  for (int k = 1; k <= 30000; ++k) {
    const double out = creep.step(0.0);
    if (k % 1009 == 0 || k == 1) {
      double expected = 0.0;
      for (const PronyTerm& p : kTerms) {
        expected +=
            p.weight * (1.0 - std::exp(-t1 / p.time_s)) * std::exp(-k * kControlDt / p.time_s);
      }
      ASSERT_NEAR(out, expected, 1e-12) << "tick " << k;
    }
  }
}

TEST(PronyCreepTest, AHeldLoadTendsToTheLongTermFactorAndNoTermsMeansNoCreep) {
  PronyCreep creep(kTerms, 10.0);
  double out = 0.0;
  for (int k = 0; k < 10000; ++k) out = creep.step(1.0);  // 28 h: every tau long past
  EXPECT_NEAR(out, creep.long_term_factor(), 1e-12);
  EXPECT_DOUBLE_EQ(creep.long_term_factor(), 1.15);
  PronyCreep elastic({}, kControlDt);
  EXPECT_EQ(elastic.step(3.5), 3.5);
  EXPECT_EQ(elastic.long_term_factor(), 1.0);
}

TEST(PronyCreepTest, EveryBadValueNamesItsKey) {
  struct Case {
    PronyTerm term;
    const char* key;
  };
  for (const Case& c :
       {Case{{-0.01, 1.0}, "creep_weights"}, Case{{std::nan(""), 1.0}, "creep_weights"},
        Case{{0.1, 0.0}, "creep_times_s"}, Case{{0.1, -5.0}, "creep_times_s"},
        Case{{0.1, INFINITY}, "creep_times_s"}}) {
    try {
      validate_prony({{0.1, 1.0}, c.term}, "creep_weights", "creep_times_s");
      ADD_FAILURE() << "no throw for " << c.key;
    } catch (const InputError& e) {
      const std::string what = e.what();
      EXPECT_EQ(what.rfind(std::string(c.key) + "[1] must be ", 0), 0u) << what;
    }
  }
  EXPECT_NO_THROW(validate_prony(kTerms, "creep_weights", "creep_times_s"));
}

}  // namespace
}  // namespace pamsim
