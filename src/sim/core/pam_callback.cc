// pam_callback.cc: see pam_callback.h.
#include "sim/core/pam_callback.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <iterator>
#include <memory>
#include <string>
#include <vector>

#include <boost/math/tools/toms748_solve.hpp>

#include "base/input_error.h"

#include "sim/core/pam_slots.h"

namespace pamsim {
namespace {

using pam_slots::relaxation_block;
using pam_slots::slip_block;
using pam_slots::user_slots;

constexpr int kLineSolveBits = 40;          // the line's tension to ~1e-12 relative
constexpr int kLineSolveIterations = 50;

// The friction's input at the muscle length `length_m`: the tendon's rate (smooth), or the
// elements as committed, moved (in `scratch`) to that length (Maxwell-slip).
FrictionInput friction_input(const mjModel* m, const mjData* d, int id,
                             const AvbdlParams& plant, double length_m, double* scratch) {
  FrictionInput in;
  in.length_rate_m_per_s = d->actuator_velocity[id];
  if (plant.friction.model != FrictionModel::kMaxwellSlip) return in;
  const mjtNum* block = d->userdata + slip_block(m, id);
  std::copy(block + 1, block + 1 + plant.friction.slip.count, scratch);
  if (block[0] > 0.0) maxwell_slip_advance(plant.friction.slip, length_m - block[0], scratch);
  in.slip_state = scratch;
  return in;
}

// The PAM's law, decoded once from the actuator's slots: the plant's (seeds/003 Eq. (25)
// with friction; the slip state moved to the length asked for) or the spring law's (Eq.
// (1)-(5)); pull() is the line's pull [N] >= 0 at pressure p with the line leaving the PAM
// at `taut` [m], zero when slack, and grows with `taut`.
struct PamLaw {
  bool has_plant = false;
  AvbdlParams plant;
  AvbdlShape shape;   // the plant's, derived once
  double max_length_m = 0.0;
  SpringModel spring;
  mutable double step_s = 0.0;           // the relaxation's constants, for this time step
  mutable RelaxationStep relaxation_step_constants;

  PamLaw(const mjModel* m, int id) {
    has_plant = pam_plant_from_model(m, id, &plant);
    if (has_plant) {
      shape = avbdl_shape(plant);
      max_length_m = avbdl_max_length(plant);
    } else {
      spring = pam_spring_from_model(m, id);
    }
  }
  const RelaxationStep& relaxation(const mjModel* m) const {
    if (m->opt.timestep != step_s) {
      step_s = m->opt.timestep;
      relaxation_step_constants = relaxation_step(plant.relaxation, step_s);
    }
    return relaxation_step_constants;
  }
  // the bladder's relaxation block advanced to `length` [m] over one step, into `h`; the
  // overstresses' sum [N] (0 before the first commit); the relaxed force there into *relaxed
  double overstress(const mjModel* m, const mjData* d, int id, double length, double* h,
                    double* relaxed_out = nullptr) const {
    const mjtNum* block = d->userdata + relaxation_block(m, id);
    const double relaxed =
        avbdl_dbladder_energy_dlength(plant, shape, std::min(length, max_length_m));
    if (relaxed_out) *relaxed_out = relaxed;
    if (!(block[0] > 0.0)) {
      std::fill(h, h + plant.relaxation.count, 0.0);
      return 0.0;
    }
    return relaxation_advance(plant.relaxation, relaxation(m), block + 2, relaxed - block[1], h);
  }
  double pull(const mjModel* m, const mjData* d, int id, double p, double taut) const {
    if (has_plant) {
      // a slack muscle contracts to its free length and pulls nothing; the law holds up to
      // avbdl_max_length (a muscle stretched to its fibre length would have to break)
      double slip_state[kMaxSlipElements];
      const FrictionInput friction = friction_input(m, d, id, plant, taut, slip_state);
      const double f = avbdl_line_pull(plant, shape, p, taut, friction);
      if (plant.relaxation.count == 0 || !(f > 0.0)) return f;
      double h[kMaxRelaxationTerms];
      return std::max(f + overstress(m, d, id, taut, h), 0.0);
    }
    return spring_force(spring, p, taut - natural_length(spring, p));
  }
};

// Actuator `id`'s law, as this thread last decoded it: the few actuators a thread evaluates
// keep theirs with the slots they came from, so a physics step decodes nothing and derives
// no shape (and its shape's memo serves the step's muscle length with the force callback's
// static force); slots that differ (stored anew, or another model at the same address) are
// decoded again. Per thread, so trials on other threads share nothing.
const PamLaw& pam_law(const mjModel* m, int id) {
  struct Entry {
    const mjModel* model = nullptr;
    int id = -1;
    std::vector<mjtNum> slots;
    std::unique_ptr<PamLaw> law;
  };
  thread_local std::array<Entry, 16> cache;   // two legs of eight PAMs
  thread_local std::size_t next = 0;
  const mjtNum* u = user_slots(m, id);
  const std::size_t n = static_cast<std::size_t>(m->nuser_actuator);
  for (const Entry& e : cache) {
    if (e.model == m && e.id == id && e.slots.size() == n &&
        std::memcmp(e.slots.data(), u, n * sizeof(mjtNum)) == 0) {
      return *e.law;
    }
  }
  Entry& e = cache[next++ % cache.size()];
  e.law = std::make_unique<PamLaw>(m, id);
  e.model = m;
  e.id = id;
  e.slots.assign(u, u + n);
  return *e.law;
}

// The line's tension [N], and in *taut the length it leaves the PAM. An inextensible line
// leaves it at tendon - L0; an extensible one, stretched by its tension, where
// F = pull(tendon - L0 - c F), c = L0 / (E A): solved on [0, pull(tendon - L0)] by TOMS 748.
double line_tension(const mjModel* m, const mjData* d, int id, double* taut) {
  const double p = d->userdata[pam_userdata_index(m, id)];
  const PamLaw& law = pam_law(m, id);
  const double unstretched = d->actuator_length[id] - pam_line_length(m, id);
  const double ea = pam_line_axial_stiffness(m, id);
  *taut = unstretched;
  const double rigid = law.pull(m, d, id, p, unstretched);
  if (ea <= 0.0 || !(rigid > 0.0)) return rigid;   // (a NaN pull is the trial's to report)
  const double c = pam_line_length(m, id) / ea;
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

double pam_length(const mjModel* m, const mjData* d, int id) {
  const double unstretched = d->actuator_length[id] - pam_line_length(m, id);
  if (pam_line_axial_stiffness(m, id) <= 0.0) return unstretched;
  double taut = unstretched;
  line_tension(m, d, id, &taut);
  return taut;
}

double pam_muscle_length(const mjModel* m, const mjData* d, int id, FreeLengthTrack* track) {
  return pam_muscle_length_at(m, d, id, pam_length(m, d, id), track);
}

double pam_muscle_length_at(const mjModel* m, const mjData* d, int id, double taut,
                            FreeLengthTrack* track) {
  // the plant's free length is a root solve, done only when the line is slack
  const double p = d->userdata[pam_userdata_index(m, id)];
  const PamLaw& law = pam_law(m, id);
  if (law.has_plant) {
    FreeLengthTrack none;   // no last root: the whole stroke's search
    return avbdl_line_muscle_length(law.plant, law.shape, p, taut, track ? track : &none);
  }
  return std::max(taut, natural_length(law.spring, p));
}

mjtNum pam_actuator_force(const mjModel* m, const mjData* d, int id) {
  double taut = 0.0;
  return -line_tension(m, d, id, &taut);
}

void pam_commit_history(const mjModel* m, mjData* d, int id, double muscle_length_m) {
  const PamLaw& law = pam_law(m, id);
  if (!law.has_plant) return;
  const AvbdlParams& plant = law.plant;
  // the muscle's own length: the line's while taut, its free length while slack
  if (plant.friction.model == FrictionModel::kMaxwellSlip) {
    mjtNum* block = d->userdata + slip_block(m, id);
    if (block[0] > 0.0) {
      maxwell_slip_advance(plant.friction.slip, muscle_length_m - block[0], block + 1);
    }
    block[0] = muscle_length_m;
  }
  if (plant.relaxation.count > 0) {
    mjtNum* block = d->userdata + relaxation_block(m, id);
    double h[kMaxRelaxationTerms], relaxed = 0.0;
    law.overstress(m, d, id, muscle_length_m, h, &relaxed);
    std::copy(h, h + plant.relaxation.count, block + 2);
    block[1] = relaxed;
    block[0] = muscle_length_m;
  }
}

void install_pam_actuator_callback() { mjcb_act_bias = pam_actuator_force; }

}  // namespace pamsim
