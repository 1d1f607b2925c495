// pass_through_controller.cc: see pass_through_controller.h.
#include "reflex/pass_through_controller.h"

#include <string>

#include "base/input_error.h"

namespace pamsim {

void embed_pass_through(const ControllerSetup& setup, pamctl_config* config) {
  if (setup.muscle_count < 0 || setup.muscle_count > PAMCTL_MAX_MUSCLES) {
    throw InputError("the embedded controller holds at most " + std::to_string(PAMCTL_MAX_MUSCLES) +
                     " muscles, the model has " + std::to_string(setup.muscle_count));
  }
  config->muscle_count = setup.muscle_count;
  config->kind = PAMCTL_KIND_PASS_THROUGH;
  config->control_period_s = 1.0 / setup.control_hz;
  for (int j = 0; j < PAMCTL_MAX_MUSCLES; ++j) config->partner[j] = -1;
}

namespace {

class PassThroughConfig final : public ControllerConfig {
 public:
  std::unique_ptr<Controller> make_controller(const ControllerSetup& setup) const override {
    return std::make_unique<PassThroughController>(setup.muscle_count);
  }
  std::string embedded(const ControllerSetup& setup, pamctl_config* config) const override {
    embed_pass_through(setup, config);
    return "";
  }
};

}  // namespace

PassThroughController::PassThroughController(int muscle_count) {
  ControllerSetup setup;
  setup.muscle_count = muscle_count;
  embed_pass_through(setup, &embedded_);
  pamctl_reset(&embedded_, &state_);
}

void PassThroughController::update(const ControlInput& in, ControlOutput* out) {
  // the schedule through the embedded controller; the estimate's velocity logged
  const std::vector<MuscleReading>& readings = *in.readings;
  for (std::size_t j = 0; j < readings.size(); ++j) {
    out_.estimates[j].velocity_m_s = readings[j].velocity_est_m_s;
    out_.estimates[j].flags = 0;
  }
  pamctl_control(&embedded_, &state_, in.time_s, in.enabled, in.p_tp_pa->data(), &out_);
  for (std::size_t j = 0; j < readings.size(); ++j) {
    out->p_cmd_pa[j] = out_.p_cmd_pa[j];
    out->velocity_m_s[j] = out_.velocity_m_s[j];
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
