// pass_through_controller.h: controller "none": the scheduled commands pass through
// unchanged; the velocity logged is the model-based estimate. Sensors are still sampled by
// the loop, so the estimates are logged (the papers' length-estimation and reaching
// experiments run without a reflex). It has no keys; the kind refuses the sections of the
// other kinds (controller_registry.h).
#pragma once

#include "reflex/controller.h"
#include "reflex/controller_kind.h"

namespace pamsim {

// The embedded controller's pass-through (PAMCTL_KIND_PASS_THROUGH): its commands are the
// schedule's, unclamped (a non-finite one vents).
class PassThroughController final : public Controller {
 public:
  // muscle_count in [0, PAMCTL_MAX_MUSCLES], else InputError
  explicit PassThroughController(int muscle_count);
  void update(const ControlInput& in, ControlOutput* out) override;

 private:
  pamctl_config embedded_{};
  pamctl_state state_{};
  pamctl_output out_{};
};

// The embedded controller's configuration of a pass-through for the setup's muscles (their
// count in [0, PAMCTL_MAX_MUSCLES], else InputError); the estimator's part is left as it is.
void embed_pass_through(const ControllerSetup& setup, pamctl_config* config);

// The kind "none" (listed in controller_registry.cc).
ControllerKind pass_through_controller_kind();

}  // namespace pamsim
