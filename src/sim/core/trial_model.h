// trial_model.h: a scenario's MuJoCo model, ready for trials: loaded, its PAM actuators
// bound to the scenario's muscles by name (laws and line lengths bound to the model's
// actuators, see muscle_binding.h), body masses set, and the ids of everything
// the scenario names (joint, held bodies, event bodies and joints) looked up and checked.
// Built once per run and then only read, so all worker threads share one mjModel (each
// trial has its own mjData; a trial whose events change the model copies it).
//
// The model's PAM actuators are its `general` actuators on a tendon with biastype="user";
// every one must have a muscle in the scenario and every muscle an actuator. Muscles are
// indexed in the model's actuator order (log columns, noise stream, controller).
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "pam_actuator/chou_hannaford.h"
#include "reflex/controller.h"
#include "sim/core/mujoco_util.h"
#include "sim/core/scenario.h"

namespace pamsim {

struct BoundMuscle {
  int spec = -1;  // index into Scenario::muscles
  int actuator = -1;
  std::string label;
  BraidGeometry braid;         // the chamber volume law, from the params' [geometry]
  double line_length_m = 0.0;  // as bound to the actuator
  int pressure_slot = -1;      // d->userdata index of its chamber pressure [Pa], the binding's
};

struct BoundJoint {
  std::string name;
  bool hinge = true;  // else slide
  int qpos = -1;
  int dof = -1;
};

struct BoundHold {
  int body = -1;
  int qpos = -1;  // of its free joint
  int dof = -1;
  int site = -1;          // above_site, or -1 for a fixed position
  double radius_m = 0.0;  // of the body's first geom if it is a sphere, else 0
};

struct BoundEvent {
  int body_a = -1, body_b = -1;  // condition bodies
  int joint_qpos = -1;           // condition joint
  int body = -1;                 // the released or loaded body
  int hold = -1;                 // kRelease: the hold it ends
  int after = -1;                // index of the event it waits for
};

struct TrialModel {
  std::uint64_t id = 0;  // unique per load in this process (trial data reuse)
  std::string model_path;
  MjModelPtr model;
  std::vector<BoundMuscle> muscles;  // model actuator order
  BoundJoint joint;
  std::vector<BoundHold> holds;  // Scenario::holds order
  // joints.<joint>.start_*: (qpos address, position [rad or m]) set at the start
  std::vector<std::pair<int, double>> start_qpos;
  std::vector<BoundEvent> events;    // Scenario::events order
  std::vector<ReflexPair> pairs;     // by muscle index (model order)
  bool events_change_model = false;  // an add_mass event: each trial copies the model

  // The muscle index of an actuator name, or -1.
  int muscle_index(const Scenario& scenario, const std::string& actuator) const;
  // The pair of two muscles by actuator name (agonist, antagonist); throws InputError
  // "<scenario>: <key> names muscle '<name>', which is not a muscle of the scenario".
  ReflexPair pair_of(const Scenario& scenario, const std::array<std::string, 2>& names,
                     const std::string& key) const;
  // Puts the joints of `d` at their start: each joints.<joint>.start_* key's, then the
  // calibrated joint at the scenario's start angle (when it has one).
  void place_at_start(const Scenario& scenario, mjData* d) const {
    for (const auto& [adr, value] : start_qpos) d->qpos[adr] = value;
    if (scenario.has_start_position) d->qpos[joint.qpos] = scenario.start_position;
  }
};

// Loads the model of `scenario` and binds everything it names. Throws InputError naming the
// scenario file and the key for a name the model lacks, a PAM actuator without a muscle (or
// the reverse), a hold on a body without a free joint, a line that cannot hold the start
// state, and MuJoCo's own message for a model that fails to load.
TrialModel load_trial_model(const Scenario& scenario);

// True if two scenarios build the same TrialModel, so a sweep worker can keep its model
// when a point changes only trial-only keys (gains, noise, the valve, the run's length...):
// their model_keys are equal, and not empty. A test holds this to the built models, key by
// key (tests/sim/core/trial_model_identity_test.cc).
bool same_trial_model(const Scenario& a, const Scenario& b);

// One bound model per distinct model among `scenarios` (same_trial_model), in order of first
// use; `model_of[i]` is the index of scenario i's (a tuning setting's noise levels differ only
// in the sensors, and compiling the MJCF again per level would double its set-up).
std::vector<TrialModel> shared_trial_models(const std::vector<Scenario>& scenarios,
                                            std::vector<std::size_t>* model_of);

// Sets a body's mass, scaling its inertia with it, and the subtree masses above it.
void set_body_mass(mjModel* m, int body, double mass_kg);

}  // namespace pamsim
