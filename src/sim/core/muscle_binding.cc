// muscle_binding.cc: the process's table of bound muscles (see muscle_binding.h).
#include "sim/core/muscle_binding.h"

#include <atomic>
#include <mutex>
#include <string>
#include <unordered_map>
#include <vector>

#include "base/input_error.h"

namespace pamsim {
namespace {

using Laws = std::vector<std::shared_ptr<const BoundMuscleLaw>>;  // by actuator id

struct Registry {
  std::mutex mutex;
  std::unordered_map<const mjModel*, Laws> models;
  std::atomic<std::uint64_t> epoch{1};
};

Registry& registry() {
  static Registry* r = new Registry;  // never destroyed: models may outlive static teardown
  return *r;
}

std::shared_ptr<const BoundMuscleLaw> derive(const MuscleBinding& binding) {
  auto law = std::make_shared<BoundMuscleLaw>();
  law->binding = binding;
  if (binding.has_plant) {
    law->shape = avbdl_shape(binding.plant);
    law->max_length_m = avbdl_max_length(binding.plant);
  }
  return law;
}

// actuator `id`'s binding, for a writer that changes part of it
MuscleBinding bound(const mjModel* m, int id, const char* path) {
  const std::shared_ptr<const BoundMuscleLaw> law = find_muscle(m, id);
  if (!law) {
    throw InputError(std::string(path) + ": actuator " + std::to_string(id) +
                     " is not a bound PAM (bind its spring law and line first)");
  }
  return law->binding;
}

// a history block [start, end) of d->userdata
void require_userdata(const mjModel* m, int start, int end, const char* path, const char* what) {
  if (start >= 0 && end <= m->nuserdata) return;
  throw InputError(std::string(path) + ": <size nuserdata> must be >= " + std::to_string(end) +
                   " to hold " + what);
}

int slip_block_size(const AvbdlParams& plant) {
  return plant.friction.model == FrictionModel::kMaxwellSlip ? 1 + plant.friction.slip.count : 0;
}

int relaxation_block_size(const AvbdlParams& plant) {
  return plant.relaxation.count > 0 ? 2 + plant.relaxation.count : 0;
}

}  // namespace

void bind_muscle(const mjModel* m, int id, const MuscleBinding& binding) {
  std::shared_ptr<const BoundMuscleLaw> law = derive(binding);
  Registry& r = registry();
  const std::lock_guard<std::mutex> lock(r.mutex);
  Laws& laws = r.models[m];
  if (static_cast<int>(laws.size()) < m->nu) laws.resize(m->nu);
  laws.at(id) = std::move(law);
  // (a thread may hold the actuator's law from before, bound or not: MuJoCo's compiler
  // runs the callback while it loads the model, before anything is bound)
  r.epoch.fetch_add(1, std::memory_order_acq_rel);
}

std::shared_ptr<const BoundMuscleLaw> find_muscle(const mjModel* m, int id) {
  Registry& r = registry();
  const std::lock_guard<std::mutex> lock(r.mutex);
  const auto it = r.models.find(m);
  if (it == r.models.end() || id < 0 || id >= static_cast<int>(it->second.size())) return nullptr;
  return it->second[id];
}

void copy_muscle_bindings(const mjModel* from, const mjModel* to) {
  Registry& r = registry();
  const std::lock_guard<std::mutex> lock(r.mutex);
  const auto it = r.models.find(from);
  if (it == r.models.end()) return;
  const Laws laws = it->second;  // (a copy: the insertion below may move the map's nodes)
  r.models[to] = laws;
  r.epoch.fetch_add(1, std::memory_order_acq_rel);
}

void unbind_muscles(const mjModel* m) {
  Registry& r = registry();
  const std::lock_guard<std::mutex> lock(r.mutex);
  if (r.models.erase(m) > 0) r.epoch.fetch_add(1, std::memory_order_acq_rel);
}

std::uint64_t muscle_binding_epoch() { return registry().epoch.load(std::memory_order_acquire); }

int pam_history_size(const AvbdlParams& plant) {
  return slip_block_size(plant) + relaxation_block_size(plant);
}

bool pam_has_history(const AvbdlParams& plant) { return pam_history_size(plant) > 0; }

void store_pam_in_model(const mjModel* m, int id, const SpringModel& spring, double line_length_m,
                        int userdata_index, const char* path) {
  const char* name = mj_id2name(m, mjOBJ_ACTUATOR, id);
  if (m->actuator_biastype[id] != mjBIAS_USER || m->actuator_trntype[id] != mjTRN_TENDON) {
    throw InputError(std::string(path) + ": actuator '" + (name ? name : "?") +
                     "' must be a general actuator on a tendon with biastype=\"user\"");
  }
  if (userdata_index < 0 || userdata_index >= m->nuserdata) {
    throw InputError(std::string(path) + ": <size nuserdata> must be > " +
                     std::to_string(userdata_index) + " to hold the PAM pressures");
  }
  const std::shared_ptr<const BoundMuscleLaw> before = find_muscle(m, id);
  MuscleBinding b = before ? before->binding : MuscleBinding{};
  b.spring = spring;
  b.line_length_m = line_length_m;
  b.pressure_index = userdata_index;
  bind_muscle(m, id, b);
}

void store_plant_in_model(const mjModel* m, int id, const AvbdlParams& plant, int history_index,
                          const char* path) {
  MuscleBinding b = bound(m, id, path);
  b.has_plant = true;
  b.plant = plant;
  const int slip = slip_block_size(plant), relaxation = relaxation_block_size(plant);
  if (slip > 0) {
    require_userdata(m, history_index, history_index + slip, path,
                     "the PAMs' pressures and Maxwell-slip states");
  }
  if (relaxation > 0) {
    require_userdata(m, history_index, history_index + slip + relaxation, path,
                     "the PAMs' pressures and histories");
  }
  b.slip_block = slip > 0 ? history_index : -1;
  b.relaxation_block = relaxation > 0 ? history_index + slip : -1;
  bind_muscle(m, id, b);
}

void store_line_in_model(const mjModel* m, int id, const LineBinding& line, const char* path) {
  MuscleBinding b = bound(m, id, path);
  if (line.creep > 0.0) {
    require_userdata(m, line.creep_index, line.creep_index + 1, path,
                     "the PAMs' pressures, histories and lines' creep states");
  }
  b.line = line;
  bind_muscle(m, id, b);
}

}  // namespace pamsim
