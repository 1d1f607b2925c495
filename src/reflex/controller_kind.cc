// controller_kind.cc: what a kind of controller does by default (controller_kind.h).
#include "reflex/controller_kind.h"

namespace pamsim {

std::string ControllerConfig::embedded(const ControllerSetup&, pamctl_config*) const {
  return "this controller kind has no embedded form (src/embedded/pamctl.h runs none, "
         "stretch_reflex, tension_reflex and stretch_tension_reflex)";
}

}  // namespace pamsim
