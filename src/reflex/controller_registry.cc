// controller_registry.cc: see controller_registry.h. The built-in kinds are listed here,
// one line each, so that the linker keeps their object files.
#include "reflex/controller_registry.h"

#include <stdexcept>

#include "reflex/pass_through_controller.h"
#include "reflex/stretch_reflex_controller.h"

namespace pamsim {
namespace {

// built on first use, so that a ControllerRegistrar in any file finds it ready
std::vector<ControllerKind>& kinds() {
  static std::vector<ControllerKind> list = {
      pass_through_controller_kind(),
      stretch_reflex_controller_kind(),
      tension_reflex_controller_kind(),
      stretch_tension_reflex_controller_kind(),
  };
  return list;
}

}  // namespace

const std::vector<ControllerKind>& controller_kinds() { return kinds(); }

const ControllerKind* find_controller_kind(const std::string& name) {
  for (const ControllerKind& kind : kinds()) {
    if (kind.name == name) return &kind;
  }
  return nullptr;
}

const char* default_controller_kind() { return "stretch_reflex"; }

void register_controller_kind(ControllerKind kind) {
  if (!kind.read) throw std::logic_error("controller kind '" + kind.name + "' has no reader");
  if (find_controller_kind(kind.name)) {
    throw std::logic_error("controller kind '" + kind.name + "' registered twice");
  }
  kinds().push_back(std::move(kind));
}

}  // namespace pamsim
