// scenario_reading.h: the parts of scenario_file.cc's reader, one per group of keys
// (internal to src/sim/io).
#pragma once

#include "sim/core/scenario.h"
#include "sim/scenario/schedule_csv.h"  // read_schedule_csv, for muscles.<m>.command.file
#include "base/config_reader.h"

namespace pamsim {

// drop.*, bodies.*, holds.*, events.* (scenario_events.cc)
// `implied`: read the drop's defaults even without a [drop] table (a pamsim 0.1 file).
void read_drop(ConfigReader& in, Scenario* sc, bool implied);
void read_bodies_and_holds(ConfigReader& in, Scenario* sc);
void read_events(ConfigReader& in, Scenario* sc);

// muscles.* with the model.<m>_params and pressure.<m>_MPa shorthands (scenario_muscles.cc)
// Without `lines_needed` (calibrate) the calibration file is not read and lines not given
// are placeholders.
void read_muscles(ConfigReader& in, Scenario* sc, bool lines_needed);

// joints.<joint>.* (scenario_joints.cc)
void read_joints(ConfigReader& in, Scenario* sc);

// sensors.*, validated with the sensing (scenario_sensors.cc); sim.control_hz read first
void read_sensors(ConfigReader& in, Scenario* sc);

}  // namespace pamsim
