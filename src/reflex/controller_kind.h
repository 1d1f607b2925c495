// controller_kind.h: what a kind of controller is to the rest of pamsim, so that a kind is
// one file. A kind (ControllerKind) has a name (controller.kind), the scenario sections it
// owns, a reader that reads and validates its keys into its configuration, and the
// documentation of those keys for `pamsim keys`. Its configuration (ControllerConfig, one
// subclass per kind) is what a Scenario holds without knowing its type: the muscle pairs it
// names, whether the trial logs reflex columns, its fields of summary.json, and the factory
// of the controller a trial runs. The kinds are listed by name in controller_registry.h.
#pragma once

#include <array>
#include <functional>
#include <memory>
#include <string>
#include <variant>
#include <vector>

#include "base/key_table.h"
#include "embedded/pamctl.h"
#include "reflex/controller.h"
#include "sensing/sensing.h"

namespace pamsim {

class ConfigReader;

// What a kind's reader may know of the scenario it reads into (read before the controller).
struct ControllerScenario {
  struct Muscle {
    std::string actuator;         // the muscle's name (the model's actuator)
    std::string key;              // its scenario key, e.g. "muscles.agonist"
    double command_max_pa = 0.0;  // the highest pressure its schedule commands [Pa]
  };
  double control_hz = 100.0;    // sim.control_hz
  double command_max_pa = 0.0;  // the regulator's command maximum [Pa]
  std::vector<Muscle> muscles;  // scenario order
};

// What a trial gives a kind's factory once the model is bound.
struct ControllerSetup {
  int muscle_count = 0;           // the model's PAM actuators
  double control_hz = 100.0;      // sim.control_hz
  std::vector<ReflexPair> pairs;  // ControllerConfig::pairs, by muscle index (model order)
};

// One field of summary.json's "scenario" object.
struct SummaryField {
  std::string key;
  std::variant<bool, double, std::string> value;
};

// A kind's configuration as read from a scenario: immutable once read (copies of a
// Scenario share it).
class ControllerConfig {
 public:
  virtual ~ControllerConfig() = default;
  // Antagonistic pairs by actuator name (the trial model binds them to indices, once).
  std::vector<std::array<std::string, 2>> pairs;
  // The low-pass its control needs on the estimated velocity and the fiber rate [Hz], 0:
  // none. The sensing applies it (SensingConfig::velocity_lowpass_hz): the scenario hands
  // it over, and validates it with the sensing.
  double velocity_lowpass_hz = SensingConfig{}.velocity_lowpass_hz;
  // What its controllers log per muscle at every tick beyond the commands (the log's columns,
  // ControlOutput::channels in this order), and the events they record
  // (Controller::event_times_s in this order).
  virtual std::vector<ControllerChannel> channels() const { return {}; }
  virtual std::vector<ControllerEvent> events() const { return {}; }
  // Appended to summary.json's "scenario" object, in this order.
  virtual std::vector<SummaryField> summary_fields() const { return {}; }
  // A new controller for one trial.
  virtual std::unique_ptr<Controller> make_controller(const ControllerSetup& setup) const = 0;
  // Gives `controller`, one this kind made for `setup`, these settings from its next tick,
  // its state (filters, windows, triggers so far) kept: a scenario's `set` event, a slider
  // of `pamsim view`. A kind without settings that change during a trial (ControllerKind::
  // live empty) is never asked.
  virtual void retune(Controller& controller, const ControllerSetup& setup) const;
  // Its part of the embedded controller's configuration (src/embedded/pamctl.h: kind,
  // settings, pairs) into `config`, whose estimator part the sensing fills; "" when done,
  // else the one-line reason this kind has no embedded form.
  virtual std::string embedded(const ControllerSetup& setup, pamctl_config* config) const;
};

// A setting a kind lets change during a trial (a scenario's `set` event, a slider of `pamsim
// view`): its scenario key (whose row gives its unit and range) and the span a slider shows,
// in the key's unit.
struct LiveSetting {
  std::string key;
  double slider_min = 0.0;
  double slider_max = 1.0;
};

// One key of a kind for `pamsim keys`: the key reference's own row (base/key_table.h).
using ControllerKeyDoc = KeyDoc;

struct ControllerKind {
  std::string name;  // controller.kind
  // tables of its own ("reflex"): a scenario that chooses another kind may not give them
  std::vector<std::string> sections;
  // Reads and validates the kind's keys. Throws InputError "<file>: <key> <problem>".
  std::function<std::shared_ptr<const ControllerConfig>(ConfigReader& in,
                                                        const ControllerScenario& scenario)>
      read;
  std::vector<ControllerKeyDoc> docs;  // its keys, in the order `pamsim keys` lists them
  // the settings that may change during a trial; the others (its sensor, pairs, filters)
  // shape what the trial logs and senses and hold for the whole trial
  std::vector<LiveSetting> live{};
};

}  // namespace pamsim
