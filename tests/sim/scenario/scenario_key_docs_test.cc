// scenario_key_docs_test.cc: the documented keys (scenario/scenario_key_docs.h) are exactly the
// keys the scenario reader asks for, over the shipped scenarios and variants that reach every
// optional key (schedules of each kind, events of each condition, holds, valve and reflex
// options), so neither list can drift from the other; the documented literal defaults are
// the reader's.
#include "sim/scenario/scenario_key_docs.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <set>
#include <string>
#include <vector>

#include "sim/cli_util.h"
#include "base/input_error.h"
#include "base/toml_file.h"
#include "sim/scenario/scenario_file.h"
#include "sim/test_paths.h"

namespace {

namespace fs = std::filesystem;
using pamsim_test::fresh_dir;
using pamsim_test::write_text;

using pamsim_test::kSource;

struct Read {
  std::string scenario;
  std::vector<std::string> overrides;
};

// Scenarios that, together, make the reader ask for every key it knows (a table schedule's
// among them, from dir/schedule.csv, which the caller writes).
std::vector<Read> every_kind_of_scenario(const fs::path& dir) {
  const std::string s = kSource + "/scenarios/";
  return {
      {s + "drop_mass.toml", {}},  // the 0.1 shorthands, drop, reflex, sensors
      {s + "drop_mass_fiber.toml", {}},
      {s + "drop_mass.toml",  // the tension (Ib) reflex's keys
       {"controller.kind=\"stretch_tension_reflex\"", "reflex.ib.f_thr_N=60",
        "reflex.ib.k_MPa_per_N=0.002"}},
      {s + "drop_mass.toml",
       {"valve.dead_time_ms=5", "valve.valve_time_constant_ms=10", "valve.proportional_band_kPa=20",
        "valve.supply_MPa=0.7", "valve.command_max_MPa=0.7", "valve.feedback=\"delayed\"",
        "valve.sense=\"outlet\"", "valve.sample_period_ms=1",
        "valve.supply_sonic_conductance_dm3_per_s_bar=0.35",
        "valve.supply_critical_pressure_ratio=0.3",
        "valve.exhaust_sonic_conductance_dm3_per_s_bar=0.35",
        "valve.exhaust_critical_pressure_ratio=0.3", "valve.outlet_volume_cm3=2",
        "valve.tube_sonic_conductance_dm3_per_s_bar=1.3", "valve.tube_critical_pressure_ratio=0.4",
        "controller.p_max_MPa=0.6", "reflex.pairs=[[\"agonist\", \"antagonist\"]]",
        "joints.shoulder.damping_N_m_s_per_rad=0", "joints.shoulder.frictionloss_N_m=0.001",
        "muscles.agonist.line_diameter_mm=0.5", "muscles.agonist.line_modulus_MPa=2500",
        "pneumatics.chamber.tube_dead_volume_cm3=12",
        // an event of each condition, and each action's keys
        "events.a.when.at_s=0.5", "events.a.action=\"add_mass\"", "events.a.body=\"basket\"",
        "events.a.mass_kg=0.1", "events.b.when.contact=[\"ball\", \"basket\"]",
        "events.b.after=\"a\"", "events.c.when.joint=\"shoulder\"", "events.c.when.below_deg=-60",
        "events.d.when.joint=\"shoulder\"", "events.d.when.above_deg=0",
        "events.e.when.body=\"ball\"", "events.e.when.below_z_m=-1", "events.f.when.at_s=0.7",
        "events.f.action=\"set\"", "events.f.set=[\"reflex.v_thr_mm_s=50\"]", "hil.hold_ticks=5",
        "hil.safe_command=\"hold\"", "hil.command_timeout_ms=50", "hil.link_lost_s=2"}},
      {s + "reaching.toml",  // the long forms: plant, label, ramp; holds by position
       {"muscles.agonist.command={kind=\"constant\", MPa=0.4}",
        "muscles.antagonist.plant.geometry.wall_thickness_mm=3.0",
        "muscles.antagonist.plant.friction.extension.A0_mm2=6.11",
        "muscles.antagonist.command={kind=\"steps\", times_s=[0.0, 1.0], MPa=[0.4, 0.5]}",
        "muscles.agonist.line_mm=150", "bodies.ball.mass_kg=0.2",
        "bodies.arm.inertia_kg_m2=[4e-6, 1.5e-3, 1.5e-3]",
        "muscles.agonist.gauge.contact.model=\"sliding\"",  // a muscle's own contact
        "muscles.agonist.gauge.contact.misalignment_mm=1",
        "muscles.agonist.gauge.contact.fitting_distance_mm=20",
        "muscles.agonist.gauge.contact.shaft_distance_mm=100",
        "muscles.agonist.gauge.contact.wrap_deg=20",
        "muscles.agonist.gauge.contact.friction_coefficient=0.2",
        "muscles.agonist.gauge.contact.reseat_mm=1"}},
      {s + "reaching.toml",
       {"muscles.agonist.command={kind=\"table\", file=\"" + (dir / "schedule.csv").string() +
            "\", column=\"MPa\", hold=true}",
        "muscles.antagonist.line=\"equilibrium\""}},
      {pamsim_test::scenario_variant(dir, "reaching.toml", "position_m = [0.5, 0.5, 0.5]",
                                     "above_site = \"basket_floor\"\nheight_m = 0.3"),
       {}},
      {s + "pulley_sine_5kg.toml",  // sine with phase and start; a slide joint's conditions
       {"muscles.pam.command.phase_deg=90", "muscles.pam.command.start_s=1",
        "events.low.when.joint=\"weight_slide\"", "events.low.when.below_mm=-500",
        "events.high.when.joint=\"weight_slide\"", "events.high.when.above_mm=500",
        "events.high.action=\"end\"", "joints.weight_slide.damping_N_s_per_m=60",
        "joints.weight_slide.frictionloss_N=0.5"}},
      {s + "landing.toml", {}},          // joints.<joint>.start_deg and start_mm, muscles.<m>.spans
      {s + "drop_mass_heavy.toml", {}},  // muscles.<m>.line_limit_N
  };
}

TEST(ScenarioKeyDocsTest, TheDocumentedKeysAreExactlyTheKeysTheReaderAsksFor) {
  const fs::path dir = fresh_dir("keys_every");
  write_text(dir / "schedule.csv", "time_s,MPa\n0,0.4\n1,0.5\n");
  std::set<std::string> documented;
  for (const pamsim::KeyDoc& d : pamsim::scenario_key_docs()) {
    EXPECT_TRUE(documented.insert(d.key).second) << "documented twice: " << d.key;
  }
  std::set<std::string> asked;
  for (const Read& r : every_kind_of_scenario(dir)) {
    std::vector<pamsim::ScenarioKeyValue> values;
    try {
      values = pamsim::scenario_key_values(r.scenario, r.overrides);
    } catch (const pamsim::InputError& e) {
      ADD_FAILURE() << r.scenario << ": " << e.what();
      continue;
    }
    for (const pamsim::ScenarioKeyValue& kv : values) {
      const pamsim::KeyDoc* doc = pamsim::scenario_key_doc(kv.key);
      EXPECT_NE(doc, nullptr) << "the reader asks for " << kv.key
                              << ", which scenario_key_docs.cc does not document";
      if (doc == nullptr) continue;
      asked.insert(doc->key);
      // a literal documented default is the reader's
      if (kv.is_default && doc->fallback[0] != '(') {
        EXPECT_EQ(doc->fallback, kv.value) << kv.key << " in " << r.scenario;
      }
    }
  }
  for (const std::string& key : documented) {
    EXPECT_TRUE(asked.count(key)) << key
                                  << " is documented, but no scenario of the test made "
                                     "the reader ask for it (stale, or add a variant)";
  }
}

}  // namespace
