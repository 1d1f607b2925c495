// controller_kind.cc: what a kind of controller does by default (controller_kind.h).
#include "reflex/controller_kind.h"

#include <stdexcept>

namespace pamsim {

std::string ControllerConfig::embedded(const ControllerSetup&, pamctl_config*) const {
  return "this controller kind has no embedded form (src/embedded/pamctl.h runs none, "
         "stretch_reflex, tension_reflex and stretch_tension_reflex)";
}

void ControllerConfig::retune(Controller&, const ControllerSetup&) const {
  throw std::logic_error("this controller kind has no settings that change during a trial");
}

}  // namespace pamsim
