// pam_callback.cc: see pam_callback.h.
#include "sim/core/pam_callback.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <iterator>
#include <memory>
#include <string>
#include <vector>

#include <boost/math/tools/toms748_solve.hpp>

#include "base/input_error.h"

namespace pamsim {
namespace {

constexpr int kLineSolveBits = 40;  // the line's tension to ~1e-12 relative
constexpr int kLineSolveIterations = 50;

// The PAM's law as bound (muscle_binding.h): the plant's (Pipan et al., Eq. (25), with friction;
// the slip state moved to the length asked for) or the spring law's (Eq. (1)-(5)); pull()
// is the line's pull [N] >= 0 at pressure p with the line leaving the PAM at `taut` [m],
// zero when slack, and grows with `taut`. A thread's own copy: its shape's memo and the
// relaxation's constants for the model's time step change as it is used.
struct PamLaw {
  BoundMuscleLaw bound;
  const MuscleBinding& b() const { return bound.binding; }
  mutable double step_s = 0.0;  // the relaxation's constants, for this time step
  mutable RelaxationStep relaxation_step_constants;

  const RelaxationStep& relaxation(const mjModel* m) const {
    if (m->opt.timestep != step_s) {
      step_s = m->opt.timestep;
      relaxation_step_constants = relaxation_step(b().plant.relaxation, step_s);
    }
    return relaxation_step_constants;
  }
  // The friction's input at the muscle length `length_m`: the tendon's rate (smooth), or
  // the elements as committed, moved (in `scratch`) to that length (Maxwell-slip).
  FrictionInput friction_input(const mjData* d, int id, double length_m, double* scratch) const {
    FrictionInput in;
    in.length_rate_m_per_s = d->actuator_velocity[id];
    const AvbdlFriction& f = b().plant.friction;
    if (f.model != FrictionModel::kMaxwellSlip) return in;
    const mjtNum* block = d->userdata + b().slip_block;
    std::copy(block + 1, block + 1 + f.slip.count, scratch);
    if (block[0] > 0.0) maxwell_slip_advance(f.slip, length_m - block[0], scratch);
    in.slip_state = scratch;
    return in;
  }
  // the bladder's relaxation block advanced to `length` [m] over one step, into `h`; the
  // overstresses' sum [N] (0 before the first commit); the relaxed force there into *relaxed
  double overstress(const mjModel* m, const mjData* d, double length, double* h,
                    double* relaxed_out = nullptr) const {
    const AvbdlParams& plant = b().plant;
    const mjtNum* block = d->userdata + b().relaxation_block;
    const double relaxed =
        avbdl_dbladder_energy_dlength(plant, bound.shape, std::min(length, bound.max_length_m));
    if (relaxed_out) *relaxed_out = relaxed;
    if (!(block[0] > 0.0)) {
      std::fill(h, h + plant.relaxation.count, 0.0);
      return 0.0;
    }
    return relaxation_advance(plant.relaxation, relaxation(m), block + 2, relaxed - block[1], h);
  }
  double pull(const mjModel* m, const mjData* d, int id, double p, double taut) const {
    if (b().has_plant) {
      // a slack muscle contracts to its free length and pulls nothing; the law holds up to
      // avbdl_max_length (a muscle stretched to its fibre length would have to break)
      double slip_state[kMaxSlipElements];
      const FrictionInput friction = friction_input(d, id, taut, slip_state);
      const double f = avbdl_line_pull(b().plant, bound.shape, p, taut, friction);
      if (b().plant.relaxation.count == 0 || !(f > 0.0)) return f;
      double h[kMaxRelaxationTerms];
      return std::max(f + overstress(m, d, taut, h), 0.0);
    }
    return spring_force(b().spring, p, taut - natural_length(b().spring, p));
  }
};

// Actuator `id`'s law, as this thread last copied it from the binding table: the few
// actuators a thread evaluates keep theirs, so a physics step takes no lock and derives
// nothing (and its shape's memo serves the step's muscle length with the force callback's
// static force). The copies are dropped whenever a binding is made, copied or forgotten
// (muscle_binding_epoch). Per thread, so trials on other threads share nothing mutable. An
// actuator with no binding has the law of an unbound MuscleBinding, which pulls nothing.
const PamLaw& pam_law(const mjModel* m, int id) {
  struct Entry {
    const mjModel* model = nullptr;
    int id = -1;
    PamLaw law;
  };
  thread_local std::array<Entry, 16> cache;  // two legs of eight PAMs
  thread_local std::size_t next = 0;
  thread_local std::uint64_t epoch = 0;
  const std::uint64_t now = muscle_binding_epoch();
  if (now != epoch) {
    for (Entry& e : cache) e.model = nullptr;
    epoch = now;
  }
  for (const Entry& e : cache) {
    if (e.model == m && e.id == id) return e.law;
  }
  Entry& e = cache[next++ % cache.size()];
  const std::shared_ptr<const BoundMuscleLaw> bound = find_muscle(m, id);
  e.law = PamLaw{};
  if (bound) e.law.bound = *bound;
  e.model = m;
  e.id = id;
  return e.law;
}

// The line's creep stretch [m]: L0 / (E A) g q, q the creep state (pam_callback.h); 0 for a
// line that does not creep.
double creep_stretch(const PamLaw& law, const mjData* d) {
  const LineBinding& line = law.b().line;
  if (line.creep_index < 0) return 0.0;
  return law.b().line_length_m / line.axial_stiffness_n * line.creep *
         d->userdata[line.creep_index];
}

// The line's tension [N], and in *taut the length it leaves the PAM. An inextensible line
// leaves it at tendon - L0; an extensible one, stretched by its tension and its creep, where
// F = pull(tendon - L0 - c g q - c F), c = L0 / (E A): solved on [0, pull(tendon - L0 - c g
// q)] by TOMS 748.
double line_tension(const mjModel* m, const mjData* d, int id, double* taut) {
  const PamLaw& law = pam_law(m, id);
  if (law.b().pressure_index < 0) return 0.0;  // unbound
  const double p = d->userdata[law.b().pressure_index];
  const double ea = law.b().line.axial_stiffness_n;
  const double unstretched = d->actuator_length[id] - law.b().line_length_m - creep_stretch(law, d);
  *taut = unstretched;
  const double rigid = law.pull(m, d, id, p, unstretched);
  if (ea <= 0.0 || !(rigid > 0.0)) return rigid;  // (a NaN pull is the trial's to report)
  const double c = law.b().line_length_m / ea;
  const auto residual = [&](double f) { return law.pull(m, d, id, p, unstretched - c * f) - f; };
  // the root lies in [0, rigid] when the pull grows with length; at its end (or should the
  // friction's strain term ever break that order) the tension is the inextensible pull,
  // rather than let TOMS 748 throw through MuJoCo's C frames
  const double at_rigid = residual(rigid);
  if (!(at_rigid < 0.0)) {
    *taut = unstretched - c * rigid;
    return rigid;
  }
  std::uintmax_t iterations = kLineSolveIterations;
  const auto [lo, hi] = boost::math::tools::toms748_solve(
      residual, 0.0, rigid, rigid, at_rigid,
      boost::math::tools::eps_tolerance<double>(kLineSolveBits), iterations);
  const double f = 0.5 * (lo + hi);
  *taut = unstretched - c * f;
  return f;
}
}  // namespace

bool pam_plant_from_model(const mjModel* m, int id, AvbdlParams* plant) {
  const PamLaw& law = pam_law(m, id);
  if (!law.b().has_plant) return false;
  *plant = law.b().plant;
  return true;
}

SpringModel pam_spring_from_model(const mjModel* m, int id) { return pam_law(m, id).b().spring; }

double pam_line_length(const mjModel* m, int id) { return pam_law(m, id).b().line_length_m; }

double pam_line_axial_stiffness(const mjModel* m, int id) {
  return pam_law(m, id).b().line.axial_stiffness_n;
}

int pam_userdata_index(const mjModel* m, int id) { return pam_law(m, id).b().pressure_index; }

double pam_taut_length(const mjModel* m, const mjData* d, int id) {
  const PamLaw& law = pam_law(m, id);
  const double unstretched = d->actuator_length[id] - law.b().line_length_m;
  if (law.b().line.axial_stiffness_n <= 0.0) return unstretched;
  double taut = unstretched;
  line_tension(m, d, id, &taut);
  return taut;
}

double pam_muscle_length(const mjModel* m, const mjData* d, int id, FreeLengthTrack* track) {
  return pam_muscle_length_at(m, d, id, pam_taut_length(m, d, id), track);
}

double pam_muscle_length_at(const mjModel* m, const mjData* d, int id, double taut,
                            FreeLengthTrack* track) {
  // the plant's free length is a root solve, done only when the line is slack
  const PamLaw& law = pam_law(m, id);
  if (law.b().pressure_index < 0) return taut;  // unbound
  const double p = d->userdata[law.b().pressure_index];
  if (law.b().has_plant) {
    FreeLengthTrack none;  // no last root: the whole stroke's search
    return avbdl_line_muscle_length(law.b().plant, law.bound.shape, p, taut, track ? track : &none);
  }
  return std::max(taut, natural_length(law.b().spring, p));
}

mjtNum pam_actuator_force(const mjModel* m, const mjData* d, int id) {
  double taut = 0.0;
  return -line_tension(m, d, id, &taut);
}

void pam_commit_history(const mjModel* m, mjData* d, int id, double muscle_length_m) {
  const PamLaw& law = pam_law(m, id);
  if (!law.b().has_plant) return;
  const AvbdlParams& plant = law.b().plant;
  // the muscle's own length: the line's while taut, its free length while slack
  if (plant.friction.model == FrictionModel::kMaxwellSlip) {
    mjtNum* block = d->userdata + law.b().slip_block;
    if (block[0] > 0.0) {
      maxwell_slip_advance(plant.friction.slip, muscle_length_m - block[0], block + 1);
    }
    block[0] = muscle_length_m;
  }
  if (plant.relaxation.count > 0) {
    mjtNum* block = d->userdata + law.b().relaxation_block;
    double h[kMaxRelaxationTerms], relaxed = 0.0;
    law.overstress(m, d, muscle_length_m, h, &relaxed);
    std::copy(h, h + plant.relaxation.count, block + 2);
    block[1] = relaxed;
    block[0] = muscle_length_m;
  }
}

void pam_start_line_creep(const mjModel* m, mjData* d, int id) {
  const LineBinding& line = pam_law(m, id).b().line;
  if (line.creep_index >= 0) d->userdata[line.creep_index] = line.start_tension_n;
}

double pam_taut_length_committing_creep(const mjModel* m, mjData* d, int id, double dt_s) {
  const LineBinding& line = pam_law(m, id).b().line;
  if (line.creep_index < 0) return pam_taut_length(m, d, id);
  double taut = 0.0;
  const double f = std::max(line_tension(m, d, id, &taut), 0.0);  // a slack line recovers
  double& q = d->userdata[line.creep_index];
  q = f + (q - f) * std::exp(-dt_s / line.creep_time_s);
  return taut;  // the step's length: before the state moved
}

void install_pam_actuator_callback() { mjcb_act_bias = pam_actuator_force; }

}  // namespace pamsim
