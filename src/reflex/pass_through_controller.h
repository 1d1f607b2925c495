// pass_through_controller.h: controller "none": the scheduled commands pass through
// unchanged; the velocity logged is the model-based estimate. Sensors are still sampled by
// the loop, so the estimates are logged (the papers' length-estimation and reaching
// experiments run without a reflex). It has no keys; the kind refuses the sections of the
// other kinds (controller_registry.h).
#pragma once

#include "reflex/controller.h"
#include "reflex/controller_kind.h"

namespace pamsim {

class PassThroughController final : public Controller {
 public:
  void update(const ControlInput& in, ControlOutput* out) override;
};

// The kind "none" (listed in controller_registry.cc).
ControllerKind pass_through_controller_kind();

}  // namespace pamsim
