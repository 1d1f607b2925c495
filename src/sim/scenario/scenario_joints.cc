// scenario_joints.cc: joints.<joint>.*, a joint's damping and friction loss in place of the
// model's (scenario.h, JointSpec): a hinge's in N m s/rad and N m, a slide's in N s/m and N;
// and its position at the start (start_deg, start_mm: set in the trial's start state, so a
// leg starts crouched or a trunk high above the ground).
// Whether the joint exists, and is of the kind its keys' units say, is checked when the
// model is bound (trial_model.cc).
#include "base/format.h"
#include "base/units.h"
#include "sim/scenario/scenario_reading.h"

namespace pamsim {
namespace {

// the key's value, >= 0 and at most `max`; NaN when not given
double read_loss(ConfigReader& in, const std::string& key, double max, const char* unit) {
  if (!in.has(key)) return std::numeric_limits<double>::quiet_NaN();
  const double v = in.require_double(key);
  in.check(v >= 0.0 && v <= max, key, "must be in [0, " + format_value(max) + "] " + unit +
                                          ", got " + format_value(v));
  return v;
}

// the key's value in [-max, max], in SI (times `si`); NaN when not given
double read_start(ConfigReader& in, const std::string& key, double max, const char* unit,
                  double si) {
  if (!in.has(key)) return std::numeric_limits<double>::quiet_NaN();
  const double v = in.require_double(key);
  in.check(v >= -max && v <= max, key, "must be in [-" + format_value(max) + ", " +
                                           format_value(max) + "] " + unit + ", got " +
                                           format_value(v));
  return v * si;
}

}  // namespace

void read_joints(ConfigReader& in, Scenario* sc) {
  for (const std::string& name : in.child_keys("joints")) {
    JointSpec j;
    j.key = "joints." + name;
    j.joint = name;
    const bool hinge = in.has(j.key + ".damping_N_m_s_per_rad") ||
                       in.has(j.key + ".frictionloss_N_m") || in.has(j.key + ".start_deg");
    const bool slide = in.has(j.key + ".damping_N_s_per_m") ||
                       in.has(j.key + ".frictionloss_N") || in.has(j.key + ".start_mm");
    in.check(!(hinge && slide), j.key, "mixes a hinge's keys (damping_N_m_s_per_rad, "
                                       "frictionloss_N_m, start_deg) with a slide's "
                                       "(damping_N_s_per_m, frictionloss_N, start_mm)");
    in.check(hinge || slide, j.key, "gives none of damping_N_m_s_per_rad, frictionloss_N_m, "
                                    "start_deg (a hinge), damping_N_s_per_m, frictionloss_N, "
                                    "start_mm (a slide)");
    j.rotational = hinge;
    if (hinge) {
      j.damping = read_loss(in, j.key + ".damping_N_m_s_per_rad", 1e4, "N m s/rad");
      j.frictionloss = read_loss(in, j.key + ".frictionloss_N_m", 1e4, "N m");
      j.start = read_start(in, j.key + ".start_deg", 360.0, "deg", units::deg_to_rad(1.0));
    } else {
      j.damping = read_loss(in, j.key + ".damping_N_s_per_m", 1e6, "N s/m");
      j.frictionloss = read_loss(in, j.key + ".frictionloss_N", 1e6, "N");
      j.start = read_start(in, j.key + ".start_mm", 1e4, "mm", units::mm_to_m(1.0));
    }
    sc->joints.push_back(j);
  }
}

}  // namespace pamsim
