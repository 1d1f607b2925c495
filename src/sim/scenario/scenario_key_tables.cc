// scenario_key_tables.cc: the rows of [sim], [drop], [valve], bodies, holds and joints (see
// scenario_key_tables.h).
#include "sim/scenario/scenario_key_tables.h"

#include <cassert>
#include <limits>
#include <utility>

#include "base/units.h"
#include "pneumatics/chamber_ode.h"
#include "pneumatics/pneumatic_params.h"
#include "reflex/controller_registry.h"
#include "sim/core/metrics.h"

namespace pamsim {

KeyTable top_level_key_table(Scenario* scenario) {
  KeyTable t{"", {}, {}, {}};
  t.ints = {int_row("seed",
                    "the trial's random seed (sensor noise); trial k of --trials uses seed + k", 0,
                    std::numeric_limits<std::int64_t>::max(), &scenario->seed)};
  t.ints[0].trial_only = true;  // the sensors' noise
  return t;
}

KeyTable metrics_key_table(Scenario* scenario) {
  KeyTable t{"", {}, {}, {}};
  t.name_lists = {{"metrics", metric_set_names(), "the metric sets in summary.json",
                   &scenario->metrics,
                   "(drop: [\"drop\", \"reflex\", \"length_estimate\"]; else [\"tracking\", "
                   "\"length_estimate\"], and \"reflex\" with a reflex controller)"}};
  return t;
}

KeyTable sim_key_table(Scenario* scenario, double* max_steps) {
  constexpr double inf = std::numeric_limits<double>::infinity();
  KeyTable t{"sim", {}, {}, {}};
  t.numbers = {
      {"timestep_s", "s", 1.0, {0.0, 0.01, true, false}, "physics step", &scenario->timestep_s},
      {"duration_s",
       "s",
       1.0,
       {0.0, 3600.0, true, false},
       "simulated time of a trial (after every timed event)",
       &scenario->duration_s},
      {"control_hz",
       "Hz",
       1.0,
       {0.0, inf, true, false},
       "control, sensing and logging rate, a whole divisor of 1 / sim.timestep_s",
       &scenario->control_hz},
      {"max_steps",
       "",
       1.0,
       {1.0, 1e10, false, false},
       "the most physics steps a trial may take (at least duration_s / timestep_s)",
       max_steps},
      {"contact_soft_onset_mm",
       "mm",
       1e-3,
       {0.0, 10.0, false, false},
       "penetration over which every contact's impedance rises from MuJoCo's least to the "
       "model's (solimp's dmin and width), so that a contact's force starts at 0; 0: the "
       "model's solimp",
       &scenario->contact_soft_onset_m}};
  for (NumberRow& row : t.numbers) {  // the step and the contacts are the model's
    row.trial_only = row.name != "timestep_s" && row.name != "contact_soft_onset_mm";
  }
  return t;
}

KeyTable drop_key_table(DropShorthand* drop) {
  KeyTable t{"drop", {}, {}, {}};
  t.bools = {{"enabled", "shorthand: drop the mass at drop.time_s", &drop->enabled}};
  t.numbers = {{"mass_kg",
                "kg",
                1.0,
                {0.0, 10.0, true, false},
                "shorthand: the falling mass",
                &drop->mass_kg},
               {"height_m",
                "m",
                1.0,
                {0.0, 1.0, false, false},
                "shorthand: its fall height above the basket floor",
                &drop->height_m},
               {"time_s",
                "s",
                1.0,
                {0.0, 3600.0, false, true},
                "shorthand: when it is released, before sim.duration_s",
                &drop->time_s}};
  // the release (its time and height) is the trial's; the mass and bodies the model's
  for (NumberRow& row : t.numbers) row.trial_only = row.name != "mass_kg";
  t.texts = {{"body", "shorthand: the falling body, a free body of the model", &drop->body},
             {"basket", "shorthand: the body it lands in (the impact event), a body of the model",
              &drop->basket},
             {"site", "shorthand: the site it is held above, a site of the model", &drop->site}};
  return t;
}

KeyTable model_key_table(Scenario* scenario) {
  KeyTable t{"model", {}, {}, {}};
  TextRow file{"file", "the arm's MuJoCo model (MJCF)", &scenario->model_file};
  TextRow calibration{"calibration",
                      "start_angle_deg and <actuator>_line_mm (pamsim calibrate; pamsim keys "
                      "--calibration)",
                      &scenario->calibration_file};
  TextRow pneumatics{"pneumatics",
                     "valve and chamber parameters (models/pams/pneumatics.toml; pamsim keys "
                     "--pneumatics)",
                     &scenario->pneumatics_file};
  file.input_file = calibration.input_file = pneumatics.input_file = true;
  file.required = pneumatics.required = true;
  pneumatics.trial_only = true;  // the valves and chambers are the trial's
  t.numbers = {{"antagonist_deformation_mm",
                "mm",
                units::kMPerMm,
                {0.0, 100.0, true, false},
                "the lines' pre-tension: model.calibration's two lines solved again at its "
                "start angle and pressures with its antagonist this far past its free length "
                "(as pamsim calibrate --antagonist-deformation-mm)",
                nullptr,
                &scenario->antagonist_deformation_m,
                false,
                "(model.calibration's lines as written)"}};
  t.texts = {file,
             {"joint", "the joint logged and measured, a hinge or slide joint of the model",
              &scenario->joint, "(the model's first hinge or slide joint)"},
             calibration,
             pneumatics};
  return t;
}

KeyTable controller_kind_key_table(std::string* kind) {
  std::vector<std::string> names;
  for (const ControllerKind& k : controller_kinds()) names.push_back(k.name);
  return KeyTable{"controller",
                  {},
                  {{"kind", names, "the controller", [kind](const std::string& v) { *kind = v; },
                    [kind] { return *kind; }}}};
}

KeyTable valve_model_key_table(Scenario* scenario) {
  KeyTable t{"valve", {}, {valve_model_row("model", &scenario->valve_model)}};
  t.trial_only = true;
  return t;
}

std::vector<KeyTable> valve_key_tables(PneumaticParams* pneumatics) {
  // the supply and the command range, as the file's [supply] and [valve] give them
  const auto file_row = [&](const std::string& table, const std::string& name) {
    for (const KeyTable& file_table : pneumatic_key_table(pneumatics)) {
      for (const NumberRow& row : file_table.numbers) {
        if (file_table.name == table && row.name == name) return row;
      }
    }
    assert(false && "valve_key_tables: no such row of the pneumatics file");
    return NumberRow{};
  };
  KeyTable rig{
      "valve", {file_row("supply", "supply_MPa"), file_row("valve", "command_max_MPa")}, {}};
  KeyTable regulator = pneumatic_regulator_table(pneumatics);
  regulator.name = "valve";
  rig.trial_only = regulator.trial_only = true;  // the valves are the trial's
  return {rig, regulator};
}

KeyTable body_key_table(BodyKeys* body) {
  KeyTable t{"bodies.<body>", {}, {}, {}};
  t.numbers = {{"mass_kg",
                "kg",
                1.0,
                {0.0, 1000.0, true, false},
                "a body's mass, in place of the model's (its inertia scaled with it)",
                nullptr,
                &body->mass_kg,
                false,
                "(the model's)"}};
  t.lists = {{"inertia_kg_m2",
              "kg m^2",
              1.0,
              {0.0, 1000.0, true, false},
              3,
              "a body's principal moments of inertia [I1, I2, I3] about its centre of mass, in "
              "place of the model's; each at most the sum of the others",
              &body->inertia_kg_m2,
              "(the model's)",
              3}};
  return t;
}

// clang-format off
KeyTable muscle_line_key_table(MuscleLineKeys* line, MuscleSpec* muscle) {
  KeyTable t{"muscles.<actuator>", {}, {}, {}};
  t.numbers = {
      {"line_mm", "mm", units::kMPerMm, kPositiveRange,
       "the fishing line's length (at the start, under its tension)", nullptr, &line->line_m,
       false, "(model.calibration's)"},
      {"line_diameter_mm", "mm", units::kMPerMm, {0.0, 10.0, true, false},
       "the fishing line's diameter, with line_modulus_MPa: it stretches by its tension over "
       "E A", nullptr, &line->diameter_m, false, "(none: inextensible)"},
      {"line_modulus_MPa", "MPa", units::kPaPerMPa, {0.0, 1e6, true, false},
       "the line material's Young's modulus E, with line_diameter_mm", nullptr,
       &line->modulus_pa, false, "(none: inextensible)"},
      {"line_creep", "", 1.0, {0.0, 10.0, false, false},
       "an extensible line's creep: its long-term stretch per unit elastic stretch, one "
       "Kelvin-Voigt element (nylon monofilament 0.05-0.3, PE braid 0-0.05)", &muscle->line_creep},
      {"line_creep_time_s", "s", 1.0, {0.0, 1e6, true, false},
       "that creep's retardation time (an extensible line)", &muscle->line_creep_time_s},
      {"line_limit_N", "N", 1.0, {0.0, 1e5, true, false},
       "the line's working load: the tension metrics give the peak pull in per cent of it",
       nullptr, &line->limit_n, false, "(none)"},
      {"line_strength_MPa", "MPa", units::kPaPerMPa, {0.0, 1e5, true, false},
       "the line material's tensile strength, with line_diameter_mm: its break load (the "
       "tension metrics' line_break_load_<m>_pct; pamsim run warns where the pull passes it, "
       "and a validation rig whose line would is refused); nylon monofilament 560-920",
       nullptr, &line->strength_pa, false, "(none: it does not break)"}};
  t.choices = {{"line",
                {"fixed", "equilibrium"},
                "where the line's length comes from: fixed (line_mm, or model.calibration's) or "
                "solved so that the start is static (equilibrium, one muscle at most)",
                [muscle](const std::string& v) {
                  muscle->line = v == "equilibrium" ? LineSource::kEquilibrium : LineSource::kFixed;
                },
                [muscle] {
                  return std::string(muscle->line == LineSource::kEquilibrium ? "equilibrium"
                                                                               : "fixed");
                }}};
  return t;
}
// clang-format on

KeyTable muscle_name_key_table(MuscleSpec* muscle) {
  KeyTable t{"muscles.<actuator>", {}, {}, {}};
  t.texts = {
      {"label", "the muscle's name in columns and metrics: no spaces, commas or quotes; unique",
       &muscle->label, "(the actuator's name)"},
      {"params", "the estimator's spring model: a PAM parameter file (models/pams/...)",
       &muscle->params_file, "(required)", true, true}};
  t.name_lists = {{"spans",
                   {},
                   "the joints of the model its tendon must cross: refused if its path misses "
                   "one (no moment arm at the start)",
                   &muscle->spans,
                   "(not checked)"}};
  return t;
}

KeyTable params_shorthand_key_table(MuscleSpec* muscle, const std::string& actuator) {
  return as_shorthand(rows_named(muscle_name_key_table(muscle), {"params"}), "model",
                      actuator + "_params", "muscles.<actuator>.params (pamsim 0.1 files)");
}

KeyTable event_key_table(EventSpec* event) {
  static const std::vector<std::pair<std::string, EventAction>> kActions = {
      {"mark", EventAction::kMark},
      {"release", EventAction::kRelease},
      {"add_mass", EventAction::kAddMass},
      {"controller_off", EventAction::kControllerOff},
      {"controller_on", EventAction::kControllerOn},
      {"end", EventAction::kEnd},
      {"set", EventAction::kSet}};
  std::vector<std::string> names;
  for (const auto& [name, action] : kActions) names.push_back(name);
  KeyTable t{"events.<event>", {}, {}, {}};
  t.choices = {{"action", names, "what happens when the event fires",
                [event](const std::string& v) {
                  for (const auto& [name, action] : kActions) {
                    if (name == v) event->action = action;
                  }
                },
                [event] {
                  for (const auto& [name, action] : kActions) {
                    if (action == event->action) return name;
                  }
                  return std::string("?");
                }}};
  t.numbers = {{"mass_kg",
                "kg",
                1.0,
                {0.0, 1000.0, true, false},
                "with add_mass: the mass added",
                &event->mass_kg,
                nullptr,
                true}};
  t.texts = {{"body", "with release or add_mass: the body released or loaded", &event->body},
             {"after", "fire only after this other event", &event->when.after}};
  t.name_lists = {{"set",
                   {},
                   "with set: the controller's settings from then on, [\"key=value\", ...] as "
                   "--set gives them (the keys `pamsim keys` marks live; the others keep the "
                   "scenario's values)",
                   &event->set}};
  return t;
}

KeyTable event_when_key_table(EventSpec* event, EventThresholds* thresholds) {
  constexpr double inf = std::numeric_limits<double>::infinity();
  const double per_deg = units::deg_to_rad(1.0);  // rad per degree, as the reader converts
  KeyTable t{"events.<event>.when", {}, {}, {}};
  t.numbers = {
      {"at_s",
       "s",
       1.0,
       {0.0, inf, false, true},
       "fire at this time (before sim.duration_s)",
       &event->when.at_s},
      {"below_deg", "deg", per_deg, kAnyRange, "with when.joint, a hinge: fire below this angle",
       nullptr, &thresholds->below_rad},
      {"above_deg", "deg", per_deg, kAnyRange, "with when.joint, a hinge: fire above this angle",
       nullptr, &thresholds->above_rad},
      {"below_mm", "mm", units::kMPerMm, kAnyRange,
       "with when.joint, a slide: fire below this position", nullptr, &thresholds->below_m},
      {"above_mm", "mm", units::kMPerMm, kAnyRange,
       "with when.joint, a slide: fire above this position", nullptr, &thresholds->above_m},
      {"below_z_m", "m", 1.0, kAnyRange,
       "with when.body: fire when its origin is below this height", nullptr, &thresholds->below_z_m,
       true}};
  t.texts = {{"joint", "fire on this joint's position (with one threshold)", &event->when.joint},
             {"body", "fire on this body's height (with below_z_m)", &event->when.body_a}};
  t.name_lists = {{"contact",
                   {},
                   "fire when the two bodies touch: [body_a, body_b]",
                   &thresholds->contact,
                   "(one when.* is required)"}};
  return t;
}

KeyTable hold_key_table(HoldSpec* hold, std::vector<double>* position_m) {
  constexpr double inf = std::numeric_limits<double>::infinity();
  KeyTable t{"holds.<body>", {}, {}, {}};
  t.numbers = {{"height_m",
                "m",
                1.0,
                {0.0, 10.0},
                "with above_site: the held body's bottom "
                "above the site",
                &hold->height_m}};
  t.texts = {{"above_site", "hold the body above this site of the model until released",
              &hold->above_site}};
  t.lists = {{"position_m",
              "m",
              1.0,
              {-inf, inf},
              3,
              "hold the body at [x, y, z] in the world instead (not with above_site)",
              position_m,
              "(none)",
              3}};
  return t;
}

KeyTable hinge_key_table(JointSpec* joint) {
  KeyTable t{"joints.<joint>", {}, {}, {}};
  t.numbers = {{"damping_N_m_s_per_rad",
                "N m s/rad",
                1.0,
                {0.0, 1e4, false, false},
                "the hinge's viscous damping (MuJoCo damping), e.g. a bearing's",
                &joint->damping},
               {"frictionloss_N_m",
                "N m",
                1.0,
                {0.0, 1e4, false, false},
                "the hinge's dry friction torque (MuJoCo frictionloss)",
                &joint->frictionloss},
               {"start_deg",
                "deg",
                units::deg_to_rad(1.0),
                {-360.0, 360.0, false, false},
                "the hinge's angle at the start",
                &joint->start}};
  return t;
}

KeyTable slide_key_table(JointSpec* joint) {
  KeyTable t{"joints.<joint>", {}, {}, {}};
  t.numbers = {{"damping_N_s_per_m",
                "N s/m",
                1.0,
                {0.0, 1e6, false, false},
                "the slide's viscous damping (MuJoCo damping)",
                &joint->damping},
               {"frictionloss_N",
                "N",
                1.0,
                {0.0, 1e6, false, false},
                "the slide's dry friction force (MuJoCo frictionloss)",
                &joint->frictionloss},
               {"start_mm",
                "mm",
                units::mm_to_m(1.0),
                {-1e4, 1e4, false, false},
                "the slide's position at the start",
                &joint->start}};
  return t;
}

}  // namespace pamsim
