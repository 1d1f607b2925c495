// instrument_keys.h: the instruments as hardware, their scenario keys as rows
// (base/key_table.h) bound to the structs they fill: the gauge on its board in its bridge
// (sensors.gauge, .gauge.board, .gauge.contact, .gauge.calibration; gauge_hardware.h), the
// pressure sensor (sensors.pressure; pressure_hardware.h), the fabric fiber sensor
// (sensors.fiber; fiber_hardware.h) and the encoder (sensors.encoder; sensors.h). Each key's
// name with its unit, factor to SI, range, default (the struct's own) and meaning is one row,
// which the scenario reader, the structs' validate(), `pamsim keys` and the tests read.
// Outside the rows: the creep series (two lists, creep_weights and creep_times_s, read and
// checked by prony_creep.h's rules); sensors.instrument_seed is a row of sensors.* (sensor_keys.h).
//
// Each instrument's first table has its "model" choice first: its ideal name, then its
// hardware name; with the ideal model the instrument's other keys are refused (the reader).
#pragma once

#include <vector>

#include "base/key_table.h"
#include "sensing/sensors.h"

namespace pamsim {

// sensors.gauge (the model and the bridge), sensors.gauge.board, sensors.gauge.contact,
// sensors.gauge.calibration, bound to `gauge`. validate(GaugeHardwareConfig) adds what joins
// keys (the contact beyond the gauge, the board's end, its strain at the calibration's load).
std::vector<KeyTable> gauge_hardware_key_tables(GaugeHardwareConfig* gauge);
// sensors.gauge.contact.* alone (one of the tables above), bound to `contact`: a muscle's own
// contact reads it under muscles.<actuator>.gauge.contact (the scenario's reader renames it).
KeyTable gauge_contact_key_table(GaugeContactParams* contact);

// sensors.pressure, bound to `pressure`.
KeyTable pressure_hardware_key_table(PressureHardwareConfig* pressure);

// sensors.fiber, bound to `fiber` (its creep lists aside).
KeyTable fiber_hardware_key_table(FiberHardwareConfig* fiber);

// sensors.encoder, bound to `encoder`.
KeyTable encoder_key_table(EncoderConfig* encoder);

// Every instrument's tables, bound to `sensors`' instruments, in the registry's order
// (instrument_kinds.h): the reference's list and the tests' (one row a key, a bad value per
// row).
std::vector<KeyTable> instrument_key_tables(SensorConfig* sensors);

}  // namespace pamsim
