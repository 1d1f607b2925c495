// pass_through_controller.cc: see pass_through_controller.h.
#include "reflex/pass_through_controller.h"

namespace pamsim {
namespace {

class PassThroughConfig final : public ControllerConfig {
 public:
  std::unique_ptr<Controller> make_controller(const ControllerSetup&) const override {
    return std::make_unique<PassThroughController>();
  }
};

}  // namespace

void PassThroughController::update(const ControlInput& in, ControlOutput* out) {
  const std::vector<MuscleReading>& readings = *in.readings;
  for (std::size_t j = 0; j < readings.size(); ++j) {
    out->p_cmd_pa[j] = (*in.p_tp_pa)[j];
    out->velocity_m_s[j] = readings[j].velocity_est_m_s;
    out->reflex_active[j] = 0;
    out->tension_reflex_active[j] = 0;
  }
}

ControllerKind pass_through_controller_kind() {
  ControllerKind kind;
  kind.name = "none";
  kind.read = [](ConfigReader&, const ControllerScenario&) {
    return std::make_shared<const PassThroughConfig>();
  };
  return kind;
}

}  // namespace pamsim
