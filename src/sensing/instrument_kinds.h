// instrument_kinds.h: the instruments a scenario may build as hardware, by name, in the order
// the scenario reader reads them and the key reference lists them: the registry of sensor
// models, as reflex/controller_registry.h is the controllers'. Each kind is one row: its key
// tables bound to a SensorConfig (instrument_keys.h; the first table's first choice is its
// model, the ideal one's name first), the creep series it reads outside the rows, and its
// validate(). The scenario reader (sim/scenario/scenario_sensors.cc), the sensing's checks
// (sensing.h), `pamsim keys` and the key tests all go through this list.
//
// Adding an instrument's hardware model: its file (the struct it fills, its class, and its
// validate(), sized from a datasheet it cites), its rows in instrument_keys.cc, a field of
// SensorConfig, its row here, and where SensorSuite (sensing.cc) builds it into a muscle's
// channel. Unlike a controller, an instrument is not registered from outside the library:
// each sits at its own place in a channel's fixed sampling order (pressure, gauge, fiber),
// which fixes the noise stream and so every trial's bytes.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "base/key_table.h"
#include "sensing/sensors.h"

namespace pamsim {

struct InstrumentKind {
  std::string name;  // "pressure": its keys sensors.pressure.*
  std::string doc;   // what it is, and the file its hardware model lives in
  // its tables bound to `sensors`' fields; the first table's first choice is the model
  std::function<std::vector<KeyTable>(SensorConfig*)> key_tables;
  // its creep series (two lists, <creep_table>.creep_weights and .creep_times_s, checked by
  // prony_creep.h's rules), or "" and nullptr
  std::string creep_table;
  std::function<std::vector<PronyTerm>*(SensorConfig*)> creep;
  // its fields checked, each against its row's range, then what joins them; throws
  // InputError naming the key
  std::function<void(const SensorConfig&)> validate;
  // whose creep series it is, for its rows' docs ("the board's"); "" without one
  std::string creep_whose{};
};

// The most terms a creep series' lists may hold.
inline constexpr std::size_t kMaxCreepTerms = 64;

// <kind.creep_table>.creep_weights (each >= 0) and .creep_times_s (each > 0 s): a kind's
// creep series as two list rows bound to `weights` and `times`; the reader checks that they
// list one time per weight, and the sensing's validate() the series (prony_creep.h).
KeyTable creep_key_table(const InstrumentKind& kind, std::vector<double>* weights,
                         std::vector<double>* times);

// Every kind, in reading order: gauge, pressure, fiber, encoder.
const std::vector<InstrumentKind>& instrument_kinds();
// The kind of this name ("gauge", "pressure", "fiber", "encoder"), or nullptr.
const InstrumentKind* find_instrument_kind(const std::string& name);

}  // namespace pamsim
