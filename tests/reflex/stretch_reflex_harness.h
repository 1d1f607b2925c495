// stretch_reflex_harness.h: the StretchReflexController behind a SensorSuite on synthetic
// truth of the Table IV arm, one control tick as the co-simulation loop does it (truth ->
// readings -> controller), for the controller's tests (stretch_reflex_controller_test.cc,
// stretch_reflex_pairs_test.cc).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "../sensing/sensing_test_util.h"

#include "base/control_step.h"
#include "base/no_value.h"
#include "pam_actuator/spring_model.h"
#include "reflex/controller.h"
#include "reflex/pass_through_controller.h"
#include "reflex/stretch_reflex_controller.h"
#include "sensing/sensing.h"

namespace pamsim::reflex_test {

using pamsim_test::kControlDt;

using test::table_iv_agonist;
using test::table_iv_antagonist;
constexpr double kRampV_m_s = 0.150;  // the stretch of the ramps below
// the log's channel of the stretch (Ia) windows in a reflex controller's output
constexpr int kWindow = StretchReflexController::kStretchWindow;

// Everything a harness is built from. Defaults: the falling-mass operating point (the arm at
// -36 deg on the Table IV laws, as a prototype calibrated it), both muscles at 0.4 MPa and
// scheduled at 0.4 MPa, agonist d = 6.66 mm, antagonist d = 1.0 mm; one pair {0, 1}; default
// sensors and Table II's model-based reflex.
struct Rig {
  std::vector<MuscleSensorSpec> muscles = {table_iv_agonist(), table_iv_antagonist()};
  std::vector<double> d_m = {6.66e-3, 1.0e-3};
  std::vector<double> p_pa = {0.4e6, 0.4e6};     // true chamber pressures
  std::vector<double> p_tp_pa = {0.4e6, 0.4e6};  // scheduled commands
  SensingConfig sensing;
  StretchReflexControllerConfig controller;
  std::uint64_t seed = 7;
};

// The default Rig with Table II's reflex for `sensor`
inline Rig table_ii_rig(ReflexSensor sensor) {
  Rig rig;
  rig.controller.reflex = table_ii_reflex_config(sensor);
  return rig;
}

// Rig plus a third muscle (an agonist, stretched like the first) in no pair, scheduled at
// p_tp_pa
inline Rig with_spare_muscle(double p_tp_pa) {
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
inline Rig two_pairs() {
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
    const double time_s = static_cast<double>(outputs.size()) / controller.config().control_hz;
    std::vector<MuscleReading> readings(muscle_count());
    sensing.sample(truth(), &readings);
    ControlOutput out;
    out.resize(muscle_count(), controller.config().tension ? 2 : 1);
    std::fill(out.p_cmd_pa.begin(), out.p_cmd_pa.end(), kNaN);
    std::fill(out.velocity_m_s.begin(), out.velocity_m_s.end(), kNaN);
    for (std::vector<double>& channel : out.channels)
      std::fill(channel.begin(), channel.end(), 2.0);
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

  Rig rig;  // the plant's state and the schedule, moved by the tests
  SensorSuite sensing;
  StretchReflexController controller;
  std::vector<std::vector<MuscleReading>> reading_log;  // per tick
  std::vector<ControlOutput> outputs;                   // per tick
};

// stretch `muscle` at 150 mm/s for 5 ticks, from tick `first` on (the tick is run after
// the move, so `first` is the first tick that reads the stretch); `shortened`, if >= 0, is
// shortened alike down to 5 mm of slack
inline void stretch_at(Harness* h, int tick, int first, int muscle, int shortened = -1) {
  if (tick < first || tick >= first + 5) return;
  h->rig.d_m[muscle] += kRampV_m_s * kControlDt;
  if (shortened >= 0) {
    h->rig.d_m[shortened] = std::max(h->rig.d_m[shortened] - kRampV_m_s * kControlDt, -5e-3);
  }
}

// the old falling-mass ramp: quiet for 1 s, then the agonist stretched (antagonist
// shortened) at 150 mm/s for 50 ms from tick 101; 200 ticks in all
inline void run_ramp(Harness* h, bool enabled = true) {
  for (int j = 0; j < 200; ++j) {
    stretch_at(h, j, 101, 0, 1);
    h->tick(enabled);
  }
}

inline int active_ticks(const Harness& h, int muscle) {
  int n = 0;
  for (const ControlOutput& o : h.outputs) n += static_cast<int>(o.channels[kWindow][muscle]);
  return n;
}

}  // namespace pamsim::reflex_test
