// controller.h: the interface between the co-simulation loop (src/sim/core) and a controller.
// At every control tick (sim.control_hz, 100 Hz as in the paper) the loop samples every
// muscle's sensors (sensing.h) and hands the controller those readings alone, with the
// pressures the scenario's schedules command at that time (the paper's top controller,
// p_tp of Eq. (12)-(13)); the controller returns one valve command per muscle.
// Muscles are indexed in the model's actuator order. The kinds of controller (none,
// stretch_reflex, ...) are listed in controller_registry.h; what a kind is, in
// controller_kind.h.
#pragma once

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
  const std::vector<MuscleReading>* readings = nullptr;   // one per muscle
  const std::vector<double>* p_tp_pa = nullptr;           // scheduled commands, gauge [Pa]
};

struct ControlOutput {
  std::vector<double> p_cmd_pa;       // valve commands, gauge [Pa]
  std::vector<double> velocity_m_s;   // the velocity each muscle's control acted on (logged)
  std::vector<char> reflex_active;    // 1 while the muscle's stretch (Ia) window is open
  std::vector<char> tension_reflex_active;   // 1 while its tension (Ib) window is open
  void resize(int muscle_count) {
    p_cmd_pa.assign(muscle_count, 0.0);
    velocity_m_s.assign(muscle_count, 0.0);
    reflex_active.assign(muscle_count, 0);
    tension_reflex_active.assign(muscle_count, 0);
  }
};

class Controller {
 public:
  virtual ~Controller() = default;
  // Called once per control tick, in time order, starting at t = 0; `out` is sized by the
  // caller (ControlOutput::resize) and every element is written.
  virtual void update(const ControlInput& in, ControlOutput* out) = 0;
  // Reflex trigger times per muscle so far (nullptr for a controller without reflexes):
  // the stretch (Ia) reflexes', and the tension (Ib) reflexes'.
  virtual const std::vector<std::vector<double>>* trigger_times_s() const { return nullptr; }
  virtual const std::vector<std::vector<double>>* tension_trigger_times_s() const {
    return nullptr;
  }
};

}  // namespace pamsim
