// cli_plant_test.cc: the lab's pipeline from a physical plant to its estimator, as a user
// runs it: `pamsim tensile --plant` on the AVBDL plant, `pamsim fit --sensors-from` to an
// estimator file, then the pulley with that plant and that estimator: the estimator's
// error falls from what Table IV's law gets wrong about the plant to a fit's residual, in
// the papers' Table III range. And the commands' bad input: one line, exit 2.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "sim/cli_util.h"

namespace {

namespace fs = std::filesystem;
using pamsim_test::CliResult;
using pamsim_test::fresh_dir;
using pamsim_test::line_count;
using pamsim_test::run_pamsim;

// agonist_line_mm of a calibration file `pamsim calibrate` wrote
double agonist_line_mm(const std::string& path) {
  const std::string text = pamsim_test::read_file(path);
  const std::string key = "\nagonist_line_mm = ";
  const auto at = text.find(key);
  EXPECT_NE(at, std::string::npos) << path;
  return at == std::string::npos ? NAN : std::stod(text.substr(at + key.size()));
}

double estimate_rmse_pct(const fs::path& out) {
  std::ifstream in(out / "summary.json");
  return nlohmann::json::parse(in)["length_est_rmse_pam_pct"].get<double>();
}

// The drop scenarios' and the leg's estimators (models/pams/fitted_*.toml,
// models/pams/leg/fitted_*.toml, models/pams/table1/fitted_*.toml) are what the lab's pipeline
// (scripts/fit-estimators.sh) gives for the shipped plants today: a plant file changed
// without refitting fails here. Every line but the provenance, which names the CSV.
TEST(CliPlantTest, CommittedFittedEstimatorsAreWhatThePipelineWrites) {
  const fs::path out = fresh_dir("refit");
  const std::string cmd = std::string("bash ") + PAMSIM_SOURCE_DIR + "/scripts/fit-estimators.sh " +
                          PAMSIM_BINARY + " " + out.string() + " > /dev/null 2>&1";
  ASSERT_EQ(std::system(cmd.c_str()), 0) << cmd;
  for (const char* m : {"agonist", "antagonist", "leg/IL", "leg/GM", "leg/RF", "leg/VAS", "leg/BFS",
                        "leg/GAS", "leg/SOL", "leg/TA", "table1/agonist", "table1/antagonist"}) {
    SCOPED_TRACE(m);
    // "leg/IL" -> leg/fitted_IL.toml
    std::string name = m;
    const std::size_t slash = name.find('/');
    const std::string file = slash == std::string::npos ? "fitted_" + name + ".toml"
                                                        : name.substr(0, slash + 1) + "fitted_" +
                                                              name.substr(slash + 1) + ".toml";
    std::istringstream fresh(pamsim_test::read_file(out / file));
    std::istringstream shipped(
        pamsim_test::read_file(std::string(PAMSIM_SOURCE_DIR) + "/models/pams/" + file));
    std::string a, b;
    int lines = 0;
    while (std::getline(fresh, a)) {
      ASSERT_TRUE(std::getline(shipped, b)) << "shipped file shorter at line " << lines + 1;
      ++lines;
      if (a.rfind("source = ", 0) == 0) continue;
      EXPECT_EQ(a, b);
    }
    EXPECT_FALSE(std::getline(shipped, b)) << "shipped file longer";
    EXPECT_GT(lines, 15);
  }
}

TEST(CliPlantTest, TensileTestThenFitGivesTheEstimatorItsTableIIIAccuracy) {
  const fs::path dir = fresh_dir("plant_pipeline");
  const std::string csv = (dir / "tensile.csv").string();
  const std::string fitted = (dir / "fitted.toml").string();
  const std::string plant = " --set 'muscles.pam.plant=\"../models/pams/plant_agonist.toml\"'";

  CliResult r = run_pamsim("tensile --plant models/pams/plant_agonist.toml -o " + csv);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  r = run_pamsim("fit --model eq3 " + csv + " --sensors-from models/pams/table4_agonist.toml -o " +
                 fitted);
  ASSERT_EQ(r.exit_code, 0) << r.err;

  r = run_pamsim("run scenarios/pulley_sine_5kg.toml --set sim.duration_s=10" + plant + " --out " +
                 (dir / "table4").string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  r = run_pamsim("run scenarios/pulley_sine_5kg.toml --set sim.duration_s=10" + plant +
                 " --set 'muscles.pam.params=\"" + fitted + "\"' --out " + (dir / "fit").string());
  ASSERT_EQ(r.exit_code, 0) << r.err;

  const double table4 = estimate_rmse_pct(dir / "table4");
  const double fit = estimate_rmse_pct(dir / "fit");
  EXPECT_GT(table4, 1.7) << "Table IV's law is not this plant's";
  EXPECT_GT(fit, 0.1) << "a fit of Eq. (3) is not the AVBDL law either";
  EXPECT_LT(fit, 1.7) << "Yoshida and Hosoda, Table III: 0.35-1.7 %";
  EXPECT_LT(fit, 0.5 * table4);
}

// `calibrate` solves the arm's lines with the plants' law, so the arm rests at the start
// angle with physical muscles as it does with the spring law.
TEST(CliPlantTest, CalibrateWithPlantsHoldsTheArmAtItsStartAngle) {
  const fs::path dir = fresh_dir("plant_calibrate");
  const std::string calibration = (dir / "calibration.toml").string();
  const std::string plants =
      " --set 'muscles.agonist.plant=\"../models/pams/plant_agonist.toml\"'"
      " --set 'muscles.antagonist.plant=\"../models/pams/plant_agonist.toml\"'";
  CliResult r =
      run_pamsim("calibrate scenarios/drop_mass_passive.toml" + plants + " -o " + calibration);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  r = run_pamsim("run scenarios/drop_mass_passive.toml" + plants + " --set 'model.calibration=\"" +
                 calibration +
                 "\"' --set drop.enabled=false"
                 " --set sim.duration_s=2 --out " +
                 (dir / "rest").string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  std::ifstream in(dir / "rest" / "summary.json");
  const nlohmann::json s = nlohmann::json::parse(in);
  EXPECT_NEAR(s["final_angle_deg"].get<double>(), -36.0, 0.05);
  // and the spring-law lines would not: the plants need other lines
  const std::string spring = (dir / "spring.toml").string();
  ASSERT_EQ(run_pamsim("calibrate scenarios/drop_mass_passive.toml -o " + spring).exit_code, 0);
  EXPECT_GT(std::fabs(agonist_line_mm(calibration) - agonist_line_mm(spring)), 1.0);
}

TEST(CliPlantTest, BadPipelineInputIsOneLineAndExit2) {
  const fs::path dir = fresh_dir("plant_bad");
  const std::string out = (dir / "x.csv").string();
  for (const std::string& args : std::vector<std::string>{
           "tensile -o " + out,
           "tensile --params models/pams/table4_agonist.toml --plant models/pams/plant_agonist.toml"
           " -o " +
               out,
           "tensile --plant models/pams/missing.toml -o " + out,
           "tensile --plant models/pams/table4_agonist.toml -o " + out,
           // beyond the plant's fibre length: refused, not NaN rows
           "tensile --plant models/pams/plant_agonist.toml --max-deformation-mm 60 -o " + out}) {
    const CliResult r = run_pamsim(args);
    EXPECT_EQ(r.exit_code, 2) << args;
    EXPECT_EQ(line_count(r.err), 1) << args << ": " << r.err;
    EXPECT_FALSE(fs::exists(out)) << args;
  }
  ASSERT_EQ(run_pamsim("tensile --plant models/pams/plant_agonist.toml -o " + out).exit_code, 0);
  const std::string fitted = (dir / "f.toml").string();
  const CliResult r = run_pamsim("fit --model eq3 " + out +
                                 " --sensors-from models/pams/missing.toml -o " + fitted);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(line_count(r.err), 1) << r.err;
  EXPECT_NE(r.err.find("missing.toml"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(fitted));
  // a sensors file without the gauge calibration, or nowhere to write it: refused
  const std::string no_gauge = (dir / "no_gauge.toml").string();
  pamsim_test::write_text(no_gauge,
                          "name = \"x\"\n[spring]\nlaw = \"eq3\"\nunits = { pressure = "
                          "\"MPa\", length = \"mm\", force = \"N\" }\nm = -60.0\n"
                          "h = 170.0\na0 = 1.0\na1 = 0.0\na2 = 7.0\na3 = 0.0\n");
  for (const std::string& args :
       {"fit --model eq3 " + out + " --sensors-from " + no_gauge + " -o " + fitted,
        "fit --model eq3 " + out + " --sensors-from models/pams/table4_agonist.toml"}) {
    const CliResult bad = run_pamsim(args);
    EXPECT_EQ(bad.exit_code, 2) << args;
    EXPECT_EQ(line_count(bad.err), 1) << args << ": " << bad.err;
    EXPECT_NE(bad.err.find("--sensors-from"), std::string::npos) << bad.err;
    EXPECT_FALSE(fs::exists(fitted));
  }
}

}  // namespace

// --set changes a plant field in the file's units exactly as the file itself would; a bad one
// is refused in one line naming it
TEST(CliPlantTest, TensileSetChangesAPlantFieldAsEditingTheFileWould) {
  const fs::path dir = fresh_dir("plant_set");
  const std::string plant = "models/pams/plant_agonist.toml";
  const std::string set = (dir / "set.csv").string(), edited = (dir / "edited.csv").string();
  const std::string original = (dir / "original.csv").string();
  std::string text = pamsim_test::read_file(plant);
  const std::string field = "wall_thickness_mm = 2.0";
  ASSERT_NE(text.find(field), std::string::npos);
  text.replace(text.find(field), field.size(), "wall_thickness_mm = 1.5");
  const std::string edited_plant = (dir / "plant.toml").string();
  pamsim_test::write_text(edited_plant, text);
  ASSERT_EQ(
      run_pamsim("tensile --plant " + plant + " --set geometry.wall_thickness_mm=1.5 -o " + set)
          .exit_code,
      0);
  ASSERT_EQ(run_pamsim("tensile --plant " + edited_plant + " -o " + edited).exit_code, 0);
  ASSERT_EQ(run_pamsim("tensile --plant " + plant + " -o " + original).exit_code, 0);
  EXPECT_EQ(pamsim_test::read_file(set), pamsim_test::read_file(edited));
  EXPECT_NE(pamsim_test::read_file(set), pamsim_test::read_file(original));
  const std::string out = (dir / "bad.csv").string();
  for (const auto& [args, key] : std::vector<std::pair<std::string, std::string>>{
           {"--plant " + plant + " --set geometry.wall_thickness_mm=-1", "wall_thickness_mm"},
           {"--plant " + plant + " --set geometry.thickness_mm=1", "thickness_mm"},
           {"--plant " + plant + " --set geometry.wall_thickness_mm", "wall_thickness_mm"},
           {"--params models/pams/table4_agonist.toml --set geometry.length_mm=170", "--plant"}}) {
    const CliResult r = run_pamsim("tensile " + args + " -o " + out);
    EXPECT_EQ(r.exit_code, 2) << args;
    EXPECT_EQ(line_count(r.err), 1) << args << ": " << r.err;
    EXPECT_NE(r.err.find(key), std::string::npos) << args << ": " << r.err;
    EXPECT_FALSE(fs::exists(out)) << args;
  }
}
