// tune_db_inputs_test.cc: a tuning database keeps its base scenario's input files
// fingerprinted, and a resume after one of them changed is refused naming it (its stored
// evaluations belong to the model as it was).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "base/input_error.h"
#include "sim/cli_util.h"
#include "sim/optimize/tune_db.h"
#include "sim/optimize/tuning_file.h"

namespace pamsim {
namespace {

namespace fs = std::filesystem;

TEST(TuneDbInputsTest, AResumeAfterAnInputFileChangedIsRefused) {
  const fs::path dir = pamsim_test::fresh_dir("tune_db_inputs");
  fs::copy_file(std::string(PAMSIM_SOURCE_DIR) + "/models/pams/plant_agonist.toml",
                dir / "plant_agonist.toml");
  const std::string base = pamsim_test::scenario_variant(
      dir, "drop_mass.toml",
      "plant = \"" + std::string(PAMSIM_SOURCE_DIR) + "/models/pams/plant_agonist.toml\"",
      "plant = \"" + (dir / "plant_agonist.toml").string() + "\"");
  pamsim_test::write_text(
      dir / "tune.toml", "base = \"" + base +
                             "\"\ngenerations = 1\npopulation = 5\nseeds = 1\nheld_out_seeds = 0\n"
                             "[[parameter]]\nkey = \"reflex.v_thr_mm_s\"\nfrom = 40.0\nto = 100.0\n"
                             "[[objective]]\nmetric = \"peak_drop_deg\"\n");
  const TuneDefinition def = load_tune_definition((dir / "tune.toml").string());
  const std::string db = (dir / "tune.db").string();
  { TuneDb made = TuneDb::create(db, def); }
  { TuneDb same = TuneDb::open_to_resume(db, def); }  // nothing changed
  std::ofstream(dir / "plant_agonist.toml", std::ios::app) << "# edited\n";
  try {
    TuneDb::open_to_resume(db, def);
    ADD_FAILURE() << "resumed on a changed plant file";
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("muscles.agonist.plant"), std::string::npos) << what;
    EXPECT_NE(what.find("changed since this tuning began"), std::string::npos) << what;
  }
}

}  // namespace
}  // namespace pamsim
