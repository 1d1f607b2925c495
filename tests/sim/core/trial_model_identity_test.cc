// trial_model_identity_test.cc: same_trial_model (trial_model.h) against what it stands for.
// It calls two scenarios the same where they differ only in keys whose rows say only the trial
// reads them (trial_only_key, scenario_key_docs.h); this test holds those flags to the built
// models: for every key of the shipped arm, rig and leg scenarios changed in turn (a number, a
// boolean, a choice), whenever same_trial_model says the changed scenario builds the same trial
// model, the two models built are the same (MuJoCo's model bytes, every muscle's binding, the
// bound ids and start state). A key flagged trial-only that load_trial_model reads fails here,
// naming the key; the counts show the test is not empty either way, and the sweeps' usual axes
// keep their model.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <regex>
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
#include "sim/scenario/scenario_key_docs.h"
#include "sim/test_paths.h"

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
  for (double v :
       {b.line.axial_stiffness_n, b.line.creep, b.line.creep_time_s, b.line.start_tension_n}) {
    bits(os, v);
  }
  os << b.line.creep_index << ';';
  os << b.pressure_index << ';' << b.has_plant << ';' << b.slip_block << ';' << b.relaxation_block
     << ';';
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

// another of the names "a" | "b" a choice key allows (its reference line's), or ""
std::string other_choice(const std::string& key, const std::string& value) {
  const KeyDoc* doc = scenario_key_doc(key);
  if (doc == nullptr) return "";
  const std::regex quoted("\"([A-Za-z0-9_]+)\"");
  for (std::sregex_iterator m(doc->allowed.begin(), doc->allowed.end(), quoted), end; m != end;
       ++m) {
    if (m->str(0) != value) return m->str(0);
  }
  return "";
}

// `value` changed: a number by about a tenth (an integer by one), a boolean flipped, a
// choice to another of its names; "" for a value of another kind (a free name, a path, a
// list), which is left alone
std::string changed(const std::string& key, const std::string& value) {
  if (value == "true" || value == "false") return value == "true" ? "false" : "true";
  if (!value.empty() && value[0] == '"') return other_choice(key, value);
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
    const std::string value = changed(kv.key, kv.value);
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
          << "same_trial_model says it is the same (its row flags as trial-only a key "
          << "load_trial_model reads)";
    } catch (const InputError&) {
      // a value the scenario refuses, or a model it cannot bind: nothing to compare
    }
  }
  return counts;
}

TEST(TrialModelIdentityTest, WhatSameTrialModelCallsTheSameIsBuiltTheSame) {
  using pamsim_test::kScenarios;
  const std::vector<std::string> arm = {"muscles.agonist.plant.geometry.wall_thickness_mm=1.5",
                                        "bodies.basket.mass_kg=0.3",
                                        "joints.shoulder.damping_N_m_s_per_rad=0.01",
                                        "joints.shoulder.frictionloss_N_m=0.001",
                                        "muscles.antagonist.line_diameter_mm=0.4",
                                        "muscles.antagonist.line_modulus_MPa=2000"};
  for (const auto& [file, given] : std::vector<std::pair<std::string, std::vector<std::string>>>{
           {"drop_mass.toml", {}}, {"reaching.toml", arm}, {"landing.toml", {}}}) {
    const Counts counts = check_every_key(kScenarios + file, given);
    EXPECT_GE(counts.same, 40) << file << ": keys that keep the model";
    EXPECT_GE(counts.rebuilt, 3) << file << ": keys that rebuild it";
  }
}

// The shipped sweeps' and tunings' axes: the reflex's gains, the noise and the valve keep the
// model; a plant field, a mass and a joint's damping load it again; a scenario not read from
// a document shares none.
TEST(TrialModelIdentityTest, TheShippedAxesOfTheControllerSensorsAndValveKeepTheModel) {
  const std::string drop = pamsim_test::kScenarios + "drop_mass.toml";
  const Scenario base = load_scenario(drop);
  for (const char* set : {"reflex.v_thr_mm_s=60", "reflex.k_MPa_s_per_mm=0.002",
                          "reflex.lowpass_hz=20", "sensors.noise_scale=2", "valve.dead_time_ms=20",
                          "sim.duration_s=2", "seed=7", "sensors.gauge.board.length_mm=50"}) {
    EXPECT_TRUE(same_trial_model(base, load_scenario(drop, {set}))) << set;
  }
  for (const char* set : {"muscles.agonist.plant.geometry.wall_thickness_mm=1.5",
                          "drop.mass_kg=0.3", "joints.shoulder.damping_N_m_s_per_rad=0.2",
                          "reflex.pairs=[[\"antagonist\", \"agonist\"]]"}) {
    EXPECT_FALSE(same_trial_model(base, load_scenario(drop, {set}))) << set;
  }
  EXPECT_FALSE(same_trial_model(Scenario{}, Scenario{}));
}

// The flags as the rows set them: a key, or a table by every documented key under it
TEST(TrialModelIdentityTest, RowsFlagTheTrialsKeysAndTablesButNotTheModels) {
  for (const char* key :
       {"seed", "sim.duration_s", "sim.control_hz", "controller.p_max_MPa", "reflex.v_thr_mm_s",
        "reflex.ib.f_thr_N", "sensors.noise_scale", "muscles.agonist.gauge.contact.wrap_deg",
        "model.pneumatics", "pneumatics.chamber.tube_dead_volume_cm3", "drop.time_s", "sensors",
        "valve", "reflex.ib", "sensors.gauge", "pneumatics.chamber"}) {
    EXPECT_TRUE(trial_only_key(key)) << key;
  }
  for (const char* key : {"sim.timestep_s", "reflex.pairs", "model.file", "drop.mass_kg", "drop",
                          "reflex", "muscles.agonist.plant", "joints", "no.such_key"}) {
    EXPECT_FALSE(trial_only_key(key)) << key;
  }
}

// Scenarios A A B C B (two masses and a gain): three models, each scenario bound to its own
// (the last B to B's, not to the model at its first match's index)
TEST(TrialModelIdentityTest, SharedModelsBindEachScenarioToItsOwn) {
  const std::string drop = pamsim_test::kScenarios + "drop_mass.toml";
  const Scenario a = load_scenario(drop);
  const Scenario a_gain = load_scenario(drop, {"reflex.v_thr_mm_s=60"});
  const Scenario b = load_scenario(drop, {"drop.mass_kg=0.3"});
  const Scenario c = load_scenario(drop, {"drop.mass_kg=0.4"});
  std::vector<std::size_t> model_of;
  const std::vector<TrialModel> models = shared_trial_models({a, a_gain, b, c, b}, &model_of);
  ASSERT_EQ(models.size(), 3u);
  EXPECT_EQ(model_of, (std::vector<std::size_t>{0, 0, 1, 2, 1}));
  const int ball = mj_name2id(models[1].model.get(), mjOBJ_BODY, "ball");
  EXPECT_DOUBLE_EQ(models[model_of[4]].model->body_mass[ball], 0.3);
}

}  // namespace
}  // namespace pamsim
