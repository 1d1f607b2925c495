// controller.h: the interface between the co-simulation loop (src/sim/core) and a controller.
// At every control tick (sim.control_hz, 100 Hz as in the paper) the loop samples every
// muscle's sensors (sensing.h) and hands the controller those readings alone, with the
// pressures the scenario's schedules command at that time (the paper's top controller,
// p_tp of Eq. (12)-(13)); the controller returns one valve command per muscle.
// Muscles are indexed in the model's actuator order. The kinds of controller (none,
// stretch_reflex, ...) are listed in controller_registry.h; what a kind is, in
// controller_kind.h. What a controller logs beyond its commands (a reflex its windows and
// triggers) it declares itself (ControllerChannel, ControllerEvent); the loop logs whatever
// is declared and knows no kind's words.
#pragma once

#include <string>
#include <vector>

#include "sensing/muscle_reading.h"

namespace pamsim {

// An antagonistic pair by muscle index (model order).
struct ReflexPair {
  int agonist = 0;
  int antagonist = 1;
};

struct ControlInput {
  double time_s = 0.0;
  // false while an event has switched the controller off: it then passes p_tp through
  bool enabled = true;
  const std::vector<MuscleReading>* readings = nullptr;  // one per muscle
  const std::vector<double>* p_tp_pa = nullptr;          // scheduled commands, gauge [Pa]
};

// A per-muscle quantity a controller logs at every control tick: the log's column
// <prefix><muscle label><suffix> ("reflex_ago"; a unit is the suffix, "_MPa").
struct ControllerChannel {
  std::string prefix;
  std::string suffix;
  std::string meaning;  // for the log's reference
  // a window (0 or 1: the video names the muscles whose window is open, each followed by
  // window_tag, "" or " Ib"); false: a value
  bool window = false;
  std::string window_tag;
};

// A kind of event a controller records per muscle, with its times (a reflex's triggers).
struct ControllerEvent {
  std::string name;  // "stretch_trigger"; the metric sets name what they read
  std::string meaning;
};

struct ControlOutput {
  std::vector<double> p_cmd_pa;      // valve commands, gauge [Pa]
  std::vector<double> velocity_m_s;  // the velocity each muscle's control acted on (logged)
  // each declared channel's value per muscle ([channel][muscle], the kind's order)
  std::vector<std::vector<double>> channels;
  void resize(int muscle_count, int channel_count = 0) {
    p_cmd_pa.assign(muscle_count, 0.0);
    velocity_m_s.assign(muscle_count, 0.0);
    channels.assign(channel_count, std::vector<double>(muscle_count, 0.0));
  }
};

class Controller {
 public:
  virtual ~Controller() = default;
  // Called once per control tick, in time order, starting at t = 0; `out` is sized by the
  // caller (ControlOutput::resize, with the kind's channel count) and every element is
  // written.
  virtual void update(const ControlInput& in, ControlOutput* out) = 0;
  // Each declared event's times so far, [event][muscle][k] in the kind's order (empty: none).
  virtual const std::vector<std::vector<std::vector<double>>>& event_times_s() const {
    static const std::vector<std::vector<std::vector<double>>> none;
    return none;
  }
};

}  // namespace pamsim
