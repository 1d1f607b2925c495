// sensor_metrics.h: the metric set "sensors": the extremes of every sensor the MJCF model
// declares, over every physics step, so that an experiment measures what its model defines
// (a touch sensor under a foot for the ground reaction force, a jointpos sensor for a knee's
// collapse, a framepos sensor for a hop's height) without code of its own.
#pragma once

#include <mujoco/mujoco.h>

#include <string>
#include <vector>

#include "sim/core/metrics.h"

namespace pamsim {

// For each named sensor (unnamed ones are skipped) and each of its components, in the
// model's order: <name>[_<axis>]_min_<unit> and _max_<unit>, in the papers' units by the
// sensor's type:
//   touch, force, actuatorfrc        N            torque              N_m
//   jointpos, jointvel (hinge)       deg, deg_s   (slide)             mm, mm_s
//   framepos, tendonpos, rangefinder mm           framelinvel, velocimeter, tendonvel  mm_s
//   any other                        si (MuJoCo's own SI value)
// axes x, y, z for three-component sensors, 0.. for others with more than one. A touch
// sensor also counts its touchdowns, <name>_touchdowns: the steps at which it reads a
// force after a step at which it read none (a contact at the start is not one). Sensors are
// read after each mj_step, at the state MuJoCo computed them for.
class SensorMetrics final : public MetricSet {
 public:
  // The model's sensors; a null model has none (a scenario read without its model).
  explicit SensorMetrics(const mjModel* model);

  bool wants_steps() const override { return true; }
  void on_state(const mjData* d) override;
  void finish(const FinishedTrial& record, std::vector<Metric>* out) const override;

 private:
  struct Channel {
    std::string name;    // <name>[_<axis>]
    std::string unit;    // in the metric's name
    int address = 0;     // in d->sensordata
    double scale = 1.0;  // SI -> the unit
    bool touch = false;  // counts touchdowns
    double min = 0.0, max = 0.0;
    int touchdowns = 0;
    bool seen = false;      // a step has been read
    bool touching = false;  // the last step read a force
  };
  std::vector<Channel> channels_;
};

}  // namespace pamsim
