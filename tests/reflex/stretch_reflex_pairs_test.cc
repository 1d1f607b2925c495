// stretch_reflex_pairs_test.cc: the StretchReflexController's gates and pairs
// (stretch_reflex_harness.h): latch mode, a slack muscle below the minimum tension, pairs by
// index (unpaired muscles, two independent pairs, the reciprocal trigger gate within a pair),
// a window running out while the controller is off, trigger times per muscle.
#include "stretch_reflex_harness.h"

namespace pamsim {
namespace {

using namespace reflex_test;  // Rig, Harness and the ramps

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
    EXPECT_EQ(out.channels[kWindow][2], 0) << j;
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
    EXPECT_EQ(o.channels[kWindow][1] + o.channels[kWindow][2] + o.channels[kWindow][3], 0);
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
    EXPECT_EQ(h.outputs[j].channels[kWindow][0], expected) << "tick " << j;
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
    readings[0].velocity_est_m_s = 0.2;  // well above 70 mm/s
    readings[1].force_meas_n = 20.0;
    std::vector<double> p_tp = {0.4e6, 0.4e6};
    ControlInput in;
    in.time_s = 1.0;
    in.readings = &readings;
    in.p_tp_pa = &p_tp;
    ControlOutput out;
    out.resize(2, 1);
    controller.update(in, &out);
    EXPECT_EQ(controller.trigger_count(0), min_tension == 0.0 ? 1 : 0) << min_tension;
  }
}

TEST(StretchReflexController, TriggerTimesPerMuscleAndTheEarliest) {
  // pairs {0, 2} and {1, 3}: muscle 1 fires at 0.51 s, muscle 0 at 1.01 s and again at
  // 1.81 s (after its 0.2 s window and 0.5 s refractory period)
  Harness h(two_pairs());
  const Controller& as_controller = h.controller;
  ASSERT_EQ(as_controller.event_times_s().size(), 1u);  // stretch_trigger
  for (int j = 0; j < 200; ++j) {
    stretch_at(&h, j, 51, 1);
    stretch_at(&h, j, 101, 0);
    stretch_at(&h, j, 181, 0);
    h.tick();
    if (j == 50) {
      EXPECT_TRUE(std::isnan(h.controller.first_trigger_time_s()));
    }
  }
  const std::vector<std::vector<double>>& times =
      as_controller.event_times_s()[StretchReflexController::kStretchTrigger];
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

}  // namespace
}  // namespace pamsim
