// scenario_physical_keys_test.cc: the plant and pneumatics files' fields as scenario keys:
// muscles.<m>.plant.<table>.<field> and pneumatics.<table>.<field>, from
// --set or from a table in the scenario, change that field of the file and nothing else, are
// validated as the file's own field (refused by their scenario key), a plant's field makes
// another trial model, and both survive the run folder's resolved scenario.toml.
#include <gtest/gtest.h>

#include <array>
#include <filesystem>
#include <string>
#include <vector>

#include "base/input_error.h"
#include "sim/cli_util.h"
#include "pam_actuator/plant_params.h"
#include "pneumatics/pneumatic_params.h"
#include "sim/core/trial_model.h"
#include "sim/scenario/scenario_file.h"
#include "sim/test_paths.h"

namespace pamsim {
namespace {

using pamsim_test::kReaching;
const std::string kTube = "pneumatics.chamber.tube_dead_volume_cm3";

const MuscleSpec& agonist(const Scenario& sc) {
  for (const MuscleSpec& m : sc.muscles) {
    if (m.actuator == "agonist") return m;
  }
  throw std::logic_error("no agonist");
}

// Each --set in `cases` is refused in one line holding its text; none names `not_named`.
void expect_refused(const std::vector<std::pair<std::string, std::string>>& cases,
                    const std::string& not_named = "\n") {
  for (const auto& [set, says] : cases) {
    SCOPED_TRACE(set);
    try {
      load_scenario(kReaching, {set});
      ADD_FAILURE() << "accepted";
    } catch (const InputError& e) {
      const std::string what = e.what();
      EXPECT_NE(what.find(says), std::string::npos) << what;
      EXPECT_EQ(what.find(not_named), std::string::npos) << what;
      EXPECT_EQ(what.find('\n'), std::string::npos) << what;
    }
  }
}

TEST(ScenarioPlantKeysTest, ASetFieldChangesThatFieldOfThePlantFileOnly) {
  const Scenario base = load_scenario(kReaching);
  const Scenario changed = load_scenario(kReaching, {pamsim_test::kAgonistWall + "=1.5"});
  const AvbdlParams& a = agonist(base).plant;
  const AvbdlParams& b = agonist(changed).plant;
  EXPECT_EQ(b.wall_thickness_m, 1.5e-3);
  EXPECT_NE(a.wall_thickness_m, b.wall_thickness_m);
  EXPECT_EQ(a.length_m, b.length_m);
  EXPECT_EQ(a.diameter_m, b.diameter_m);
  EXPECT_EQ(a.friction.extension.pressure_area_m2, b.friction.extension.pressure_area_m2);
  EXPECT_EQ(agonist(changed).plant_file, agonist(base).plant_file);
  // another plant file and a field of it, in either order
  const std::string other = "muscles.agonist.plant=\"" + std::string(PAMSIM_SOURCE_DIR) +
                            "/models/pams/plant_antagonist.toml\"";
  for (const auto& sets : {std::vector<std::string>{other, pamsim_test::kAgonistWall + "=1.5"},
                           std::vector<std::string>{pamsim_test::kAgonistWall + "=1.5", other}}) {
    const Scenario both = load_scenario(kReaching, sets);
    EXPECT_EQ(agonist(both).plant.wall_thickness_m, 1.5e-3);
    EXPECT_NE(agonist(both).plant_file.find("plant_antagonist.toml"), std::string::npos);
  }
  EXPECT_FALSE(same_trial_model(base, changed)) << "a sweep over the field rebuilds the model";
  EXPECT_TRUE(
      same_trial_model(changed, load_scenario(kReaching, {pamsim_test::kAgonistWall + "=1.5"})));
  // the file's own reading of the same value
  EXPECT_EQ(load_plant_params(agonist(base).plant_file).avbdl.wall_thickness_m, a.wall_thickness_m);
}

TEST(ScenarioPlantKeysTest, APlantTableInTheScenarioIsTheSameAsTheSet) {
  const auto dir = pamsim_test::fresh_dir("plant_keys_table");
  const std::string variant = pamsim_test::scenario_variant(
      dir, "reaching.toml",
      "plant = \"" + std::string(PAMSIM_SOURCE_DIR) + "/models/pams/plant_agonist.toml\"",
      "plant = { file = \"" + std::string(PAMSIM_SOURCE_DIR) +
          "/models/pams/plant_agonist.toml\", geometry = { wall_thickness_mm = 1.5 }, "
          "friction = { extension = { A0_mm2 = 3.0 } } }");
  const Scenario sc = load_scenario(variant);
  EXPECT_EQ(agonist(sc).plant.wall_thickness_m, 1.5e-3);
  EXPECT_DOUBLE_EQ(agonist(sc).plant.friction.extension.pressure_area_m2, 3.0e-6);
  EXPECT_NE(agonist(sc).plant_changes.find("wall_thickness_mm"), std::string::npos);
}

TEST(ScenarioPlantKeysTest, TheRunFoldersScenarioKeepsTheFieldsAndThePath) {
  const auto dir = pamsim_test::fresh_dir("plant_keys_recorded");
  const RecordedScenario r =
      load_recorded_scenario(pamsim_test::read_file(kReaching), kReaching,
                             {pamsim_test::kAgonistWall + "=1.5"}, dir.string(), "");
  pamsim_test::write_text(dir / "scenario.toml", r.resolved_toml);
  const Scenario again = load_scenario((dir / "scenario.toml").string());
  EXPECT_EQ(agonist(again).plant.wall_thickness_m, 1.5e-3);
  EXPECT_EQ(agonist(again).plant_changes, agonist(r.scenario).plant_changes);
  EXPECT_TRUE(
      std::filesystem::equivalent(agonist(again).plant_file, agonist(r.scenario).plant_file));
  bool recorded = false;
  for (const auto& [key, path] : r.input_paths) recorded |= key == "muscles.agonist.plant.file";
  EXPECT_TRUE(recorded) << "the plant file is among the run's inputs";
}

// Each bad field is one line naming its scenario key, as the file's own would name its key.
TEST(ScenarioPlantKeysTest, BadFieldsNameTheirScenarioKey) {
  expect_refused(
      {{pamsim_test::kAgonistWall + "=-1",
        pamsim_test::kAgonistWall + ": must be in [0, inf) mm, got -1"},
       {pamsim_test::kAgonistWall + "=\"thick\"", pamsim_test::kAgonistWall + ": must be a number"},
       {"muscles.agonist.plant.geometry.colour=1",
        "muscles.agonist.plant.geometry.colour: unknown key"},
       {"muscles.agonist.plant.friction.extension.A0_mm2=-2",
        "muscles.agonist.plant.friction.extension.A0_mm2: must be in [0, inf) mm^2, got -2"},
       {"muscles.agonist.plant.geometry.length_mm.x=1",
        "muscles.agonist.plant.geometry.length_mm: is a value, not a table"},
       {"muscles.agonist.plant.bladder.diameter_mm=40",
        "muscles.agonist.plant.bladder.diameter_mm: must be 0"},
       {"muscles.pam.plant.geometry.wall_thickness_mm=1", "muscles.pam"},
       // no value at all (a fuzzer's finding: it threw std::out_of_range)
       {"muscles.agonist.plant=", "muscles.agonist.plant"},
       {"muscles.agonist.plant.geometry.wall_thickness_mm=  ", pamsim_test::kAgonistWall}});
  // a plant table without its file
  const auto dir = pamsim_test::fresh_dir("plant_keys_nofile");
  const std::string variant = pamsim_test::scenario_variant(
      dir, "reaching.toml",
      "plant = \"" + std::string(PAMSIM_SOURCE_DIR) + "/models/pams/plant_agonist.toml\"",
      "plant = { geometry = { wall_thickness_mm = 1.5 } }");
  try {
    load_scenario(variant);
    ADD_FAILURE() << "a plant table without file accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("muscles.agonist.plant.file is required"),
              std::string::npos)
        << e.what();
  }
}

// A mass scales the model's inertia; an inertia given replaces it, with or without a mass.
TEST(ScenarioBodyKeysTest, InertiaReplacesTheModelsAndAMassAloneScalesIt) {
  auto inertia = [](const Scenario& sc, const char* body) {
    const TrialModel tm = load_trial_model(sc);
    const int b = mj_name2id(tm.model.get(), mjOBJ_BODY, body);
    const mjtNum* i = tm.model->body_inertia + 3 * b;
    return std::array<double, 3>{i[0], i[1], i[2]};
  };
  const Scenario base = load_scenario(kReaching);
  const std::array<double, 3> model = inertia(base, "basket");
  const std::array<double, 3> doubled = inertia(
      load_scenario(kReaching, {"bodies.basket.mass_kg=" + std::to_string(2 * 0.0831)}), "basket");
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(doubled[k], 2 * model[k], 1e-6 * model[k]);
  const std::array<double, 3> given{1e-4, 2e-4, 2.5e-4};
  const Scenario set =
      load_scenario(kReaching, {"bodies.basket.inertia_kg_m2=[1e-4, 2e-4, 2.5e-4]"});
  EXPECT_EQ(inertia(set, "basket"), given);
  EXPECT_FALSE(same_trial_model(base, set));
  EXPECT_EQ(inertia(load_scenario(kReaching, {"bodies.basket.inertia_kg_m2=[1e-4, 2e-4, 2.5e-4]",
                                              "bodies.basket.mass_kg=1"}),
                    "basket"),
            given);
  // the drop's ball: its mass from [drop], its inertia from bodies.ball
  const std::string drop = std::string(PAMSIM_SOURCE_DIR) + "/scenarios/drop_mass.toml";
  EXPECT_EQ(inertia(load_scenario(drop, {"bodies.ball.inertia_kg_m2=[3e-5, 3e-5, 3e-5]"}), "ball"),
            (std::array<double, 3>{3e-5, 3e-5, 3e-5}));
}

TEST(ScenarioPneumaticsKeysTest, ASetFieldChangesThatFieldOfThePneumaticsFileOnly) {
  const Scenario base = load_scenario(kReaching);
  const Scenario changed =
      load_scenario(kReaching, {kTube + "=20", "pneumatics.gas.polytropic_index=1.4"});
  EXPECT_DOUBLE_EQ(changed.pneumatics.tube_dead_volume_m3, 20e-6);
  EXPECT_EQ(changed.pneumatics.polytropic_index, 1.4);
  EXPECT_NE(base.pneumatics.tube_dead_volume_m3, changed.pneumatics.tube_dead_volume_m3);
  EXPECT_EQ(base.pneumatics.temperature_k, changed.pneumatics.temperature_k);
  EXPECT_EQ(base.pneumatics.sonic_conductance_m3_per_s_pa,
            changed.pneumatics.sonic_conductance_m3_per_s_pa);
  // the file itself, read alone, is as it was
  EXPECT_EQ(load_pneumatic_params(base.pneumatics_file).tube_dead_volume_m3,
            base.pneumatics.tube_dead_volume_m3);
  // a valve.* key still has the last word over the file's field it overrides
  const Scenario both =
      load_scenario(kReaching, {"pneumatics.supply.supply_MPa=0.95", "valve.supply_MPa=0.9"});
  EXPECT_DOUBLE_EQ(both.pneumatics.supply_gauge_pa, 0.9e6);
}

TEST(ScenarioPneumaticsKeysTest, TheRunFoldersScenarioKeepsTheFields) {
  const auto dir = pamsim_test::fresh_dir("pneumatics_keys_recorded");
  const RecordedScenario r = load_recorded_scenario(pamsim_test::read_file(kReaching), kReaching,
                                                    {kTube + "=20"}, dir.string(), "");
  pamsim_test::write_text(dir / "scenario.toml", r.resolved_toml);
  const Scenario again = load_scenario((dir / "scenario.toml").string());
  EXPECT_DOUBLE_EQ(again.pneumatics.tube_dead_volume_m3, 20e-6);
}

TEST(ScenarioPneumaticsKeysTest, BadFieldsNameTheirScenarioKey) {
  expect_refused({{kTube + "=-1", kTube + ": "},
                  {kTube + "=nan", kTube + ": "},
                  {"pneumatics.gas.polytropic_index=1.6", "pneumatics.gas.polytropic_index: "},
                  {"pneumatics.chamber.colour=1", "pneumatics.chamber.colour: unknown key"},
                  {"pneumatics.pipes.length_m=1", "pneumatics.pipes: unknown table"},
                  {"pneumatics.solver.method=\"rk4\"", "pneumatics.solver.method: unknown value"},
                  {"pneumatics=3", "pneumatics must be a table"}},
                 "pneumatics.toml");  // named by its key, not by the file
}

}  // namespace
}  // namespace pamsim
