// controller_registry.h: the kinds of controller a scenario may choose by controller.kind,
// by name, in registration order: the built-in kinds ("none", "stretch_reflex",
// "tension_reflex", "stretch_tension_reflex"), listed in
// controller_registry.cc, then any registered by a ControllerRegistrar.
//
// Why the built-in kinds are a list and not self-registering: the reflex library is a
// static library, and the linker takes from it only the object files something references;
// a kind's file that registered itself with a static object, and that nothing else names,
// would be dropped from pamsim and its registration would never run. The list references
// each kind's function, so every built-in kind is linked wherever the registry is. A kind
// outside the library (a test, an experiment's own controller) is an object file linked
// into its program directly, which the linker always keeps: there a static
// ControllerRegistrar registers it before main().
#pragma once

#include <string>
#include <vector>

#include "reflex/controller_kind.h"

namespace pamsim {

// Every kind, in registration order.
const std::vector<ControllerKind>& controller_kinds();
// The kind of this name, or nullptr.
const ControllerKind* find_controller_kind(const std::string& name);
// controller.kind when a scenario does not say.
const char* default_controller_kind();

// Adds a kind. Throws std::logic_error if its name is taken or it has no reader. Call it
// before any scenario is read or `pamsim keys` listed (at static initialisation, as
// ControllerRegistrar does): the list is not locked, and the key docs are built once.
void register_controller_kind(ControllerKind kind);

// Registers a kind at static initialisation: `static ControllerRegistrar r{my_kind()};` at
// namespace scope of a file linked into the program (not into a static library).
struct ControllerRegistrar {
  explicit ControllerRegistrar(ControllerKind kind) { register_controller_kind(std::move(kind)); }
};

}  // namespace pamsim
