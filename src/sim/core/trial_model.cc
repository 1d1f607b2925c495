// trial_model.cc: see trial_model.h.
#include "sim/core/trial_model.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <cstring>

#include "base/format.h"
#include "base/input_error.h"
#include "base/units.h"
#include "sim/core/metrics.h"
#include "sim/core/muscle_law.h"
#include "sim/core/pam_callback.h"
#include "sim/core/trial_lines.h"

namespace pamsim {
namespace {

constexpr double kMinMomentArm_m = 1e-4;  // 0.1 mm: below it a tendon does not cross a joint

using detail::fail;
using detail::start_state;

int find_id(const mjModel* m, mjtObj type, const std::string& name) {
  return name.empty() ? -1 : mj_name2id(m, type, name.c_str());
}

int require(const Scenario& sc, const mjModel* m, mjtObj type, const std::string& name,
            const std::string& key, const char* what) {
  const int id = find_id(m, type, name);
  if (id < 0)
    fail(sc, key,
         "names " + std::string(what) + " '" + name + "', which " + sc.model_file +
             " does not have");
  return id;
}

bool is_pam_actuator(const mjModel* m, int id) {
  return m->actuator_biastype[id] == mjBIAS_USER && m->actuator_trntype[id] == mjTRN_TENDON;
}

std::string pam_actuator_names(const mjModel* m) {
  std::string names;
  for (int id = 0; id < m->nu; ++id) {
    if (!is_pam_actuator(m, id)) continue;
    names += (names.empty() ? "" : ", ") + std::string(mj_id2name(m, mjOBJ_ACTUATOR, id));
  }
  return names.empty() ? "none" : names;
}

// the muscles in actuator order; every PAM actuator has one and every muscle an actuator
void bind_muscles(const Scenario& sc, TrialModel* tm) {
  mjModel* m = tm->model.get();
  for (std::size_t k = 0; k < sc.muscles.size(); ++k) {
    const MuscleSpec& spec = sc.muscles[k];
    const int id = find_id(m, mjOBJ_ACTUATOR, spec.actuator);
    if (id < 0 || !is_pam_actuator(m, id)) {
      fail(
          sc, spec.key,
          "names no PAM actuator of " + sc.model_file + " (it has: " + pam_actuator_names(m) + ")");
    }
  }
  for (int id = 0; id < m->nu; ++id) {
    if (!is_pam_actuator(m, id)) continue;
    const std::string name = mj_id2name(m, mjOBJ_ACTUATOR, id);
    const MuscleSpec* spec = sc.muscle(name);
    if (!spec) {
      fail(sc, "muscles." + name,
           "is required: " + sc.model_file + " has a PAM actuator of that name (give its params)");
    }
    BoundMuscle b;
    b.spec = static_cast<int>(spec - sc.muscles.data());
    b.actuator = id;
    b.label = spec->label;
    if (!spec->plant_file.empty()) {
      b.braid = avbdl_braid(spec->plant);  // the chamber of the physical muscle
    } else if (!spec->pam.geometry) {
      fail(sc, spec->key + ".params",
           "(" + spec->params_file +
               ") needs a [geometry] table "
               "for the chamber volume");
    } else {
      b.braid = braid_from_initial_shape(spec->pam.geometry->length_m,
                                         spec->pam.geometry->sleeve_diameter_m,
                                         spec->pam.geometry->braid_angle_rad);
    }
    tm->muscles.push_back(b);
  }
  if (m->nuserdata < static_cast<int>(tm->muscles.size())) {
    throw InputError(sc.model_file + ": <size nuserdata> must be >= " +
                     std::to_string(tm->muscles.size()) + " to hold the PAM pressures");
  }
}

void bind_joint(const Scenario& sc, TrialModel* tm) {
  const mjModel* m = tm->model.get();
  int j = -1;
  if (sc.joint.empty()) {  // the model's first hinge or slide joint
    for (int k = 0; k < m->njnt && j < 0; ++k) {
      if (m->jnt_type[k] == mjJNT_HINGE || m->jnt_type[k] == mjJNT_SLIDE) j = k;
    }
    if (j < 0)
      fail(sc, "model.joint", "is required: " + sc.model_file + " has no hinge or slide joint");
  } else {
    j = require(sc, m, mjOBJ_JOINT, sc.joint, "model.joint", "a joint");
  }
  if (m->jnt_type[j] != mjJNT_HINGE && m->jnt_type[j] != mjJNT_SLIDE) {
    fail(sc, "model.joint", "must name a hinge or slide joint");
  }
  tm->joint.name = mj_id2name(m, mjOBJ_JOINT, j);
  tm->joint.hinge = m->jnt_type[j] == mjJNT_HINGE;
  tm->joint.qpos = m->jnt_qposadr[j];
  tm->joint.dof = m->jnt_dofadr[j];
  if (sc.has_start_position && !tm->joint.hinge) {
    fail(sc, "model.calibration",
         "gives a start angle, but joint '" + tm->joint.name + "' is a slide");
  }
}

// a body with a free joint: its qpos and dof addresses
void free_joint_of(const Scenario& sc, const mjModel* m, int body, const std::string& key,
                   int* qpos, int* dof) {
  const int j = m->body_jntadr[body];
  if (j < 0 || m->jnt_type[j] != mjJNT_FREE) {
    fail(sc, key,
         "needs body '" + std::string(mj_id2name(m, mjOBJ_BODY, body)) + "' to have a free joint");
  }
  *qpos = m->jnt_qposadr[j];
  *dof = m->jnt_dofadr[j];
}

void bind_holds(const Scenario& sc, TrialModel* tm) {
  const mjModel* m = tm->model.get();
  for (const HoldSpec& h : sc.holds) {
    BoundHold b;
    b.body = require(sc, m, mjOBJ_BODY, h.body, h.key + ".body", "a body");
    free_joint_of(sc, m, b.body, h.key, &b.qpos, &b.dof);
    if (!h.at_position) {
      b.site = require(sc, m, mjOBJ_SITE, h.above_site, h.key + ".above_site", "a site");
      // the height is the body's bottom's when its first geom is a sphere
      const int g = m->body_geomadr[b.body];
      const bool sphere = m->body_geomnum[b.body] > 0 && m->geom_type[g] == mjGEOM_SPHERE;
      b.radius_m = sphere ? m->geom_size[3 * g] : 0.0;
    }
    tm->holds.push_back(b);
  }
}

void bind_events(const Scenario& sc, TrialModel* tm) {
  const mjModel* m = tm->model.get();
  for (const EventSpec& e : sc.events) {
    BoundEvent b;
    const ConditionSpec& c = e.when;
    if (c.kind == ConditionKind::kContact || c.kind == ConditionKind::kBodyBelow) {
      b.body_a = require(sc, m, mjOBJ_BODY, c.body_a, e.key + ".when", "a body");
    }
    if (c.kind == ConditionKind::kContact) {
      b.body_b = require(sc, m, mjOBJ_BODY, c.body_b, e.key + ".when", "a body");
    }
    if (c.kind == ConditionKind::kJointBelow || c.kind == ConditionKind::kJointAbove) {
      const int j = require(sc, m, mjOBJ_JOINT, c.joint, e.key + ".joint", "a joint");
      if (m->jnt_type[j] != mjJNT_HINGE && m->jnt_type[j] != mjJNT_SLIDE) {
        fail(sc, e.key + ".joint", "must name a hinge or slide joint");
      }
      b.joint_qpos = m->jnt_qposadr[j];
    }
    if (e.action == EventAction::kRelease || e.action == EventAction::kAddMass) {
      b.body = require(sc, m, mjOBJ_BODY, e.body, e.key + ".body", "a body");
    }
    if (e.action == EventAction::kRelease) {
      for (std::size_t h = 0; h < tm->holds.size(); ++h) {
        if (tm->holds[h].body == b.body) b.hold = static_cast<int>(h);
      }
      if (b.hold < 0) fail(sc, e.key + ".body", "names body '" + e.body + "', which no hold holds");
    }
    if (e.action == EventAction::kAddMass) tm->events_change_model = true;
    if (!c.after.empty()) {
      const EventSpec* after = sc.event(c.after);
      if (!after || after == &e) {
        fail(sc, e.key + ".after", "names no other event ('" + c.after + "')");
      }
      b.after = static_cast<int>(after - sc.events.data());
    }
    tm->events.push_back(b);
  }
}

void bind_pairs(const Scenario& sc, TrialModel* tm) {
  for (const std::array<std::string, 2>& names : sc.controller_pairs()) {
    tm->pairs.push_back(tm->pair_of(sc, names, "reflex.pairs"));
  }
}

// joints.<joint>.*: damping and friction loss over the model's, in the joint's own units;
// its start position (MuJoCo's qpos0 is the bodies' reference, so not that)
void set_joints(const Scenario& sc, TrialModel* tm) {
  mjModel* m = tm->model.get();
  for (const JointSpec& j : sc.joints) {
    const int id = require(sc, m, mjOBJ_JOINT, j.joint, j.key, "a joint");
    const int type = m->jnt_type[id];
    if (type != mjJNT_HINGE && type != mjJNT_SLIDE) {
      fail(sc, j.key, "names joint '" + j.joint + "', which is neither a hinge nor a slide");
    }
    if ((type == mjJNT_HINGE) != j.rotational) {
      fail(sc, j.key,
           "gives a " + std::string(j.rotational ? "hinge" : "slide") + "'s keys, but joint '" +
               j.joint + "' is a " + (type == mjJNT_HINGE ? "hinge" : "slide"));
    }
    const int dof = m->jnt_dofadr[id];
    if (!std::isnan(j.damping)) m->dof_damping[dof] = j.damping;
    if (!std::isnan(j.frictionloss)) m->dof_frictionloss[dof] = j.frictionloss;
    if (std::isnan(j.start)) continue;
    const std::string key = j.key + (j.rotational ? ".start_deg" : ".start_mm");
    // the calibrated joint: model.joint's, or the default it falls back to
    if (sc.has_start_position && m->jnt_qposadr[id] == tm->joint.qpos) {
      fail(sc, key, "would move the start that model.calibration sets (its start_angle_deg)");
    }
    const double* range = m->jnt_range + 2 * id;
    if (m->jnt_limited[id] && !(j.start >= range[0] && j.start <= range[1])) {
      const double unit = j.rotational ? units::rad_to_deg(1.0) : units::m_to_mm(1.0);
      fail(sc, key,
           "must be within the joint's range [" + format_value(unit * range[0]) + ", " +
               format_value(unit * range[1]) + "], got " + format_value(unit * j.start));
    }
    tm->start_qpos.push_back({m->jnt_qposadr[id], j.start});
  }
}

// muscles.<m>.spans: a moment arm of the muscle's tendon at each joint it names, in the
// start state (a biarticular tendon whose path misses a joint has none there)
void check_spans(const Scenario& sc, const TrialModel& tm) {
  const mjModel* m = tm.model.get();
  MjDataPtr data;
  for (const BoundMuscle& b : tm.muscles) {
    const MuscleSpec& spec = sc.muscles[b.spec];
    for (const std::string& joint : spec.spans) {
      const int j = require(sc, m, mjOBJ_JOINT, joint, spec.key + ".spans", "a joint");
      if (m->jnt_type[j] != mjJNT_HINGE && m->jnt_type[j] != mjJNT_SLIDE) {
        fail(sc, spec.key + ".spans", "names joint '" + joint + "': a hinge or slide only");
      }
      if (!data) data = start_state(sc, tm);
      const double arm =
          data->actuator_moment[static_cast<long>(b.actuator) * m->nv + m->jnt_dofadr[j]];
      if (std::fabs(arm) < kMinMomentArm_m) {
        fail(sc, spec.key + ".spans",
             "names joint '" + joint +
                 "', which the tendon's path "
                 "misses (no moment arm there at the start)");
      }
    }
  }
}

// sim.contact_soft_onset_mm: MuJoCo starts a contact on the step its geoms first overlap,
// with the force its impedance at zero penetration gives (solimp's dmin, 0.9 by default), so
// when a landing moves by a step the trajectory jumps, however small the change that moved
// it: a prediction that is not a continuous function of the model's parameters. From mjMINIMP
// over `width` the force starts at 0 and a landing's step no longer matters.
void set_contact_onset(double width_m, mjModel* m) {
  if (width_m <= 0) return;
  const auto soften = [&](mjtNum* solimp) {
    solimp[0] = mjMINIMP;
    solimp[2] = width_m;
  };
  for (int g = 0; g < m->ngeom; ++g) soften(m->geom_solimp + mjNIMP * g);
  for (int p = 0; p < m->npair; ++p) soften(m->pair_solimp + mjNIMP * p);
}

}  // namespace

int TrialModel::muscle_index(const Scenario& sc, const std::string& actuator) const {
  for (std::size_t k = 0; k < muscles.size(); ++k) {
    if (sc.muscles[muscles[k].spec].actuator == actuator) return static_cast<int>(k);
  }
  return -1;
}

ReflexPair TrialModel::pair_of(const Scenario& sc, const std::array<std::string, 2>& names,
                               const std::string& key) const {
  ReflexPair pair;
  int* slot[2] = {&pair.agonist, &pair.antagonist};
  for (int r = 0; r < 2; ++r) {
    *slot[r] = muscle_index(sc, names[r]);
    if (*slot[r] < 0) {
      fail(sc, key, "names muscle '" + names[r] + "', which is not a muscle of the scenario");
    }
  }
  return pair;
}

void set_body_mass(mjModel* m, int body, double mass_kg) {
  const double old_mass = m->body_mass[body];
  if (old_mass > 0) {
    for (int k = 0; k < 3; ++k) m->body_inertia[3 * body + k] *= mass_kg / old_mass;
  }
  m->body_mass[body] = mass_kg;
  for (int b = body; b > 0; b = m->body_parentid[b]) m->body_subtreemass[b] += mass_kg - old_mass;
  m->body_subtreemass[0] += mass_kg - old_mass;
}

TrialModel load_trial_model(const Scenario& sc) {
  static std::atomic<std::uint64_t> next_id{1};
  TrialModel tm;
  tm.id = next_id++;
  tm.model_path = sc.model_file;
  tm.model = load_mjcf(sc.model_file);
  mjModel* m = tm.model.get();
  m->opt.timestep = sc.timestep_s;  // the scenario's step, not the MJCF's
  set_contact_onset(sc.contact_soft_onset_m, m);

  // the cast by name; masses before the lines: a static start depends on them
  bind_muscles(sc, &tm);
  bind_joint(sc, &tm);
  for (const BodyMassSpec& b : sc.body_masses) {
    const int body = require(sc, m, mjOBJ_BODY, b.body, b.key, "a body");
    if (b.mass_kg > 0) set_body_mass(m, body, b.mass_kg);
  }
  for (const BodyMassSpec& b : sc.body_masses) {  // an inertia given wins over a scaled one
    const int body = require(sc, m, mjOBJ_BODY, b.body, b.key, "a body");
    if (b.inertia_kg_m2[0] > 0) std::copy_n(b.inertia_kg_m2.data(), 3, m->body_inertia + 3 * body);
  }
  set_joints(sc, &tm);
  bind_holds(sc, &tm);
  bind_events(sc, &tm);
  bind_pairs(sc, &tm);
  detail::set_lines(sc, &tm);
  // where the force callback reads each muscle's pressure: the trial writes it there
  for (BoundMuscle& b : tm.muscles)
    b.pressure_slot = pam_userdata_index(tm.model.get(), b.actuator);
  check_spans(sc, tm);
  std::vector<std::string> labels;
  for (const BoundMuscle& b : tm.muscles) labels.push_back(b.label);
  require_unique_metric_names(sc, metric_names(sc, labels, tm.joint.hinge, tm.model.get()));
  return tm;
}

}  // namespace pamsim
