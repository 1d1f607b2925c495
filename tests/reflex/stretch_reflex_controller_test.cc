// stretch_reflex_controller_test.cc: the StretchReflexController end to end behind a
// SensorSuite on synthetic truth of the Table IV arm, one control tick as the co-simulation
// loop does it (truth -> readings -> controller): a stretch ramp triggers the agonist reflex
// with either sensor, quiet noisy samples do not, the pressure low-pass removes mistrips at
// high noise, determinism per seed, the reflex switched off (by configuration or by
// ControlInput) holds the schedule, latch mode; pairs by index (unpaired muscles, two
// independent pairs, trigger times per muscle); a bad-value test for every validated key.
#include "reflex/stretch_reflex_controller.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "../sensing/sensing_test_util.h"

#include "base/input_error.h"
#include "pam_actuator/spring_model.h"
#include "reflex/controller.h"
#include "reflex/pass_through_controller.h"
#include "sensing/sensing.h"
#include "base/control_step.h"
#include "base/no_value.h"

namespace pamsim {
namespace {

using pamsim_test::kControlDt;

using test::expect_bad_value;
using test::table_iv_agonist;
using test::table_iv_antagonist;
constexpr double kRampV_m_s = 0.150;   // the stretch of the ramps below

// Everything a harness is built from. Defaults: the falling-mass operating point (DESIGN.md),
// both muscles at 0.4 MPa and scheduled at 0.4 MPa, agonist d = 6.66 mm, antagonist
// d = 1.0 mm; one pair {0, 1}; default sensors and Table II's model-based reflex.
struct Rig {
  std::vector<MuscleSensorSpec> muscles = {table_iv_agonist(), table_iv_antagonist()};
  std::vector<double> d_m = {6.66e-3, 1.0e-3};
  std::vector<double> p_pa = {0.4e6, 0.4e6};      // true chamber pressures
  std::vector<double> p_tp_pa = {0.4e6, 0.4e6};   // scheduled commands
  SensingConfig sensing;
  StretchReflexControllerConfig controller;
  std::uint64_t seed = 7;
};

// The default Rig with Table II's reflex for `sensor`
Rig table_ii_rig(ReflexSensor sensor) {
  Rig rig;
  rig.controller.reflex = table_ii_reflex_config(sensor);
  return rig;
}

// Rig plus a third muscle (an agonist, stretched like the first) in no pair, scheduled at
// p_tp_pa
Rig with_spare_muscle(double p_tp_pa) {
  Rig rig;
  rig.muscles.push_back(table_iv_agonist("muscles.spare"));
  rig.d_m.push_back(6.66e-3);
  rig.p_pa.push_back(0.4e6);
  rig.p_tp_pa.push_back(p_tp_pa);
  rig.controller.muscle_count = 3;
  return rig;
}

// Rig with 4 muscles in two pairs, interleaved so that a partner is never the next index:
// muscles [agonist A, agonist B, antagonist A, antagonist B], pairs {0, 2} and {1, 3}.
Rig two_pairs() {
  Rig rig;
  rig.muscles = {table_iv_agonist("muscles.ago_a"), table_iv_agonist("muscles.ago_b"),
               table_iv_antagonist("muscles.anta_a"), table_iv_antagonist("muscles.anta_b")};
  rig.d_m = {6.66e-3, 6.66e-3, 1.0e-3, 1.0e-3};
  rig.p_pa = {0.4e6, 0.4e6, 0.4e6, 0.4e6};
  rig.p_tp_pa = {0.4e6, 0.4e6, 0.4e6, 0.4e6};
  rig.controller.muscle_count = 4;
  rig.controller.pairs = {ReflexPair{0, 2}, ReflexPair{1, 3}};
  return rig;
}

// The co-simulation loop in miniature: owns the sensing and the controller and moves the
// synthetic plant (tests change rig.d_m and rig.p_tp_pa between ticks). sim.control_hz is
// one key, given to the sensing and the controller alike; reflex.lowpass_hz is the sensing's.
struct Harness {
  explicit Harness(const Rig& from)
      : rig(from),
        sensing(sensing_config(from), from.muscles, from.seed),
        controller(from.controller) {}

  static SensingConfig sensing_config(const Rig& rig) {
    SensingConfig config = rig.sensing;
    config.control_hz = rig.controller.control_hz;
    return config;
  }

  int muscle_count() const { return static_cast<int>(rig.muscles.size()); }

  std::vector<MuscleTruth> truth() const {
    std::vector<MuscleTruth> t(rig.muscles.size());
    for (std::size_t j = 0; j < t.size(); ++j) {
      const SpringModel& spring = rig.muscles[j].estimator;
      t[j].pressure_pa = rig.p_pa[j];
      t[j].force_n = spring_force(spring, rig.p_pa[j], rig.d_m[j]);
      t[j].length_m = natural_length(spring, rig.p_pa[j]) + rig.d_m[j];
    }
    return t;
  }

  // One control tick at t = (ticks so far) * dt: truth -> readings -> controller. The
  // output starts as NaN / 2 so that an element the controller leaves unwritten shows.
  const ControlOutput& tick(bool enabled = true) {
    const double time_s =
        static_cast<double>(outputs.size()) / controller.config().control_hz;
    std::vector<MuscleReading> readings(muscle_count());
    sensing.sample(truth(), &readings);
    ControlOutput out;
    out.resize(muscle_count());
    std::fill(out.p_cmd_pa.begin(), out.p_cmd_pa.end(), kNaN);
    std::fill(out.velocity_m_s.begin(), out.velocity_m_s.end(), kNaN);
    std::fill(out.reflex_active.begin(), out.reflex_active.end(), 2);
    ControlInput in;
    in.time_s = time_s;
    in.enabled = enabled;
    in.readings = &readings;
    in.p_tp_pa = &rig.p_tp_pa;
    controller.update(in, &out);
    reading_log.push_back(readings);
    outputs.push_back(out);
    return outputs.back();
  }

  Rig rig;     // the plant's state and the schedule, moved by the tests
  SensorSuite sensing;
  StretchReflexController controller;
  std::vector<std::vector<MuscleReading>> reading_log;   // per tick
  std::vector<ControlOutput> outputs;                     // per tick
};

// stretch `muscle` at 150 mm/s for 5 ticks, from tick `first` on (the tick is run after
// the move, so `first` is the first tick that reads the stretch); `shortened`, if >= 0, is
// shortened alike down to 5 mm of slack
void stretch_at(Harness* h, int tick, int first, int muscle, int shortened = -1) {
  if (tick < first || tick >= first + 5) return;
  h->rig.d_m[muscle] += kRampV_m_s * kControlDt;
  if (shortened >= 0) {
    h->rig.d_m[shortened] = std::max(h->rig.d_m[shortened] - kRampV_m_s * kControlDt, -5e-3);
  }
}

// the old falling-mass ramp: quiet for 1 s, then the agonist stretched (antagonist
// shortened) at 150 mm/s for 50 ms from tick 101; 200 ticks in all
void run_ramp(Harness* h, bool enabled = true) {
  for (int j = 0; j < 200; ++j) {
    stretch_at(h, j, 101, 0, 1);
    h->tick(enabled);
  }
}

int active_ticks(const Harness& h, int muscle) {
  int n = 0;
  for (const ControlOutput& o : h.outputs) n += o.reflex_active[muscle];
  return n;
}

TEST(StretchReflexController, StretchRampTriggersAgonistReflex) {
  for (ReflexSensor sensor : {ReflexSensor::kModel, ReflexSensor::kFiber}) {
    SCOPED_TRACE(to_string(sensor));
    Rig rig = table_ii_rig(sensor);
    Harness h(rig);
    run_ramp(&h);
    EXPECT_EQ(h.controller.trigger_count(0), 1);
    EXPECT_EQ(h.controller.trigger_count(1), 0);
    // the first stretched tick (t = 1.01 s) exceeds the threshold
    EXPECT_NEAR(h.controller.first_trigger_time_s(), 1.01, 1e-9);
    const ControlOutput& during = h.outputs[102];
    EXPECT_EQ(during.reflex_active[0], 1);
    EXPECT_EQ(during.reflex_active[1], 0);
    // agonist up by k v, antagonist down by k v (v ~ 150 mm/s), within [0, p_max]
    // (the fiber gain 1/300 asks for 0.5 MPa: both commands hit the valve's range)
    const double k_v = std::min(rig.controller.reflex.k_pa_s_per_m * 0.150, 0.4e6);
    EXPECT_NEAR(during.p_cmd_pa[0] - 0.4e6, k_v, 0.15 * k_v);
    EXPECT_NEAR(0.4e6 - during.p_cmd_pa[1], k_v, 0.15 * k_v);
    // follow mode: back to the goal once the stretch stops, inside the window
    EXPECT_NEAR(h.outputs[110].p_cmd_pa[0], 0.4e6, 0.02e6);
    EXPECT_EQ(h.outputs[110].reflex_active[0], 1);
    // the window is 20 ticks
    EXPECT_EQ(active_ticks(h, 0), 20);
    EXPECT_EQ(active_ticks(h, 1), 0);
    // before and well after: the goal pressures
    EXPECT_EQ(h.outputs[50].p_cmd_pa[0], 0.4e6);
    EXPECT_EQ(h.outputs[150].p_cmd_pa[1], 0.4e6);
  }
}

TEST(StretchReflexController, ActsOnTheConfiguredSensorsVelocity) {
  // velocity_m_s is the reading the reflex used: Eq. (11)'s estimate or the fiber rate
  for (ReflexSensor sensor : {ReflexSensor::kModel, ReflexSensor::kFiber}) {
    SCOPED_TRACE(to_string(sensor));
    Rig rig = table_ii_rig(sensor);
    Harness h(rig);
    run_ramp(&h);
    for (std::size_t tick = 0; tick < h.outputs.size(); ++tick) {
      for (int j = 0; j < 2; ++j) {
        const MuscleReading& r = h.reading_log[tick][j];
        const double v = sensor == ReflexSensor::kFiber ? r.fiber_velocity_m_s
                                                        : r.velocity_est_m_s;
        EXPECT_EQ(h.outputs[tick].velocity_m_s[j], v) << tick;
      }
    }
    // the two sensors disagree by their noise, so the choice is visible
    EXPECT_NE(h.reading_log[50][0].fiber_velocity_m_s, h.reading_log[50][0].velocity_est_m_s);
  }
}

TEST(StretchReflexController, QuietNoisySamplesNeverTripAtDefaults) {
  // 10 s at 100 Hz, static arm, default noise and filters, several seeds, both sensors
  for (ReflexSensor sensor : {ReflexSensor::kModel, ReflexSensor::kFiber}) {
    double max_v = 0.0;
    for (std::uint64_t seed = 1; seed <= 5; ++seed) {
      Rig rig = table_ii_rig(sensor);
      rig.seed = seed;
      Harness h(rig);
      for (int j = 0; j < 1000; ++j) {
        const ControlOutput& out = h.tick();
        for (int m = 0; m < 2; ++m) max_v = std::max(max_v, out.velocity_m_s[m]);
      }
      EXPECT_EQ(h.controller.trigger_count(0), 0) << to_string(sensor) << " " << seed;
      EXPECT_EQ(h.controller.trigger_count(1), 0) << to_string(sensor) << " " << seed;
      EXPECT_TRUE(std::isnan(h.controller.first_trigger_time_s()));
    }
    // a margin, not just luck: the largest stretch velocity stays well under threshold
    const double v_thr = table_ii_reflex_config(sensor).v_thr_m_s;
    EXPECT_LT(max_v, 0.6 * v_thr) << to_string(sensor) << " max v " << max_v;
  }
}

TEST(StretchReflexController, PressureLowpassRemovesMistripsAtHighNoise) {
  // DESIGN.md: at 0.003 MPa / 0.5 N the unfiltered model-based velocity mistrips the 70 mm/s
  // threshold most quiet seconds; a 5 Hz low-pass on the measured pressure removes it
  auto trips = [](double pressure_lowpass_hz) {
    int count = 0;
    for (std::uint64_t seed = 1; seed <= 3; ++seed) {
      Rig rig;
      rig.sensing.sensors.pressure_noise_pa = 0.003e6;   // 0.003 MPa
      rig.sensing.sensors.gauge_noise_v = 0.5 * rig.muscles[0].gauge.q_v_per_n;
      rig.sensing.sensors.pressure_lowpass_hz = pressure_lowpass_hz;
      rig.controller.reflex.refractory_s = 0.0;
      rig.seed = seed;
      Harness h(rig);
      for (int j = 0; j < 1000; ++j) h.tick();
      count += h.controller.trigger_count(0) + h.controller.trigger_count(1);
    }
    return count;
  };
  EXPECT_GT(trips(0.0), 10);
  EXPECT_EQ(trips(5.0), 0);
}

TEST(StretchReflexController, DeterministicPerSeed) {
  // commands, velocities and windows over the ramp, default noise
  auto trace = [](std::uint64_t seed) {
    Rig rig;
    rig.seed = seed;
    Harness h(rig);
    run_ramp(&h);
    std::vector<double> out;
    for (const ControlOutput& o : h.outputs) {
      for (int j = 0; j < 2; ++j) {
        out.push_back(o.p_cmd_pa[j]);
        out.push_back(o.velocity_m_s[j]);
        out.push_back(o.reflex_active[j]);
      }
    }
    return out;
  };
  EXPECT_EQ(trace(99), trace(99));
  EXPECT_NE(trace(99), trace(100));
}

TEST(StretchReflexController, WritesEveryOutputElement) {
  // the harness fills the output with NaN / 2 before each update; three muscles, the third
  // unpaired, with the controller on and off
  Rig rig = with_spare_muscle(0.3e6);
  Harness h(rig);
  for (int j = 0; j < 40; ++j) {
    const ControlOutput& out = h.tick(/*enabled=*/j % 2 == 0);
    for (int m = 0; m < 3; ++m) {
      EXPECT_TRUE(std::isfinite(out.p_cmd_pa[m])) << j << " " << m;
      EXPECT_TRUE(std::isfinite(out.velocity_m_s[m])) << j << " " << m;
      EXPECT_TRUE(out.reflex_active[m] == 0 || out.reflex_active[m] == 1) << j << " " << m;
    }
  }
}

TEST(StretchReflexController, DisabledReflexHoldsScheduledPressures) {
  Rig rig;
  rig.controller.reflex.enabled = false;
  rig.p_tp_pa = {0.45e6, 0.35e6};
  Harness h(rig);
  run_ramp(&h);
  EXPECT_EQ(h.controller.trigger_count(0), 0);
  EXPECT_EQ(h.controller.trigger_count(1), 0);
  for (const ControlOutput& o : h.outputs) {
    EXPECT_EQ(o.p_cmd_pa[0], 0.45e6);
    EXPECT_EQ(o.p_cmd_pa[1], 0.35e6);
    EXPECT_EQ(o.reflex_active[0], 0);
    EXPECT_EQ(o.reflex_active[1], 0);
  }
  // the stretch was there to be seen: the velocity it would have acted on
  EXPECT_GT(h.outputs[102].velocity_m_s[0], 0.1);
}

TEST(StretchReflexController, DisabledReflexMatchesPassThrough) {
  // an independent equivalent: controller "none" commands the schedule and logs the
  // model-based estimate, as a disabled model-based reflex does
  Rig rig;
  rig.controller.reflex.enabled = false;
  rig.p_tp_pa = {0.45e6, 0.35e6};
  Harness h(rig);
  run_ramp(&h);
  PassThroughController none;
  EXPECT_EQ(none.trigger_times_s(), nullptr);
  for (std::size_t tick = 0; tick < h.outputs.size(); ++tick) {
    ControlInput in;
    in.time_s = tick * kControlDt;
    in.readings = &h.reading_log[tick];
    in.p_tp_pa = &rig.p_tp_pa;
    ControlOutput expected;
    expected.resize(2);
    none.update(in, &expected);
    EXPECT_EQ(h.outputs[tick].p_cmd_pa, expected.p_cmd_pa) << tick;
    EXPECT_EQ(h.outputs[tick].velocity_m_s, expected.velocity_m_s) << tick;
    EXPECT_EQ(h.outputs[tick].reflex_active, expected.reflex_active) << tick;
  }
}

TEST(StretchReflexController, SwitchedOffControllerHoldsScheduleAndOpensNoWindow) {
  // ControlInput.enabled = false (an event switched the controller off) through the ramp
  Rig rig;
  rig.p_tp_pa = {0.45e6, 0.35e6};
  Harness h(rig);
  run_ramp(&h, /*enabled=*/false);
  EXPECT_EQ(h.controller.trigger_count(0), 0);
  EXPECT_EQ(h.controller.trigger_count(1), 0);
  EXPECT_TRUE(std::isnan(h.controller.first_trigger_time_s()));
  for (const ControlOutput& o : h.outputs) {
    EXPECT_EQ(o.p_cmd_pa[0], 0.45e6);
    EXPECT_EQ(o.p_cmd_pa[1], 0.35e6);
    EXPECT_EQ(o.reflex_active[0], 0);
    EXPECT_EQ(o.reflex_active[1], 0);
  }
  // switched on again, the same controller does trigger on the next stretch
  for (int j = 200; j < 260; ++j) {
    stretch_at(&h, j, 231, 0);
    h.tick();
  }
  EXPECT_EQ(h.controller.trigger_count(0), 1);
  EXPECT_NEAR(h.controller.first_trigger_time_s(), 2.31, 1e-9);
  EXPECT_GT(h.outputs[232].p_cmd_pa[0], 0.45e6 + 0.1e6);
}

TEST(StretchReflexController, LatchModeHoldsTheTriggerCommand) {
  Rig rig;
  rig.controller.reflex.mode = ReflexMode::kLatch;
  rig.sensing.sensors.pressure_noise_pa = 0.0;
  rig.sensing.sensors.gauge_noise_v = 0.0;
  Harness h(rig);
  run_ramp(&h);
  // the ramp stops at tick 105; latched, the command stays up until tick 120
  EXPECT_NEAR(h.outputs[101].p_cmd_pa[0], h.outputs[119].p_cmd_pa[0], 1e-6);
  EXPECT_GT(h.outputs[119].p_cmd_pa[0], 0.5e6);
  EXPECT_EQ(h.outputs[121].p_cmd_pa[0], 0.4e6);
}

TEST(StretchReflexController, SlackMuscleDoesNotTriggerBelowMinTension) {
  // The antagonist hangs 5 mm slack while its pressure drops 20 kPa per tick for 5 ticks:
  // its natural length grows at 70.3 mm/MPa * 2 MPa/s = 141 mm/s, which both sensors read
  // as stretch (the model estimate is l_n(p) when slack, Fig. 7). The gauge reads no
  // tension (noise-free, ideal converter), so reflex.min_tension_N = 1 N holds the reflex
  // back; 0 disables the gate.
  for (ReflexSensor sensor : {ReflexSensor::kModel, ReflexSensor::kFiber}) {
    for (double min_tension_n : {1.0, 0.0}) {
      SCOPED_TRACE(std::string(to_string(sensor)) + " min_tension_N " +
                   std::to_string(min_tension_n));
      Rig rig = table_ii_rig(sensor);
      rig.controller.reflex.min_tension_n = min_tension_n;
      rig.sensing.sensors.gauge_noise_v = 0.0;
      rig.sensing.sensors.gauge_adc_bits = 0;
      rig.d_m[1] = -5e-3;
      Harness h(rig);
      for (int j = 0; j < 200; ++j) {
        if (j >= 101 && j < 106) h.rig.p_pa[1] -= 20e3;
        h.tick();
      }
      EXPECT_GT(h.outputs[102].velocity_m_s[1], 0.1);
      EXPECT_EQ(h.controller.trigger_count(1), min_tension_n > 0.0 ? 0 : 1);
      EXPECT_EQ(h.controller.trigger_count(0), 0);
    }
  }
}

TEST(StretchReflexController, UnpairedMuscleGetsItsClampedScheduleAndNeverTriggers) {
  // three muscles, pair {0, 1}; muscle 2 is in no pair. Its schedule goes below 0 and
  // above p_max, and it is stretched at twice the ramp speed while the pair's reflex fires.
  Rig rig = with_spare_muscle(0.0);
  Harness h(rig);
  for (int j = 0; j < 200; ++j) {
    h.rig.p_tp_pa[2] = j < 50 ? -0.1e6 : j < 150 ? 0.3e6 + 1e3 * j : 1.0e6;
    stretch_at(&h, j, 101, 0, 1);
    stretch_at(&h, j, 101, 2);
    stretch_at(&h, j, 101, 2);
    const ControlOutput& out = h.tick();
    EXPECT_EQ(out.p_cmd_pa[2], std::clamp(h.rig.p_tp_pa[2], 0.0, 0.8e6)) << j;
    EXPECT_EQ(out.reflex_active[2], 0) << j;
  }
  EXPECT_EQ(h.controller.trigger_count(2), 0);
  EXPECT_TRUE((*h.controller.trigger_times_s())[2].empty());
  // the pair did fire, and muscle 2's stretch was read (and logged) as such
  EXPECT_EQ(h.controller.trigger_count(0), 1);
  EXPECT_GT(h.outputs[102].velocity_m_s[2], 0.25);
  EXPECT_EQ(h.outputs[10].p_cmd_pa[2], 0.0);
  EXPECT_EQ(h.outputs[199].p_cmd_pa[2], 0.8e6);
}

TEST(StretchReflexController, TwoPairsAreIndependent) {
  // pairs {0, 2} and {1, 3} (two_pairs()); stretch pair 0's agonist
  Harness h(two_pairs());
  for (int j = 0; j < 200; ++j) {
    stretch_at(&h, j, 101, 0);
    h.tick();
  }
  EXPECT_EQ(h.controller.trigger_count(0), 1);
  for (int m : {1, 2, 3}) EXPECT_EQ(h.controller.trigger_count(m), 0) << m;
  // its own antagonist (muscle 2) is inhibited, the other pair is untouched
  const ControlOutput& during = h.outputs[102];
  const double k_v = 150.0 / 800.0 * 1e6;
  EXPECT_NEAR(during.p_cmd_pa[0] - 0.4e6, k_v, 0.15 * k_v);
  EXPECT_NEAR(0.4e6 - during.p_cmd_pa[2], k_v, 0.15 * k_v);
  EXPECT_EQ(active_ticks(h, 0), 20);
  for (const ControlOutput& o : h.outputs) {
    EXPECT_EQ(o.p_cmd_pa[1], 0.4e6);
    EXPECT_EQ(o.p_cmd_pa[3], 0.4e6);
    EXPECT_EQ(o.reflex_active[1] + o.reflex_active[2] + o.reflex_active[3], 0);
  }
}

TEST(StretchReflexController, ReciprocalTriggerGateActsWithinAPairOnly) {
  // pair 0's agonist fires at tick 101 (window to tick 120); at tick 110 pair 0's
  // antagonist (muscle 2) and pair 1's agonist (muscle 1) are stretched alike: the open
  // window silences its partner only
  for (bool gate : {true, false}) {
    SCOPED_TRACE(gate ? "gate on" : "gate off");
    Rig rig = two_pairs();
    rig.controller.reflex.reciprocal_trigger_inhibition = gate;
    Harness h(rig);
    for (int j = 0; j < 200; ++j) {
      stretch_at(&h, j, 101, 0);
      stretch_at(&h, j, 110, 1);
      stretch_at(&h, j, 110, 2);
      h.tick();
    }
    EXPECT_EQ(h.controller.trigger_count(0), 1);
    EXPECT_EQ(h.controller.trigger_count(1), 1);
    EXPECT_NEAR((*h.controller.trigger_times_s())[1].at(0), 1.10, 1e-9);
    EXPECT_EQ(h.controller.trigger_count(2), gate ? 0 : 1);
    EXPECT_EQ(h.controller.trigger_count(3), 0);
  }
}

// A window open when an event switches the controller off runs out on time: off for ticks
// 105-109 of the 20-tick window that opened at tick 101, it closes after tick 120 as it
// would have (not 5 ticks later), and acts only while the controller is on.
TEST(StretchReflexController, AWindowRunsOutWhileTheControllerIsOff) {
  Harness h{Rig{}};
  for (int j = 0; j < 140; ++j) {
    stretch_at(&h, j, 101, 0, 1);
    h.tick(!(j >= 105 && j < 110));
  }
  ASSERT_EQ(h.controller.trigger_count(0), 1);
  for (int j = 101; j < 140; ++j) {
    const int expected = (j < 105 || (j >= 110 && j <= 120)) ? 1 : 0;
    EXPECT_EQ(h.outputs[j].reflex_active[0], expected) << "tick " << j;
  }
  EXPECT_EQ(h.outputs[107].p_cmd_pa[0], 0.4e6) << "off: the schedule";
}

// reflex.min_tension_N = 0 switches the tension gate off: a slack line's reading (a gauge
// that reads slightly negative) may trigger; with the 1 N gate it may not.
TEST(StretchReflexController, ZeroMinimumTensionLetsASlackLineTrigger) {
  for (double min_tension : {0.0, 1.0}) {
    StretchReflexControllerConfig config;
    config.reflex.min_tension_n = min_tension;
    StretchReflexController controller(config);
    std::vector<MuscleReading> readings(2);
    readings[0].force_meas_n = -0.3;
    readings[0].velocity_est_m_s = 0.2;   // well above 70 mm/s
    readings[1].force_meas_n = 20.0;
    std::vector<double> p_tp = {0.4e6, 0.4e6};
    ControlInput in;
    in.time_s = 1.0;
    in.readings = &readings;
    in.p_tp_pa = &p_tp;
    ControlOutput out;
    out.resize(2);
    controller.update(in, &out);
    EXPECT_EQ(controller.trigger_count(0), min_tension == 0.0 ? 1 : 0) << min_tension;
  }
}

TEST(StretchReflexController, TriggerTimesPerMuscleAndTheEarliest) {
  // pairs {0, 2} and {1, 3}: muscle 1 fires at 0.51 s, muscle 0 at 1.01 s and again at
  // 1.81 s (after its 0.2 s window and 0.5 s refractory period)
  Harness h(two_pairs());
  const Controller& as_controller = h.controller;
  ASSERT_NE(as_controller.trigger_times_s(), nullptr);
  for (int j = 0; j < 200; ++j) {
    stretch_at(&h, j, 51, 1);
    stretch_at(&h, j, 101, 0);
    stretch_at(&h, j, 181, 0);
    h.tick();
    if (j == 50) {
      EXPECT_TRUE(std::isnan(h.controller.first_trigger_time_s()));
    }
  }
  const std::vector<std::vector<double>>& times = *as_controller.trigger_times_s();
  ASSERT_EQ(times.size(), 4u);
  ASSERT_EQ(times[0].size(), 2u);
  EXPECT_NEAR(times[0][0], 1.01, 1e-9);
  EXPECT_NEAR(times[0][1], 1.81, 1e-9);
  ASSERT_EQ(times[1].size(), 1u);
  EXPECT_NEAR(times[1][0], 0.51, 1e-9);
  EXPECT_TRUE(times[2].empty());
  EXPECT_TRUE(times[3].empty());
  for (int m = 0; m < 4; ++m) {
    EXPECT_EQ(h.controller.trigger_count(m), static_cast<int>(times[m].size())) << m;
  }
  // the earliest of any muscle, not the first muscle's
  EXPECT_NEAR(h.controller.first_trigger_time_s(), 0.51, 1e-9);
}

// --- bad values: every validated key; the message names the key and quotes the value ---

using BadValue = test::BadValueOf<StretchReflexControllerConfig>;

std::vector<BadValue> bad_values() {
  using C = StretchReflexControllerConfig&;
  return {
      {"sim.control_hz", "0", [](C c) { c.control_hz = 0.0; }},
      {"sim.control_hz", "nan", [](C c) { c.control_hz = kNaN; }},
      // an enum outside its names reads as "?"
      {"reflex.sensor", "\"?\"", [](C c) { c.reflex.sensor = static_cast<ReflexSensor>(7); }},
      {"reflex.mode", "\"?\"", [](C c) { c.reflex.mode = static_cast<ReflexMode>(7); }},
      // SI fields, reported in the keys' units
      {"reflex.v_thr_mm_s", "-5", [](C c) { c.reflex.v_thr_m_s = -0.005; }},
      {"reflex.v_thr_mm_s", "0", [](C c) { c.reflex.v_thr_m_s = 0.0; }},
      {"reflex.v_thr_mm_s", "nan", [](C c) { c.reflex.v_thr_m_s = kNaN; }},
      {"reflex.k_MPa_s_per_mm", "-0.001", [](C c) { c.reflex.k_pa_s_per_m = -1e6; }},
      {"reflex.k_MPa_s_per_mm", "nan", [](C c) { c.reflex.k_pa_s_per_m = kNaN; }},
      {"reflex.duration_s", "-0.2", [](C c) { c.reflex.duration_s = -0.2; }},
      {"reflex.duration_s", "0.001", [](C c) { c.reflex.duration_s = 0.001; }},
      {"reflex.duration_s", "nan", [](C c) { c.reflex.duration_s = kNaN; }},
      // one control period is 20 ms at 50 Hz
      {"reflex.duration_s", "0.01", [](C c) { c.control_hz = 50.0; c.reflex.duration_s = 0.01; }},
      {"reflex.refractory_s", "-0.1", [](C c) { c.reflex.refractory_s = -0.1; }},
      {"reflex.refractory_s", "nan", [](C c) { c.reflex.refractory_s = kNaN; }},
      {"reflex.refractory_s", "1e+10", [](C c) { c.reflex.refractory_s = 1e10; }},
      {"reflex.duration_s", "1e+10", [](C c) { c.reflex.duration_s = 1e10; }},
      {"reflex.arm_after_s", "-1", [](C c) { c.reflex.arm_after_s = -1.0; }},
      {"reflex.arm_after_s", "nan", [](C c) { c.reflex.arm_after_s = kNaN; }},
      {"reflex.min_tension_N", "-1", [](C c) { c.reflex.min_tension_n = -1.0; }},
      {"reflex.min_tension_N", "nan", [](C c) { c.reflex.min_tension_n = kNaN; }},
      // in MPa, as in the scenario file
      {"controller.p_max_MPa", "0", [](C c) { c.p_max_pa = 0.0; }},
      {"controller.p_max_MPa", "-0.1", [](C c) { c.p_max_pa = -0.1e6; }},
      {"controller.p_max_MPa", "nan", [](C c) { c.p_max_pa = kNaN; }},
      // reflex.pairs: an index out of range
      {"reflex.pairs[0]", "-1", [](C c) { c.pairs = {ReflexPair{-1, 1}}; }},
      {"reflex.pairs[0]", "2", [](C c) { c.pairs = {ReflexPair{0, 2}}; }},
      {"reflex.pairs[0]", "0", [](C c) { c.muscle_count = 0; }},
      {"reflex.pairs[1]", "4",
       [](C c) { c.muscle_count = 4; c.pairs = {ReflexPair{0, 1}, ReflexPair{4, 2}}; }},
      // a muscle in two pairs, as agonist or antagonist
      {"reflex.pairs[1]", "1",
       [](C c) { c.muscle_count = 4; c.pairs = {ReflexPair{0, 1}, ReflexPair{1, 2}}; }},
      {"reflex.pairs[1]", "0",
       [](C c) { c.muscle_count = 4; c.pairs = {ReflexPair{0, 1}, ReflexPair{2, 0}}; }},
      // a muscle paired with itself
      {"reflex.pairs[0]", "1", [](C c) { c.pairs = {ReflexPair{1, 1}}; }},
  };
}

TEST(StretchReflexControllerConfig, DefaultsAreValid) {
  StretchReflexControllerConfig config;
  EXPECT_NO_THROW(validate(config));
  config.reflex = table_ii_reflex_config(ReflexSensor::kFiber);
  EXPECT_NO_THROW(validate(config));
  // no pair at all; two pairs of four; a pair that skips a muscle
  config.pairs.clear();
  EXPECT_NO_THROW(validate(config));
  EXPECT_NO_THROW(validate(two_pairs().controller));
  config.muscle_count = 3;
  config.pairs = {ReflexPair{2, 0}};
  EXPECT_NO_THROW(validate(config));
}

TEST(StretchReflexControllerConfig, EveryBadValueThrowsNamingTheKeyAndValue) {
  for (const BadValue& bad : bad_values()) {
    SCOPED_TRACE(bad.key + " = " + bad.value);
    StretchReflexControllerConfig config;
    bad.set(config);
    expect_bad_value([&] { validate(config); }, bad.key, bad.value);
    // the constructor validates too
    expect_bad_value([&] { StretchReflexController{config}; }, bad.key, bad.value);
  }
}

TEST(StretchReflexControllerConfig, MessagesSayWhatIsAllowed) {
  auto message = [](const std::function<void(StretchReflexControllerConfig&)>& set) {
    StretchReflexControllerConfig config;
    set(config);
    try {
      validate(config);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("no throw");
  };
  using C = StretchReflexControllerConfig&;
  EXPECT_EQ(message([](C c) { c.reflex.v_thr_m_s = -0.005; }),
            "reflex.v_thr_mm_s must be in (0, inf), got -5");
  EXPECT_EQ(message([](C c) { c.reflex.duration_s = 0.001; }),
            "reflex.duration_s must be >= one control period (0.01 s), got 0.001");
  EXPECT_EQ(message([](C c) { c.pairs = {ReflexPair{0, 2}}; }),
            "reflex.pairs[0] must be a muscle index in [0, 2), got 2");
  EXPECT_EQ(message([](C c) { c.muscle_count = 3; c.pairs = {{0, 1}, {2, 1}}; }),
            "reflex.pairs[1] must be muscles not already in a pair (muscle index), got 1");
}

TEST(ReflexSensor, ParsesAndRejectsNamingTheKey) {
  EXPECT_EQ(parse_reflex_sensor("model"), ReflexSensor::kModel);
  EXPECT_EQ(parse_reflex_sensor("fiber"), ReflexSensor::kFiber);
  for (ReflexSensor sensor : {ReflexSensor::kModel, ReflexSensor::kFiber}) {
    EXPECT_EQ(parse_reflex_sensor(to_string(sensor)), sensor);
  }
  for (const char* bad : {"fibre", "", "Model"}) {
    try {
      parse_reflex_sensor(bad);
      ADD_FAILURE() << "no throw for " << bad;
    } catch (const InputError& e) {
      EXPECT_EQ(std::string(e.what()),
                std::string("reflex.sensor must be \"model\" or \"fiber\", got \"") + bad +
                    "\"");
    }
  }
}

TEST(ReflexSensor, TableIiThresholdsAndGains) {
  const ReflexConfig model = table_ii_reflex_config(ReflexSensor::kModel);
  EXPECT_EQ(model.sensor, ReflexSensor::kModel);
  EXPECT_DOUBLE_EQ(model.v_thr_m_s, 70.0e-3);            // 70 mm/s
  EXPECT_DOUBLE_EQ(model.k_pa_s_per_m, 1e6 / 800.0 / 1e-3);   // 1/800 MPa per mm/s
  const ReflexConfig fiber = table_ii_reflex_config(ReflexSensor::kFiber);
  EXPECT_EQ(fiber.sensor, ReflexSensor::kFiber);
  EXPECT_DOUBLE_EQ(fiber.v_thr_m_s, 25.0e-3);
  EXPECT_DOUBLE_EQ(fiber.k_pa_s_per_m, 1e6 / 300.0 / 1e-3);
  // the other fields keep their defaults
  EXPECT_DOUBLE_EQ(fiber.duration_s, ReflexConfig{}.duration_s);
  EXPECT_EQ(fiber.enabled, ReflexConfig{}.enabled);
}

}  // namespace
}  // namespace pamsim
