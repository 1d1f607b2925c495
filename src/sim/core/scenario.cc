// scenario.cc: see scenario.h.
#include "sim/core/scenario.h"

namespace pamsim {

const MuscleSpec* Scenario::muscle(const std::string& actuator) const {
  for (const MuscleSpec& m : muscles) {
    if (m.actuator == actuator) return &m;
  }
  return nullptr;
}

const EventSpec* Scenario::event(const std::string& name) const {
  for (const EventSpec& e : events) {
    if (e.name == name) return &e;
  }
  return nullptr;
}

bool Scenario::controller_records(const std::string& name) const {
  for (const ControllerEvent& e : controller_events()) {
    if (e.name == name) return true;
  }
  return false;
}

const std::vector<std::array<std::string, 2>>& Scenario::controller_pairs() const {
  static const std::vector<std::array<std::string, 2>> none;
  return controller ? controller->pairs : none;
}

}  // namespace pamsim
