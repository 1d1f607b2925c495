// scenario_sensors.cc: sensors.* (noise, ADCs, low-pass: the rows of sensing/sensor_keys.h)
// and the sensors as hardware, sensors.gauge.*, .pressure.*, .fiber.*, .encoder.* (the rows
// of sensing/instrument_keys.h), with the creep series; sensors.instrument_seed is a row; a
// muscle's own gauge contact, muscles.<m>.gauge.contact.* (the contact's rows renamed).
// Validated with the sensing (sensing/sensing.h).
#include <algorithm>
#include <cstdint>
#include <string>
#include <vector>

#include "base/input_error.h"
#include "base/key_table.h"
#include "sensing/instrument_keys.h"
#include "sensing/instrument_kinds.h"
#include "sensing/sensor_keys.h"
#include "sim/scenario/scenario_reading.h"

namespace pamsim {
namespace {

// a kind's Prony series from its two list rows (instrument_kinds.h), one time per weight
std::vector<PronyTerm> read_creep(ConfigReader& in, const InstrumentKind& kind,
                                  const std::vector<PronyTerm>& fallback) {
  std::vector<double> weights, times;
  prony_lists(fallback, &weights, &times);
  read_key_rows(in, creep_key_table(kind, &weights, &times));
  in.check(weights.size() == times.size(), kind.creep_table + ".creep_times_s",
           "must list one time per weight (" + std::to_string(weights.size()) + "), got " +
               std::to_string(times.size()));
  std::vector<PronyTerm> creep;
  for (std::size_t i = 0; i < weights.size(); ++i) creep.push_back({weights[i], times[i]});
  return creep;
}

// An instrument's tables (instrument_keys.h), its model the first table's first choice (the
// ideal name, then the hardware one): with the ideal model, every other key under the first
// table's name is refused, since the ideal model would ignore it (as the valve's regulator
// keys are); then each table by its rows.
void read_instrument(ConfigReader& in, const std::vector<KeyTable>& tables) {
  const KeyTable& first = tables.front();
  const ChoiceRow& model = first.choices.front();
  read_key_rows(in, KeyTable{first.name, {}, {model}, {}});
  const std::string prefix = first.name + ".";
  if (model.get() == model.allowed.front()) {
    for (const std::string& key : in.leaf_keys()) {
      if (key.rfind(prefix, 0) != 0 || key == prefix + model.name) continue;
      in.check(false, key,
               "is used only by " + prefix + model.name + " = \"" + model.allowed.back() +
                   "\", not \"" + model.allowed.front() + "\"");
    }
  }
  for (const KeyTable& table : tables) read_key_rows(in, table);
}

// the instruments as hardware, in the registry's order (instrument_kinds.h): their rows and
// creep series (their seed is a row of sensors.*)
void read_instruments(ConfigReader& in, SensorConfig* s) {
  for (const InstrumentKind& kind : instrument_kinds()) {
    read_instrument(in, kind.key_tables(s));
    if (kind.creep) *kind.creep(s) = read_creep(in, kind, *kind.creep(s));
  }
}

// The gauge's checks of a muscle's own contact (gauge_hardware.h: the re-seated line on the
// board), a refusal of a sensors.gauge.contact key renamed to the muscle's
void validate_own_contact(ConfigReader& in, const GaugeHardwareConfig& own,
                          const std::string& prefix) {
  const std::string shared = "sensors.gauge.contact.";
  try {
    validate(own);
  } catch (const InputError& e) {
    if (e.parts().key.rfind(shared, 0) != 0) throw;
    in.fail(prefix + "." + e.parts().key.substr(shared.size()), e.parts().problem);
  }
}

// muscles.<m>.gauge.contact.*: a muscle's own gauge contact (one gauge's line laid otherwise
// than the other's), the shared sensors.gauge.contact its defaults; a bridge gauge's only
void read_muscle_contacts(ConfigReader& in, Scenario* sc) {
  const GaugeHardwareConfig& shared = sc->sensing.sensors.gauge_hardware;
  const std::vector<std::string> leaves = in.leaf_keys();
  for (MuscleSpec& m : sc->muscles) {
    const std::string prefix = m.key + ".gauge.contact";
    const auto given = std::find_if(leaves.begin(), leaves.end(), [&](const std::string& k) {
      return k.rfind(prefix + ".", 0) == 0;
    });
    if (given == leaves.end()) continue;
    in.check(shared.enabled, *given, "is used only by sensors.gauge.model = \"bridge\"");
    GaugeHardwareConfig own = shared;
    KeyTable rows = gauge_contact_key_table(&own.contact);
    rows.name = prefix;
    read_key_rows(in, rows);
    validate_own_contact(in, own, prefix);
    m.gauge_contact = own.contact;
  }
}

}  // namespace

void read_sensors(ConfigReader& in, Scenario* sc) {
  SensorConfig& s = sc->sensing.sensors;
  read_key_rows(in, sensor_key_table(&s));  // sensors.*: noise, ADCs, the pressure low-pass
  read_instruments(in, &s);
  read_muscle_contacts(in, sc);
  sc->sensing.control_hz = sc->control_hz;  // velocity_lowpass_hz: the controller's config
  sc->sensing.physics_dt_s = sc->timestep_s;
  in_file(in, [&] {
    validate(sc->sensing);
    return 0;
  });
}

}  // namespace pamsim
