// sensor_metrics.cc: see sensor_metrics.h.
#include "sim/core/sensor_metrics.h"

#include <cmath>

#include "base/no_value.h"
#include "base/units.h"

namespace pamsim {
namespace {

struct Unit {
  const char* name;
  double scale;  // SI -> unit
};

// The unit of a sensor's type (and, for joint sensors, its joint's kind)
Unit unit_of(const mjModel* m, int sensor) {
  const double deg = units::rad_to_deg(1.0), mm = units::m_to_mm(1.0);
  const bool hinge = m->sensor_objtype[sensor] == mjOBJ_JOINT &&
                     m->jnt_type[m->sensor_objid[sensor]] == mjJNT_HINGE;
  switch (m->sensor_type[sensor]) {
    case mjSENS_TOUCH:
    case mjSENS_FORCE:
    case mjSENS_ACTUATORFRC:
      return {"N", 1.0};
    case mjSENS_TORQUE:
      return {"N_m", 1.0};
    case mjSENS_JOINTPOS:
      return hinge ? Unit{"deg", deg} : Unit{"mm", mm};
    case mjSENS_JOINTVEL:
      return hinge ? Unit{"deg_s", deg} : Unit{"mm_s", mm};
    case mjSENS_FRAMEPOS:
    case mjSENS_TENDONPOS:
    case mjSENS_RANGEFINDER:
      return {"mm", mm};
    case mjSENS_FRAMELINVEL:
    case mjSENS_VELOCIMETER:
    case mjSENS_TENDONVEL:
      return {"mm_s", mm};
    default:
      return {"si", 1.0};
  }
}

std::string axis_name(int dim, int k) {
  if (dim == 1) return "";
  if (dim == 3) return std::string("_") + "xyz"[k];
  return "_" + std::to_string(k);
}

}  // namespace

SensorMetrics::SensorMetrics(const mjModel* m) {
  if (m == nullptr) return;
  for (int s = 0; s < m->nsensor; ++s) {
    const char* name = mj_id2name(m, mjOBJ_SENSOR, s);
    if (name == nullptr || *name == '\0') continue;
    const Unit unit = unit_of(m, s);
    for (int k = 0; k < m->sensor_dim[s]; ++k) {
      Channel c;
      c.name = name + axis_name(m->sensor_dim[s], k);
      c.unit = unit.name;
      c.address = m->sensor_adr[s] + k;
      c.scale = unit.scale;
      c.touch = m->sensor_type[s] == mjSENS_TOUCH;
      channels_.push_back(c);
    }
  }
}

void SensorMetrics::on_state(const mjData* d) {
  for (Channel& c : channels_) {
    const double v = c.scale * d->sensordata[c.address];
    if (!c.seen || std::isnan(v)) {
      c.min = c.max = v;
    } else if (!std::isnan(c.min)) {  // NaN sticks: a diverged trial's extremes are NaN
      if (v < c.min) c.min = v;
      if (v > c.max) c.max = v;
    }
    const bool touching = v > 0.0;
    if (c.touch && c.seen && touching && !c.touching) ++c.touchdowns;
    c.touching = touching;
    c.seen = true;
  }
}

void SensorMetrics::finish(const FinishedTrial& /*record*/, std::vector<Metric>* out) const {
  for (const Channel& c : channels_) {
    out->push_back({c.name + "_min_" + c.unit, c.seen ? c.min : kNaN});
    out->push_back({c.name + "_max_" + c.unit, c.seen ? c.max : kNaN});
    if (c.touch) out->push_back({c.name + "_touchdowns", static_cast<double>(c.touchdowns), true});
  }
}

}  // namespace pamsim
