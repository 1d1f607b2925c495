// pam_slots.cc: a PAM's parameters written into and read back from its actuator's user
// slots, and where its history lives in the trial's userdata (layout in pam_callback.h).
#include "sim/core/pam_slots.h"

#include <algorithm>
#include <iterator>
#include <string>

#include "base/input_error.h"
#include "sim/core/pam_callback.h"

namespace pamsim {
namespace pam_slots {

void require_user_slots(const mjModel* m, int slots, const char* what, const char* path) {
  if (m->nuser_actuator >= slots) return;
  throw InputError(std::string(path) + ": <size nuser_actuator> must be >= " +
                   std::to_string(slots) + " for " + what + ", got " +
                   std::to_string(m->nuser_actuator));
}

const mjtNum* user_slots(const mjModel* m, int id) {
  return m->actuator_user + static_cast<long>(id) * m->nuser_actuator;
}

int relaxation_block(const mjModel* m, int id) {
  return static_cast<int>(user_slots(m, id)[kPamBladderUserSize + 1 + 2 * kMaxRelaxationTerms]);
}

int slip_block(const mjModel* m, int id) {
  return static_cast<int>(user_slots(m, id)[kPamPlantUserSize + 2 + 2 * kMaxSlipElements]);
}

int slip_block_size(const AvbdlParams& plant) {
  return plant.friction.model == FrictionModel::kMaxwellSlip ? 1 + plant.friction.slip.count
                                                             : 0;
}

}  // namespace pam_slots

namespace {

using pam_slots::require_user_slots;
using pam_slots::slip_block_size;
using pam_slots::user_slots;

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

// slots kPamBladderUserSize.. : the bladder's relaxation and its userdata block (none needed
// for an elastic bladder)
void store_relaxation_form(mjModel* m, int id, const BladderRelaxation& r, int index,
                           const char* path) {
  if (r.count == 0 && m->nuser_actuator < kPamRelaxationUserSize) return;
  require_user_slots(m, kPamRelaxationUserSize, "a PAM whose bladder relaxes", path);
  if (r.count > 0 && (index < 0 || index + 2 + r.count > m->nuserdata)) {
    throw InputError(std::string(path) + ": <size nuserdata> must be >= " +
                     std::to_string(index + 2 + r.count) +
                     " to hold the PAMs' pressures and histories");
  }
  mjtNum* u = m->actuator_user + static_cast<long>(id) * m->nuser_actuator + kPamBladderUserSize;
  u[0] = r.count;
  for (int k = 0; k < kMaxRelaxationTerms; ++k) {
    u[1 + k] = r.weight[k];
    u[1 + kMaxRelaxationTerms + k] = r.time_s[k];
  }
  u[1 + 2 * kMaxRelaxationTerms] = r.count > 0 ? index : -1;
}

void read_relaxation_form(const mjModel* m, int id, BladderRelaxation* r) {
  *r = BladderRelaxation{};
  if (m->nuser_actuator < kPamRelaxationUserSize) return;
  const mjtNum* u = user_slots(m, id) + kPamBladderUserSize;
  r->count = static_cast<int>(u[0]);
  for (int k = 0; k < kMaxRelaxationTerms; ++k) {
    r->weight[k] = u[1 + k];
    r->time_s[k] = u[1 + kMaxRelaxationTerms + k];
  }
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

int pam_history_size(const AvbdlParams& plant) {
  const int relaxation = plant.relaxation.count > 0 ? 2 + plant.relaxation.count : 0;
  return slip_block_size(plant) + relaxation;
}

bool pam_has_history(const AvbdlParams& plant) { return pam_history_size(plant) > 0; }

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

void store_plant_in_model(mjModel* m, int id, const AvbdlParams& a, int history_index,
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
  store_friction_form(m, id, f, history_index, path);
  store_bladder_form(m, id, a, path);
  store_relaxation_form(m, id, a.relaxation, history_index + slip_block_size(a), path);
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
  read_relaxation_form(m, id, &a->relaxation);
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

}  // namespace pamsim
