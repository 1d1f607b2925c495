// instrument_kinds.cc: the instruments' registry (instrument_kinds.h).
#include "sensing/instrument_kinds.h"

#include "sensing/fiber_hardware.h"
#include "sensing/gauge_hardware.h"
#include "sensing/instrument_keys.h"
#include "sensing/pressure_hardware.h"

namespace pamsim {
namespace {

std::vector<InstrumentKind> make_kinds() {
  InstrumentKind gauge{
      "gauge",
      "the strain gauge on its acrylic board in a quarter bridge, calibrated "
      "statically (gauge_hardware.h)",
      [](SensorConfig* s) { return gauge_hardware_key_tables(&s->gauge_hardware); },
      "sensors.gauge.board",
      [](SensorConfig* s) { return &s->gauge_hardware.creep; },
      [](const SensorConfig& s) { validate(s.gauge_hardware); },
      "the board's"};
  InstrumentKind pressure{
      "pressure",
      "the PSE540-class pressure sensor (pressure_hardware.h)",
      [](SensorConfig* s) {
        return std::vector<KeyTable>{pressure_hardware_key_table(&s->pressure_hardware)};
      },
      "",
      nullptr,
      [](const SensorConfig& s) { validate(s.pressure_hardware); }};
  InstrumentKind fiber{"fiber",
                       "the conductive-fabric fiber sensor (fiber_hardware.h)",
                       [](SensorConfig* s) {
                         return std::vector<KeyTable>{fiber_hardware_key_table(&s->fiber_hardware)};
                       },
                       "sensors.fiber",
                       [](SensorConfig* s) { return &s->fiber_hardware.creep; },
                       [](const SensorConfig& s) { validate(s.fiber_hardware); },
                       "the fabric's (ASSUMPTION)"};
  InstrumentKind encoder{
      "encoder",
      "the linear encoder, read in counts (sensors.h)",
      [](SensorConfig* s) { return std::vector<KeyTable>{encoder_key_table(&s->encoder)}; },
      "",
      nullptr,
      [](const SensorConfig& s) {
        EncoderConfig fields = s.encoder;
        check_key_rows(encoder_key_table(&fields));
      }};
  return {gauge, pressure, fiber, encoder};
}

}  // namespace

KeyTable creep_key_table(const InstrumentKind& kind, std::vector<double>* weights,
                         std::vector<double>* times) {
  KeyTable t{kind.creep_table, {}, {}};
  t.trial_only = true;
  const std::string none = weights->empty() ? "(none)" : "";
  t.lists = {{"creep_weights", "", 1.0, kNonNegativeRange, kMaxCreepTerms,
              kind.creep_whose + " Prony creep weights", weights, none},
             {"creep_times_s", "s", 1.0, kPositiveRange, kMaxCreepTerms,
              kind.creep_whose + " Prony retardation times, one per weight", times, none}};
  return t;
}

const std::vector<InstrumentKind>& instrument_kinds() {
  static const std::vector<InstrumentKind> kinds = make_kinds();
  return kinds;
}

const InstrumentKind* find_instrument_kind(const std::string& name) {
  for (const InstrumentKind& k : instrument_kinds()) {
    if (k.name == name) return &k;
  }
  return nullptr;
}

}  // namespace pamsim
