// scenario_key_tables.h: the scenario's own tables as key-table rows (base/key_table.h): [sim],
// trial's time, [drop], the falling-mass shorthand's numbers, [valve], a rig's own point of
// the pneumatics file's supply, command range and regulator, bodies.<body>, holds.<body> and
// joints.<joint>. Each key's unit, range,
// default and meaning is one row, which the reader (scenario_file.cc, scenario_events.cc),
// `pamsim keys` and the tests read. What joins keys stays with the reader: a control rate
// that divides the physics rate, the steps a trial takes, a drop before the trial's end.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "base/key_table.h"
#include "sim/core/scenario.h"

namespace pamsim {

// The most physics steps a trial may take unless sim.max_steps says more: an hour at 0.5 ms.
// A mistyped time step (1e-9 s) would otherwise run for days, or (1e-308 s) for an
// uncountable number of steps.
inline constexpr double kDefaultMaxSteps = 1e7;

// The scenario's own top-level keys that are values (seed), bound to `scenario`.
KeyTable top_level_key_table(Scenario* scenario);

// `metrics`, the metric sets of a trial's summary (sim/core/metrics.h: metric_set_names),
// bound to `scenario`'s list; its default depends on the experiment, so the reader sets it
// after the drop and the controller are read.
KeyTable metrics_key_table(Scenario* scenario);

// [sim], bound to `scenario`'s time step, duration and control rate and to `max_steps` (read
// to check the trial's length, not kept).
KeyTable sim_key_table(Scenario* scenario, double* max_steps);

// The drop shorthand's numbers (drop.*; its body, basket and site are names the reader
// takes as they are): the mass held above the basket floor and released.
struct DropShorthand {
  bool enabled = true;
  double mass_kg = 0.2;
  double height_m = 0.14;
  double time_s = 1.0;
  std::string body = "ball";  // the model's names it uses (checked when bound)
  std::string basket = "basket";
  std::string site = "basket_floor";
};

// [drop], bound to `drop`.
KeyTable drop_key_table(DropShorthand* drop);

// [model]: the model file, the joint, the calibration and pneumatics files (paths relative to
// the scenario's folder), bound to `scenario`.
KeyTable model_key_table(Scenario* scenario);

// controller.kind, bound to `kind`: one of the registered kinds' names
// (reflex/controller_registry.h).
KeyTable controller_kind_key_table(std::string* kind);

// valve.model, bound to `scenario`'s valve model: read first, as it decides which of [valve]'s
// other keys a scenario may give.
KeyTable valve_model_key_table(Scenario* scenario);

// [valve]'s numbers and choices (valve.model, a name of the reader's, aside): the pneumatics
// file's own rows (pneumatic_params.h), bound to `pneumatics`, so that a scenario or a sweep
// axis picks a point of the file's bracket by the file's rows. Two tables, both "valve": a
// rig's supply and command range ([supply].supply_MPa, [valve].command_max_MPa), then every
// [regulator] row, which valve.model = "regulator" must accompany (another valve model would
// ignore them).
std::vector<KeyTable> valve_key_tables(PneumaticParams* pneumatics);

// bodies.<body>: what a scenario gives of a body (BodyMassSpec): its mass, and its principal
// moments of inertia [I1, I2, I3], each in place of the model's (unset: the model's). The
// reader checks what joins them: three moments, each at most the sum of the others.
struct BodyKeys {
  std::optional<double> mass_kg;
  std::vector<double> inertia_kg_m2;
};
// bodies.<body> (a placeholder the reader replaces with the body's name), bound to `body`.
KeyTable body_key_table(BodyKeys* body);

// A muscle's line keys (muscles.<actuator>.*), SI inside: its length, and for an extensible
// line its diameter, its material's modulus and its creep; its working load. The reader
// checks what joins them (line or line_mm; diameter and modulus both or neither; a creep
// only on an extensible line; the load only with the tension metrics).
struct MuscleLineKeys {
  std::optional<double> line_m, diameter_m, modulus_pa, limit_n, strength_pa;
};
// muscles.<actuator> (a placeholder the reader replaces with the muscle's name), bound to
// `line`, and the line's creep straight to `muscle`'s fields (their defaults are its own).
KeyTable muscle_line_key_table(MuscleLineKeys* line, MuscleSpec* muscle);

// muscles.<actuator>'s parameter file (params; the reader renames the row for the shorthand
// model.<actuator>_params), its name in columns (label) and the joints its tendon must cross
// (spans), bound to `muscle`; the reader sets the label's default (the actuator's name) first.
KeyTable muscle_name_key_table(MuscleSpec* muscle);
// The shorthand model.<actuator>_params (pamsim 0.1 files): muscle_name_key_table's params
// row, renamed (`actuator` may be the placeholder "<actuator>").
KeyTable params_shorthand_key_table(MuscleSpec* muscle, const std::string& actuator);

// events.<event> and events.<event>.when (placeholders a reader replaces with the event's
// key), bound to `event`; `thresholds` holds the when.* numbers that set its condition's kind
// and threshold (below_deg, above_deg, below_mm, above_mm, below_z_m, SI) and when.contact's
// bodies. A reader reads only the rows its action and its condition use (mass_kg with
// add_mass, a threshold with when.joint), so a key given beside the wrong ones is refused as
// unknown.
struct EventThresholds {
  std::optional<double> below_rad, above_rad, below_m, above_m, below_z_m;
  std::vector<std::string> contact;  // when.contact's two bodies
};
KeyTable event_key_table(EventSpec* event);
KeyTable event_when_key_table(EventSpec* event, EventThresholds* thresholds);

// holds.<body> (a placeholder, as above), bound to `hold`'s site and height and to
// `position_m`, the fixed position [x, y, z] given instead (the reader: one or the other).
KeyTable hold_key_table(HoldSpec* hold, std::vector<double>* position_m);

// joints.<joint> (its table name "joints.<joint>", a placeholder a reader replaces with the
// joint's name), bound to `joint`: a hinge's damping, friction loss and start angle, or a
// slide's (their units in their names). Each is optional (NaN: the model's own).
KeyTable hinge_key_table(JointSpec* joint);
KeyTable slide_key_table(JointSpec* joint);

}  // namespace pamsim
