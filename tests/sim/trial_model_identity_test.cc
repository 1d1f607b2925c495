// trial_model_identity_test.cc: same_trial_model (trial_model.h) against what it stands for.
// It compares what load_trial_model reads, kept beside it by hand; this test holds that list
// to the built models: for every key of the shipped arm, rig and leg scenarios changed in
// turn, whenever same_trial_model says the changed scenario builds the same trial model, the
// two models built are the same (MuJoCo's model bytes, every muscle's binding, the bound ids
// and start state). A key that load_trial_model reads and the list misses fails here, naming
// the key; the counts show the test is not empty either way.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <sstream>
#include <string>
#include <vector>

#include <mujoco/mujoco.h>

#include "base/double_bits.h"
#include "base/input_error.h"
#include "pam_actuator/avbdl_keys.h"
#include "sim/core/muscle_binding.h"
#include "sim/core/trial_model.h"
#include "sim/scenario/scenario_file.h"
#include "test_paths.h"

namespace pamsim {
namespace {

void bits(std::ostringstream& os, double v) { os << double_bits(v) << ';'; }

// a muscle's binding: its spring law, line and plant (every plant row, the series' terms)
void binding_text(std::ostringstream& os, const MuscleBinding& b) {
  os << static_cast<int>(b.spring.law) << ';';
  bits(os, b.spring.m_m_per_pa);
  bits(os, b.spring.h_m);
  for (double c : b.spring.coef) bits(os, c);
  bits(os, b.line_length_m);
  for (double v : {b.line.axial_stiffness_n, b.line.creep, b.line.creep_time_s,
                   b.line.start_tension_n}) {
    bits(os, v);
  }
  os << b.line.creep_index << ';';
  os << b.pressure_index << ';' << b.has_plant << ';' << b.slip_block << ';'
     << b.relaxation_block << ';';
  AvbdlParams plant = b.plant;
  for (const KeyDoc& d : key_table_docs(avbdl_key_tables(&plant))) os << d.fallback << ';';
  for (int i = 0; i < plant.relaxation.count; ++i) {
    bits(os, plant.relaxation.time_s[i]);
    bits(os, plant.relaxation.weight[i]);
  }
  for (int i = 0; i < plant.friction.slip.count; ++i) {
    bits(os, plant.friction.slip.breakaway_m[i]);
    bits(os, plant.friction.slip.weight[i]);
  }
}

// Everything a built trial model is, as text.
std::string built_text(const TrialModel& tm) {
  const mjModel* m = tm.model.get();
  std::string bytes(static_cast<std::size_t>(mj_sizeModel(m)), '\0');
  mj_saveModel(m, nullptr, bytes.data(), static_cast<int>(bytes.size()));
  std::ostringstream os;
  os << bytes << '|';
  for (const BoundMuscle& b : tm.muscles) {
    os << b.spec << ';' << b.actuator << ';' << b.label << ';';
    bits(os, b.line_length_m);
    binding_text(os, find_muscle(m, b.actuator)->binding);
  }
  os << tm.joint.name << ';' << tm.joint.hinge << ';' << tm.joint.qpos << ';' << tm.joint.dof;
  for (const BoundHold& h : tm.holds) {
    os << h.body << ';' << h.qpos << ';' << h.dof << ';' << h.site << ';';
    bits(os, h.radius_m);
  }
  for (const auto& [adr, value] : tm.start_qpos) {
    os << adr << ';';
    bits(os, value);
  }
  for (const BoundEvent& e : tm.events) {
    os << e.body_a << ';' << e.body_b << ';' << e.joint_qpos << ';' << e.body << ';' << e.hold
       << ';' << e.after << ';';
  }
  for (const ReflexPair& p : tm.pairs) os << p.agonist << ',' << p.antagonist << ';';
  os << tm.events_change_model;
  return os.str();
}

// `value` changed: a number by about a tenth (an integer by one), a boolean flipped; "" for
// a value of another kind (a name, a path, a list), which is left alone
std::string changed(const std::string& value) {
  if (value == "true" || value == "false") return value == "true" ? "false" : "true";
  char* end = nullptr;
  const double v = std::strtod(value.c_str(), &end);
  if (value.empty() || *end != '\0' || !std::isfinite(v)) return "";
  if (value.find_first_of(".eE") == std::string::npos) return std::to_string(std::llround(v) + 1);
  char buf[40];
  std::snprintf(buf, sizeof(buf), "%.17g", v * 1.1 + 0.01);
  return buf;
}

struct Counts {
  int same = 0, rebuilt = 0;
};

// Every key of `scenario` with `given` set (keys a shipped file leaves out) changed in turn.
Counts check_every_key(const std::string& scenario, const std::vector<std::string>& given) {
  const Scenario base = load_scenario(scenario, given);
  const std::string base_text = built_text(load_trial_model(base));
  Counts counts;
  for (const ScenarioKeyValue& kv : scenario_key_values(scenario, given)) {
    const std::string value = changed(kv.value);
    if (value.empty()) continue;
    std::vector<std::string> sets = given;
    sets.push_back(kv.key + "=" + value);
    try {
      const Scenario other = load_scenario(scenario, sets);
      if (!same_trial_model(base, other)) {
        ++counts.rebuilt;
        continue;
      }
      ++counts.same;
      EXPECT_EQ(built_text(load_trial_model(other)), base_text)
          << scenario << ": --set " << sets.back() << " builds another model, but "
          << "same_trial_model says it is the same (a key load_trial_model reads is missing "
          << "from its list)";
    } catch (const InputError&) {
      // a value the scenario refuses, or a model it cannot bind: nothing to compare
    }
  }
  return counts;
}

TEST(TrialModelIdentityTest, WhatSameTrialModelCallsTheSameIsBuiltTheSame) {
  using pamsim_test::kScenarios;
  const std::vector<std::string> arm = {
      "muscles.agonist.plant.geometry.wall_thickness_mm=1.5", "bodies.basket.mass_kg=0.3",
      "joints.shoulder.damping_N_m_s_per_rad=0.01", "joints.shoulder.frictionloss_N_m=0.001",
      "muscles.antagonist.line_diameter_mm=0.4", "muscles.antagonist.line_modulus_MPa=2000"};
  for (const auto& [file, given] : std::vector<std::pair<std::string, std::vector<std::string>>>{
           {"drop_mass.toml", {}}, {"reaching.toml", arm}, {"landing.toml", {}}}) {
    const Counts counts = check_every_key(kScenarios + file, given);
    EXPECT_GE(counts.same, 40) << file << ": keys that keep the model";
    EXPECT_GE(counts.rebuilt, 3) << file << ": keys that rebuild it";
  }
}

}  // namespace
}  // namespace pamsim
