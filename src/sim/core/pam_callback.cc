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

namespace pamsim {
namespace {

constexpr int kLineSolveBits = 40;          // the line's tension to ~1e-12 relative
constexpr int kLineSolveIterations = 50;

// Throws "<path>: <size nuser_actuator> must be >= <slots> for <what>, got <n>" if the
// model's actuators have fewer user slots than `what` needs.
void require_user_slots(const mjModel* m, int slots, const char* what, const char* path) {
  if (m->nuser_actuator >= slots) return;
  throw InputError(std::string(path) + ": <size nuser_actuator> must be >= " +
                   std::to_string(slots) + " for " + what + ", got " +
                   std::to_string(m->nuser_actuator));
}

const mjtNum* user_slots(const mjModel* m, int id) {
  return m->actuator_user + static_cast<long>(id) * m->nuser_actuator;
}

// slots kPamPlantUserSize.. : the friction's form, its elements, its userdata block
void store_friction_form(mjModel* m, int id, const AvbdlFriction& f, int slip_index,
                         const char* path) {
  const bool slip = f.model == FrictionModel::kMaxwellSlip;
  if (!slip && m->nuser_actuator < kPamSlipUserSize) return;   // older models: no slots needed
  require_user_slots(m, kPamSlipUserSize, "a PAM with Maxwell-slip friction", path);
  if (slip && (slip_index < 0 || slip_index + 1 + f.slip.count > m->nuserdata)) {
    throw InputError(std::string(path) + ": <size nuserdata> must be >= " +
                     std::to_string(slip_index + 1 + f.slip.count) +
                     " to hold the PAMs' pressures and Maxwell-slip states");
  }
  mjtNum* u = m->actuator_user + static_cast<long>(id) * m->nuser_actuator + kPamPlantUserSize;
  u[0] = slip ? 1.0 : 0.0;
  u[1] = slip ? f.slip.count : 0;
  for (int k = 0; k < kMaxSlipElements; ++k) {
    u[2 + k] = f.slip.weight[k];
    u[2 + kMaxSlipElements + k] = f.slip.breakaway_m[k];
  }
  u[2 + 2 * kMaxSlipElements] = slip ? slip_index : -1;
}

void read_friction_form(const mjModel* m, int id, AvbdlFriction* f) {
  f->model = FrictionModel::kSmooth;
  if (m->nuser_actuator < kPamSlipUserSize) return;
  const mjtNum* u = user_slots(m, id) + kPamPlantUserSize;
  if (u[0] != 1.0) return;
  f->model = FrictionModel::kMaxwellSlip;
  f->slip.count = static_cast<int>(u[1]);
  for (int k = 0; k < kMaxSlipElements; ++k) {
    f->slip.weight[k] = u[2 + k];
    f->slip.breakaway_m[k] = u[2 + kMaxSlipElements + k];
  }
}

// slots kPamLineUserSize.. : the bladder's law and tube (none needed for the default)
void store_bladder_form(mjModel* m, int id, const AvbdlParams& a, const char* path) {
  const bool gent = a.bladder_law == BladderLaw::kGentGent;
  if (!gent && a.bladder_diameter_m == 0.0 && m->nuser_actuator < kPamBladderUserSize) return;
  require_user_slots(m, kPamBladderUserSize, "a PAM with a tube bladder or the Gent-Gent law",
                     path);
  mjtNum* u = m->actuator_user + static_cast<long>(id) * m->nuser_actuator + kPamLineUserSize;
  u[0] = gent ? 1.0 : 0.0;
  u[1] = a.bladder_diameter_m;
  u[2] = a.bladder_gent.mu_pa;
  u[3] = a.bladder_gent.c2_pa;
  u[4] = a.bladder_gent.jm;
}

void read_bladder_form(const mjModel* m, int id, AvbdlParams* a) {
  if (m->nuser_actuator < kPamBladderUserSize) return;
  const mjtNum* u = user_slots(m, id) + kPamLineUserSize;
  a->bladder_law = u[0] == 1.0 ? BladderLaw::kGentGent : BladderLaw::kMooneyRivlin;
  a->bladder_diameter_m = u[1];
  a->bladder_gent = {u[2], u[3], u[4]};
}

// the actuator's slip block in d->userdata: [L_prev, s_1..s_N]
int slip_block(const mjModel* m, int id) {
  return static_cast<int>(user_slots(m, id)[kPamPlantUserSize + 2 + 2 * kMaxSlipElements]);
}

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
  SpringModel spring;

  PamLaw(const mjModel* m, int id) {
    has_plant = pam_plant_from_model(m, id, &plant);
    if (has_plant) {
      shape = avbdl_shape(plant);
    } else {
      spring = pam_spring_from_model(m, id);
    }
  }
  double pull(const mjModel* m, const mjData* d, int id, double p, double taut) const {
    if (has_plant) {
      // a slack muscle contracts to its free length and pulls nothing; the law holds up to
      // avbdl_max_length (a muscle stretched to its fibre length would have to break)
      double slip_state[kMaxSlipElements];
      const FrictionInput friction = friction_input(m, d, id, plant, taut, slip_state);
      return avbdl_line_pull(plant, shape, p, taut, friction);
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
  thread_local std::array<Entry, 8> cache;
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

void store_line_stiffness_in_model(mjModel* m, int id, double axial_stiffness_n,
                                   const char* path) {
  if (axial_stiffness_n <= 0.0 && m->nuser_actuator < kPamLineUserSize) return;   // older models
  require_user_slots(m, kPamLineUserSize, "an extensible line", path);
  m->actuator_user[static_cast<long>(id) * m->nuser_actuator + kPamSlipUserSize] =
      axial_stiffness_n;
}

double pam_line_axial_stiffness(const mjModel* m, int id) {
  return m->nuser_actuator < kPamLineUserSize ? 0.0 : user_slots(m, id)[kPamSlipUserSize];
}

int pam_slip_block_size(const AvbdlParams& plant) {
  return plant.friction.model == FrictionModel::kMaxwellSlip ? 1 + plant.friction.slip.count
                                                             : 0;
}

void store_pam_in_model(mjModel* m, int id, const SpringModel& spring, double line_length_m,
                        int userdata_index, const char* path) {
  const std::string name = mj_id2name(m, mjOBJ_ACTUATOR, id) ? mj_id2name(m, mjOBJ_ACTUATOR, id) : "?";
  require_user_slots(m, kPamUserSize, "PAM actuators", path);
  if (m->actuator_biastype[id] != mjBIAS_USER || m->actuator_trntype[id] != mjTRN_TENDON) {
    throw InputError(std::string(path) + ": actuator '" + name +
                     "' must be a general actuator on a tendon with biastype=\"user\"");
  }
  if (userdata_index < 0 || userdata_index >= m->nuserdata) {
    throw InputError(std::string(path) + ": <size nuserdata> must be > " +
                     std::to_string(userdata_index) + " to hold the PAM pressures");
  }
  mjtNum* u = m->actuator_user + static_cast<long>(id) * m->nuser_actuator;
  u[0] = static_cast<int>(spring.law);
  u[1] = spring.m_m_per_pa;
  u[2] = spring.h_m;
  for (int k = 0; k < 6; ++k) u[3 + k] = spring.coef[k];
  u[9] = line_length_m;
  u[10] = userdata_index;
}

void store_plant_in_model(mjModel* m, int id, const AvbdlParams& a, int slip_userdata_index,
                          const char* path) {
  require_user_slots(m, kPamPlantUserSize, "a PAM with a plant law", path);
  mjtNum* u = m->actuator_user + static_cast<long>(id) * m->nuser_actuator;
  const AvbdlFriction& f = a.friction;
  const double values[] = {1.0, a.length_m, a.diameter_m, a.braid_angle_rad,
                           a.wall_thickness_m, a.bladder.c10_pa, a.bladder.c01_pa,
                           a.bladder.c20_pa, a.end_length_m, a.end_slope,
                           f.velocity_scale_m_per_s, f.extension.force_n,
                           f.extension.pressure_area_m2, f.extension.strain_area_m2,
                           f.contraction.force_n, f.contraction.pressure_area_m2,
                           f.contraction.strain_area_m2};
  std::copy(std::begin(values), std::end(values), u + kPamUserSize);
  store_friction_form(m, id, f, slip_userdata_index, path);
  store_bladder_form(m, id, a, path);
}

bool pam_plant_from_model(const mjModel* m, int id, AvbdlParams* a) {
  if (m->nuser_actuator < kPamPlantUserSize) return false;
  const mjtNum* u = user_slots(m, id) + kPamUserSize;
  if (u[0] != 1.0) return false;
  a->length_m = u[1];
  a->diameter_m = u[2];
  a->braid_angle_rad = u[3];
  a->wall_thickness_m = u[4];
  a->bladder = {u[5], u[6], u[7]};
  a->end_length_m = u[8];
  a->end_slope = u[9];
  a->friction.velocity_scale_m_per_s = u[10];
  a->friction.extension = {u[11], u[12], u[13]};
  a->friction.contraction = {u[14], u[15], u[16]};
  read_friction_form(m, id, &a->friction);
  read_bladder_form(m, id, a);
  return true;
}

SpringModel pam_spring_from_model(const mjModel* m, int id) {
  const mjtNum* u = user_slots(m, id);
  SpringModel spring;
  spring.law = static_cast<SpringLaw>(static_cast<int>(u[0]));
  spring.m_m_per_pa = u[1];
  spring.h_m = u[2];
  for (int k = 0; k < 6; ++k) spring.coef[k] = u[3 + k];
  return spring;
}

double pam_line_length(const mjModel* m, int id) { return user_slots(m, id)[9]; }

int pam_userdata_index(const mjModel* m, int id) {
  return static_cast<int>(user_slots(m, id)[10]);
}

double pam_length(const mjModel* m, const mjData* d, int id) {
  const double unstretched = d->actuator_length[id] - pam_line_length(m, id);
  if (pam_line_axial_stiffness(m, id) <= 0.0) return unstretched;
  double taut = unstretched;
  line_tension(m, d, id, &taut);
  return taut;
}

double pam_muscle_length(const mjModel* m, const mjData* d, int id) {
  // the plant's free length is a root solve, done only when the line is slack
  const double p = d->userdata[pam_userdata_index(m, id)];
  const PamLaw& law = pam_law(m, id);
  if (law.has_plant) {
    return avbdl_line_muscle_length(law.plant, law.shape, p, pam_length(m, d, id));
  }
  return std::max(pam_length(m, d, id), natural_length(law.spring, p));
}

mjtNum pam_actuator_force(const mjModel* m, const mjData* d, int id) {
  double taut = 0.0;
  return -line_tension(m, d, id, &taut);
}

void pam_commit_friction(const mjModel* m, mjData* d, int id, double muscle_length_m) {
  AvbdlParams plant;
  if (!pam_plant_from_model(m, id, &plant) ||
      plant.friction.model != FrictionModel::kMaxwellSlip) {
    return;
  }
  // the muscle's own length: the line's while taut, its free length while slack
  mjtNum* block = d->userdata + slip_block(m, id);
  if (block[0] > 0.0) {
    maxwell_slip_advance(plant.friction.slip, muscle_length_m - block[0], block + 1);
  }
  block[0] = muscle_length_m;
}

void install_pam_actuator_callback() { mjcb_act_bias = pam_actuator_force; }

}  // namespace pamsim
