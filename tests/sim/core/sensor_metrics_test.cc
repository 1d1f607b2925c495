// sensor_metrics_test.cc: the metric set "sensors" (sensor_metrics.h) on small models: the
// names and units by sensor type, a pendulum's swing between its release angles (energy
// conservation), a dropped box's touchdown and its weight on the touch sensor at rest, no
// touchdown for a box that starts on the floor, and the set through a scenario.
#include "sim/core/sensor_metrics.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "sim/inline_mjcf.h"
#include "base/input_error.h"
#include "sim/core/mujoco_util.h"
#include "sim/core/trial.h"
#include "sim/core/trial_model.h"
#include "sim/scenario/scenario_file.h"

namespace pamsim {
namespace {

using pamsim_test::load_inline;

constexpr char kRig[] = R"(
<mujoco>
  <option timestep="0.0005" gravity="0 0 -9.81"/>
  <worldbody>
    <geom name="floor" type="plane" size="1 1 0.1"/>
    <body name="box" pos="0 0 HEIGHT">
      <joint name="drop" type="slide" axis="0 0 1"/>
      <geom type="box" size="0.05 0.05 0.05" mass="1"/>
      <site name="sole" pos="0 0 -0.05" size="0.06 0.06 0.01" type="box"/>
    </body>
    <body name="bob" pos="1 0 1">
      <joint name="swing" type="hinge" axis="0 1 0"/>
      <geom type="sphere" pos="0 0 -0.5" size="0.02" mass="0.5" contype="0" conaffinity="0"/>
      <site name="tip" pos="0 0 -0.5"/>
    </body>
  </worldbody>
  <sensor>
    <touch name="grf" site="sole"/>
    <jointpos name="swing_angle" joint="swing"/>
    <jointpos name="drop_height" joint="drop"/>
    <framepos name="tip" objtype="site" objname="tip"/>
    <jointvel joint="swing"/>
  </sensor>
</mujoco>)";

// The rig with the box's centre `height_m` up, the pendulum released from 30 deg.
MjModelPtr rig(double height_m) {
  std::string xml = kRig;
  xml.replace(xml.find("HEIGHT"), 6, std::to_string(height_m));
  return load_inline(xml.c_str(), "sensor_rig.xml");
}

std::vector<Metric> run(const mjModel* m, double seconds) {
  SensorMetrics set(m);
  MjDataPtr d = make_data(m);
  d->qpos[m->jnt_qposadr[mj_name2id(m, mjOBJ_JOINT, "swing")]] = 30.0 * M_PI / 180.0;
  const int steps = static_cast<int>(std::lround(seconds / m->opt.timestep));
  for (int k = 0; k < steps; ++k) {
    mj_step(m, d.get());
    set.on_state(d.get());
  }
  std::vector<Metric> out;
  set.finish(FinishedTrial{}, &out);
  return out;
}

double value(const std::vector<Metric>& metrics, const std::string& name) {
  for (const Metric& m : metrics) {
    if (m.name == name) return m.value;
  }
  ADD_FAILURE() << "no metric " << name;
  return NAN;
}

TEST(SensorMetricsTest, EveryNamedSensorGivesItsExtremesInThePapersUnits) {
  MjModelPtr m = rig(0.05);
  std::vector<std::string> names;
  for (const Metric& metric : run(m.get(), 0.01)) names.push_back(metric.name);
  EXPECT_EQ(names,
            (std::vector<std::string>{
                "grf_min_N", "grf_max_N", "grf_touchdowns", "swing_angle_min_deg",
                "swing_angle_max_deg", "drop_height_min_mm", "drop_height_max_mm", "tip_x_min_mm",
                "tip_x_max_mm", "tip_y_min_mm", "tip_y_max_mm", "tip_z_min_mm", "tip_z_max_mm"}))
      << "the unnamed jointvel sensor is skipped";
}

// Released from 30 deg, the undamped pendulum swings to -30 deg (energy conserved to the
// integrator's error); its lowest point is 0.5 m below the pivot, 500 mm.
TEST(SensorMetricsTest, APendulumSwingsBetweenItsReleaseAngles) {
  MjModelPtr m = rig(0.05);
  const std::vector<Metric> metrics = run(m.get(), 1.6);  // beyond half a period (0.71 s)
  EXPECT_NEAR(value(metrics, "swing_angle_max_deg"), 30.0, 0.01);
  EXPECT_NEAR(value(metrics, "swing_angle_min_deg"), -30.0, 0.3);
  EXPECT_NEAR(value(metrics, "tip_z_min_mm"), 500.0, 0.1);
}

// Dropped from 5 cm above the floor, the box lands once and rests on its sole: the touch
// sensor then reads its weight, m g = 9.81 N, and peaked above it at the landing.
TEST(SensorMetricsTest, ADroppedBoxTouchesDownOnceAndRestsWithItsWeight) {
  MjModelPtr m = rig(0.10);
  const std::vector<Metric> metrics = run(m.get(), 1.5);
  EXPECT_EQ(value(metrics, "grf_touchdowns"), 1.0) << "it lands once";
  EXPECT_GT(value(metrics, "grf_max_N"), 1.5 * 9.81);
  EXPECT_EQ(value(metrics, "grf_min_N"), 0.0) << "in the air first";
  // at rest after 3 s: the set's extremes over the next 0.1 s are the weight, no touchdown
  SensorMetrics resting(m.get());
  MjDataPtr d = make_data(m.get());
  for (int k = 0; k < 3000; ++k) mj_step(m.get(), d.get());
  for (int k = 0; k < 100; ++k) {
    mj_step(m.get(), d.get());
    resting.on_state(d.get());
  }
  std::vector<Metric> rest;
  resting.finish(FinishedTrial{}, &rest);
  EXPECT_NEAR(value(rest, "grf_min_N"), 9.81, 0.2);
  EXPECT_NEAR(value(rest, "grf_max_N"), 9.81, 0.2);
  EXPECT_EQ(value(rest, "grf_touchdowns"), 0.0);
}

TEST(SensorMetricsTest, ABoxThatStartsOnTheFloorHasNoTouchdown) {
  MjModelPtr m = rig(0.0495);  // pressed 0.5 mm into it: in contact from the first step
  const std::vector<Metric> metrics = run(m.get(), 0.5);
  EXPECT_EQ(value(metrics, "grf_touchdowns"), 0.0);
  EXPECT_GT(value(metrics, "grf_min_N"), 0.0);
}

// A sensor named like another set's metric ("angle" gives angle_min_deg, as tracking does)
// would make two columns of one name: refused with the name
TEST(SensorMetricsTest, TwoMetricsOfOneNameAreRefused) {
  Scenario sc;
  sc.path = "leg.toml";
  EXPECT_NO_THROW(require_unique_metric_names(sc, {"angle_min_deg", "grf_max_N"}));
  try {
    require_unique_metric_names(sc, {"angle_min_deg", "grf_max_N", "angle_min_deg"});
    ADD_FAILURE() << "a repeated name was accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()),
              "leg.toml: metrics name two metrics angle_min_deg (rename the model's sensor that "
              "gives it)");
  }
}

// Through a scenario: the arm has no sensors, so the set adds no metrics and the summary
// still has the others; the set's name is accepted by the scenario's metrics list
TEST(SensorMetricsTest, AScenarioListsTheSetAndAModelWithoutSensorsAddsNothing) {
  const Scenario sc = load_scenario(std::string(PAMSIM_SOURCE_DIR) + "/scenarios/drop_mass.toml",
                                    {"metrics=[\"drop\", \"sensors\"]", "sim.duration_s=1.2"});
  const TrialModel model = load_trial_model(sc);
  const TrialResult r = run_trial(model, sc, 1);
  ASSERT_EQ(r.summary.status, "ok");
  EXPECT_FALSE(std::isnan(r.summary.metric("peak_drop_deg")));
  for (const Metric& metric : r.summary.metrics) {
    EXPECT_EQ(metric.name.find("_touchdowns"), std::string::npos) << metric.name;
  }
}

}  // namespace
}  // namespace pamsim
