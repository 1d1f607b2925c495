// scenario.h: a trial's complete description, as plain data: which model, which of its PAM
// actuators with which parameter files and command schedules, what happens when (holds and
// events), which controller, which metrics. The core (trial.h) runs any such description
// and knows no experiment by name: the falling mass, the pulley's sinusoid and the reaching
// ramps are scenario files (scenarios/*.toml), read and validated by scenario/scenario_file.h,
// which documents every key.
#pragma once

#include <array>
#include <cstdint>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "pam_actuator/avbdl.h"
#include "pam_actuator/pam_params.h"
#include "pneumatics/pneumatics.h"
#include "reflex/controller_kind.h"
#include "sensing/sensing.h"
#include "sim/core/schedule.h"

namespace pamsim {

// How a muscle's fishing-line length (tendon length minus PAM length) is set.
enum class LineSource {
  kFixed,        // muscles.<name>.line_mm, or <actuator>_line_mm of model.calibration
  kEquilibrium,  // solved so the start state is static (trial_model.h)
};

// Every spec carries the scenario key it was read from (e.g. "muscles.agonist",
// "events.release", "drop"), so an error found when the model is bound can name it.

struct MuscleSpec {
  std::string key;
  std::string actuator;       // the model's PAM actuator (MJCF name)
  std::string label;          // in log columns and metric names (default: actuator)
  std::string params_file;    // muscles.<name>.params
  PamParams pam;              // the law its estimator inverts, its gauge and geometry
  std::string plant_file;     // muscles.<name>.plant, or empty: the plant is pam's law
  AvbdlParams plant;          // the physical muscle (Pipan et al.), when plant_file is set
  std::string plant_changes;  // muscles.<name>.plant.<table>.<field> as TOML text, if any
  PressureSchedule command;   // muscles.<name>.command
  LineSource line = LineSource::kFixed;
  double line_length_m = 0.0;  // kFixed
  // The line's axial stiffness E A [N] (muscles.<m>.line_diameter_mm, line_modulus_MPa);
  // 0: inextensible. An extensible line's length above is its length at the start state,
  // under the start's tension.
  double line_axial_stiffness_n = 0.0;
  // Its creep (muscles.<m>.line_creep, line_creep_time_s): one Kelvin-Voigt element on its
  // compliance, the long-term creep g per unit elastic stretch and its retardation time
  // (pam_callback.h); 0: none.
  double line_creep = 0.0;
  double line_creep_time_s = 10.0;
  // muscles.<m>.spans: the joints its tendon must cross (checked when the model is bound: a
  // moment arm at each in the start state); empty: not checked
  std::vector<std::string> spans;
  // muscles.<m>.line_limit_N: the line's working load [N] (NaN: none); the metric set
  // "tension" gives the peak pull in per cent of it
  double line_limit_n = std::numeric_limits<double>::quiet_NaN();
  // muscles.<m>.line_strength_MPa times its line's cross-section: the tension at which the
  // line breaks [N] (NaN: none given); a validation protocol refuses a rig whose line would
  // break (sim/validate/line_breaks.h)
  double line_break_n = std::numeric_limits<double>::quiet_NaN();
  // muscles.<m>.gauge.contact.*: this muscle's gauge contact, in place of the shared
  // sensors.gauge.contact (its keys the defaults); none: the shared one
  std::optional<GaugeContactParams> gauge_contact;
};

// A free body held kinematically (at rest, upright) until an event releases it.
struct HoldSpec {
  std::string key;
  std::string body;
  std::string above_site;  // held height_m above this site (its bottom, for a sphere)...
  double height_m = 0.0;
  bool at_position = false;  // ...or at position_m in the world
  std::array<double, 3> position_m{};
};

// A body's mass and/or principal moments of inertia as the scenario sets them: a mass alone
// scales the model's inertia with it; an inertia given replaces the model's (after any mass).
struct BodyMassSpec {
  std::string key;
  std::string body;
  double mass_kg = 0.0;                   // 0: the model's
  std::array<double, 3> inertia_kg_m2{};  // all 0: the model's (scaled with a new mass)
};

// joints.<joint>.*: a joint's viscous damping and dry friction (MuJoCo's damping and
// frictionloss) in place of the model's, e.g. a bearing's. A hinge's
// keys are in N m s/rad and N m, a slide's in N s/m and N; `rotational` says which were
// given. A value not given (NaN) keeps the model's.
struct JointSpec {
  std::string key;  // "joints.<joint>"
  std::string joint;
  bool rotational = true;
  double damping = std::numeric_limits<double>::quiet_NaN();
  double frictionloss = std::numeric_limits<double>::quiet_NaN();
  double start = std::numeric_limits<double>::quiet_NaN();  // its position at t = 0 [rad, m]
};

// When an event fires: at a time, or on the first physics step a condition holds; either
// only after another event has fired (`after`).
enum class ConditionKind { kTime, kContact, kJointBelow, kJointAbove, kBodyBelow };
struct ConditionSpec {
  ConditionKind kind = ConditionKind::kTime;
  double at_s = 0.0;           // kTime
  std::string body_a, body_b;  // kContact: any geom of one touches any geom of the other;
                               // kBodyBelow: body_a's origin height
  std::string joint;           // kJointBelow / kJointAbove
  double threshold = 0.0;      // SI: rad (hinge) or m (slide, body height)
  std::string after;           // another event's name, or empty
};

enum class EventAction {
  kMark,           // only records its time (e.g. the impact, for metrics)
  kRelease,        // stops holding `body`
  kAddMass,        // adds mass_kg to `body` (at its centre of mass)
  kControllerOff,  // the controller passes the schedules through
  kControllerOn,
  kEnd,  // ends the trial (status ok)
  kSet,  // gives the controller the settings `set` assigns, from this control tick on
};

struct EventSpec {
  std::string key;
  std::string name;  // unique; metrics look events up by name
  EventAction action = EventAction::kMark;
  ConditionSpec when;
  std::string body;      // kRelease, kAddMass
  double mass_kg = 0.0;  // kAddMass
  // kSet: "key=value" assignments of the controller's settings (the keys its kind lets change
  // during a trial, ControllerKind::live), each from the scenario's own settings, and the
  // controller's configuration they make, read and validated with the scenario
  std::vector<std::string> set;
  std::shared_ptr<const ControllerConfig> controller;
};

// hil.*: what `pamsim hil` does when a controller board's command comes late or not at all
// (the trial itself never reads them; scenario/scenario_hil.cc holds their rows).
enum class SafeCommand { kVent, kHold };
struct HilSpec {
  int hold_ticks = 3;                     // the last command held this many ticks, then
  SafeCommand safe = SafeCommand::kVent;  // every valve vented (0 Pa), or the last held on
  double command_timeout_s = 0.1;         // lockstep: how long the plant waits for a command
  double link_lost_s = 1.0;               // no packet for this long (wall clock): the run ends
};

struct Scenario {
  std::string path;  // the scenario file (for messages and summaries)

  std::string model_file;           // model.file
  std::string joint;                // model.joint: logged as angle/omega or position/velocity
  std::string calibration_file;     // model.calibration (optional): start angle, line lengths
  std::string pneumatics_file;      // model.pneumatics
  bool has_start_position = false;  // the joint's start [rad or m] (from the calibration);
  double start_position = 0.0;      // otherwise the model's qpos0
  // model.antagonist_deformation_mm: the calibration's two lines solved again at its start
  // angle and pressures with this pre-stretch of its antagonist, as `pamsim calibrate
  // --antagonist-deformation-mm` solves them (calibration.h); unset: the file's lines
  std::optional<double> antagonist_deformation_m;
  std::array<std::string, 2> calibrated_pair;      // the file's (agonist, antagonist)
  std::array<double, 2> calibrated_pressure_pa{};  // the pressures it was solved for

  std::uint64_t seed = 1;
  double timestep_s = 0.001;
  double duration_s = 3.0;
  double control_hz = 100.0;
  // sim.contact_soft_onset_mm: every contact's impedance rising from MuJoCo's least over this
  // penetration [m] (trial_model.cc: set_contact_onset); 0: the model's own solimp
  double contact_soft_onset_m = 0.0;

  std::vector<MuscleSpec> muscles;
  std::vector<BodyMassSpec> body_masses;
  std::vector<JointSpec> joints;
  std::vector<HoldSpec> holds;
  std::vector<EventSpec> events;

  ValveModel valve_model = ValveModel::kIso6358;
  PneumaticParams pneumatics;

  // controller.kind and its configuration (reflex/controller_registry.h lists the kinds);
  // its muscle pairs by actuator name are bound to indices by the trial model. Null: the
  // scheduled commands pass through, as with "none".
  std::string controller_kind = "none";
  std::shared_ptr<const ControllerConfig> controller;
  SensingConfig sensing;

  std::vector<std::string> metrics;  // metric sets (metrics.h), in output order
  HilSpec hil;                       // hil.*

  // The keys that may change its trial model, as its reader read them: the file's path, then
  // the document with its overrides, less the keys trial_only_key (trial_model.h) names, as
  // TOML text (scenario_file.cc). same_trial_model compares these; "" where the scenario was
  // not read from a document (it then shares no model).
  std::string model_keys;

  // The muscle with this actuator name, or nullptr.
  const MuscleSpec* muscle(const std::string& actuator) const;
  // The event with this name, or nullptr.
  const EventSpec* event(const std::string& name) const;
  // The controller's configuration as its kind's type, or nullptr if it is another kind's.
  template <typename Config>
  const Config* controller_config() const {
    return dynamic_cast<const Config*>(controller.get());
  }
  // The muscle pairs the controller names (by actuator), none without a controller.
  const std::vector<std::array<std::string, 2>>& controller_pairs() const;
  // What the controller logs per muscle and the events it records (ControllerConfig), none
  // without a controller; whether it records the event `name`.
  std::vector<ControllerChannel> controller_channels() const {
    return controller ? controller->channels() : std::vector<ControllerChannel>{};
  }
  std::vector<ControllerEvent> controller_events() const {
    return controller ? controller->events() : std::vector<ControllerEvent>{};
  }
  bool controller_records(const std::string& name) const;
};

}  // namespace pamsim
