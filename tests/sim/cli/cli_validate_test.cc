// cli_validate_test.cc: `pamsim validate length-estimation` and `pamsim validate reaching` as
// a user runs them: complete tables (every PAM, law and weight; finite values) and their
// figures, the same bytes for the same seed, and bad input refused in one line with no
// table left behind.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "sim/cli_util.h"

namespace {

namespace fs = std::filesystem;
using pamsim_test::CliResult;
using pamsim_test::fresh_dir;
using pamsim_test::line_count;
using pamsim_test::read_file;
using pamsim_test::run_pamsim;

std::vector<std::vector<std::string>> csv_rows(const std::string& text) {
  std::vector<std::vector<std::string>> rows;
  std::istringstream in(text);
  std::string line;
  while (std::getline(in, line)) {
    std::vector<std::string> cells;
    std::string cell;
    std::istringstream l(line);
    while (std::getline(l, cell, ',')) cells.push_back(cell);
    if (!line.empty() && line.back() == ',') cells.push_back("");
    rows.push_back(cells);
  }
  return rows;
}

TEST(CliValidateTest, LengthEstimationWritesEveryPamLawAndWeight) {
  const fs::path out = fresh_dir("cli_validate_le");
  const CliResult r = run_pamsim("validate length-estimation --threads 2 --out " + out.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto rows = csv_rows(read_file(out / "table3.csv"));
  ASSERT_EQ(rows.size(), 1u + 4 * 3 * 2);  // header, PAMs A-D x Eq. (3)-(5) x 5 / 10 kg
  EXPECT_EQ(rows[0][4], "max_error_pct");
  for (std::size_t i = 1; i < rows.size(); ++i) {
    ASSERT_EQ(rows[i].size(), 11u) << i;
    EXPECT_EQ(rows[i][3], "ok") << i;
    for (int c : {4, 5, 6, 7, 8, 9, 10}) {  // the simulation's, the paper's, the fit's
      ASSERT_FALSE(rows[i][c].empty()) << "row " << i << " column " << c;
      EXPECT_TRUE(std::isfinite(std::stod(rows[i][c]))) << "row " << i << " column " << c;
    }
  }
  for (const char* pam : {"A", "B", "C", "D"}) {
    EXPECT_TRUE(fs::exists(out / ("pam_" + std::string(pam) + ".png"))) << pam;
    EXPECT_TRUE(fs::exists(out / "fits" / ("pam_" + std::string(pam) + "_eq4.toml"))) << pam;
  }
  // docs/validation.md's Table III, Eq. (3) at 5 kg, to its digits: a change to the PAMs'
  // physics (PAMs A-C as Table I builds them) shows here, and the page's block is
  // made again with it
  const std::map<std::string, double> readme_rmse = {
      {"A", 0.438}, {"B", 0.459}, {"C", 0.458}, {"D", 0.475}};
  int pinned = 0;
  for (std::size_t i = 1; i < rows.size(); ++i) {
    if (rows[i][1] != "eq3" || rows[i][2] != "5") continue;
    EXPECT_NEAR(std::stod(rows[i][5]), readme_rmse.at(rows[i][0]), 0.0005) << rows[i][0];
    ++pinned;
  }
  EXPECT_EQ(pinned, 4) << "PAMs A-D, Eq. (3), 5 kg";
  const std::string md = read_file(out / "table3.md");
  EXPECT_NE(md.find("| Eq. (5) |"), std::string::npos);
  EXPECT_NE(md.find("(1.72 / 0.861)"), std::string::npos) << "Table III's PAM-A Eq. (3) beside";
  EXPECT_EQ(r.out, md) << "the table is also printed";
}

TEST(CliValidateTest, ReachingWritesTableVAndFigure7) {
  const fs::path out = fresh_dir("cli_validate_re");
  const CliResult r = run_pamsim("validate reaching --out " + out.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto rows = csv_rows(read_file(out / "table5.csv"));
  ASSERT_EQ(rows.size(), 1u + 2 * 2 * 3);  // muscles x methods x (all, before, after)
  for (std::size_t i = 1; i < rows.size(); ++i) {
    if (rows[i][2] != "all") continue;
    EXPECT_TRUE(std::isfinite(std::stod(rows[i][4]))) << i;
    EXPECT_TRUE(std::isfinite(std::stod(rows[i][5]))) << i;
  }
  EXPECT_TRUE(fs::exists(out / "fig7.png"));
  EXPECT_NE(read_file(out / "table5.md").find("(8.82 / 5.24)"), std::string::npos);
}

// The outputs appear as one set: --no-plot writes no figure, a rerun is refused without
// --force, and a forced rerun replaces the whole set (no figure of the earlier run left
// beside tables that have none); provenance.json names the protocol.
TEST(CliValidateTest, OutputsAreOneSetReplacedOnlyWithForce) {
  const fs::path out = fresh_dir("cli_validate_set");
  const std::string args = "validate reaching --quiet --out " + out.string();
  ASSERT_EQ(run_pamsim(args).exit_code, 0);
  EXPECT_TRUE(fs::exists(out / "fig7.png"));
  const std::string table = read_file(out / "table5.csv");
  const CliResult refused = run_pamsim(args + " --no-plot");
  EXPECT_EQ(refused.exit_code, 2);
  EXPECT_EQ(line_count(refused.err), 1) << refused.err;
  EXPECT_TRUE(fs::exists(out / "fig7.png"));
  const CliResult forced = run_pamsim(args + " --no-plot --force");
  ASSERT_EQ(forced.exit_code, 0) << forced.err;
  EXPECT_EQ(forced.err.find("pamsim validate reaching:"), std::string::npos)
      << "--quiet: no progress lines: " << forced.err;
  EXPECT_FALSE(fs::exists(out / "fig7.png")) << "the earlier run's figure went with its set";
  EXPECT_EQ(read_file(out / "table5.csv"), table);
  const std::string provenance = read_file(out / "provenance.json");
  EXPECT_NE(provenance.find("\"command\": \"validate reaching\""), std::string::npos) << provenance;
  EXPECT_NE(provenance.find("validate_reaching.toml"), std::string::npos) << provenance;
}

TEST(CliValidateTest, SameSeedSameBytesAnotherSeedOtherNumbers) {
  const fs::path a = fresh_dir("cli_validate_s1"), b = fresh_dir("cli_validate_s2"),
                 c = fresh_dir("cli_validate_s3");
  const std::string args = "validate length-estimation --pams D --set sim.duration_s=5 ";
  ASSERT_EQ(run_pamsim(args + "--seed 7 --threads 1 --out " + a.string()).exit_code, 0);
  ASSERT_EQ(run_pamsim(args + "--seed 7 --threads 2 --out " + b.string()).exit_code, 0);
  ASSERT_EQ(run_pamsim(args + "--seed 8 --threads 2 --out " + c.string()).exit_code, 0);
  EXPECT_EQ(read_file(a / "table3.csv"), read_file(b / "table3.csv"));
  EXPECT_EQ(read_file(a / "table3.md"), read_file(b / "table3.md"));
  EXPECT_NE(read_file(a / "table3.csv"), read_file(c / "table3.csv"));
}

TEST(CliValidateTest, BadInputIsOneLineAndLeavesNoTable) {
  const fs::path dir = fresh_dir("cli_validate_bad");
  // a protocol whose PAM-A plant has a braid angle no braid can have
  std::string plant = read_file(fs::path(PAMSIM_SOURCE_DIR) / "models/pams/plant_pam_a.toml");
  plant.replace(plant.find("braid_angle_deg = 25"), 20, "braid_angle_deg = 60");
  pamsim_test::write_text(dir / "bad_plant.toml", plant);
  std::string protocol =
      read_file(fs::path(PAMSIM_SOURCE_DIR) / "scenarios/validate_length_estimation.toml");
  const std::string src = "\"../models/pams/plant_pam_a.toml\"";
  protocol.replace(protocol.find(src), src.size(), "\"" + (dir / "bad_plant.toml").string() + "\"");
  std::string rig = "rig = \"pulley_sine_5kg.toml\"";
  protocol.replace(
      protocol.find(rig), rig.size(),
      "rig = \"" + std::string(PAMSIM_SOURCE_DIR) + "/scenarios/pulley_sine_5kg.toml\"");
  const std::string gauge = "\"../models/pams/table4_agonist.toml\"";
  protocol.replace(protocol.find(gauge), gauge.size(),
                   "\"" + std::string(PAMSIM_SOURCE_DIR) + "/models/pams/table4_agonist.toml\"");
  for (const char* p : {"B", "C", "D"}) {
    const std::string path =
        "\"../models/pams/plant_pam_" + std::string(1, char(p[0] + 32)) + ".toml\"";
    protocol.replace(protocol.find(path), path.size(),
                     "\"" + std::string(PAMSIM_SOURCE_DIR) + "/models/pams/plant_pam_" +
                         std::string(1, char(p[0] + 32)) + ".toml\"");
  }
  pamsim_test::write_text(dir / "protocol.toml", protocol);

  const fs::path out = dir / "out";
  fs::create_directories(dir / "a_file");
  pamsim_test::write_text(dir / "a_file" / "f", "x");
  struct Case {
    std::string args, says;
  };
  for (const Case& c : std::vector<Case>{
           {"validate length-estimation --pams A,X --out " + out.string(), "unknown PAM X"},
           {"validate length-estimation --out " + (dir / "a_file" / "f" / "sub").string(),
            (dir / "a_file" / "f" / "sub").string()},
           {"validate length-estimation " + (dir / "protocol.toml").string() + " --out " +
                out.string(),
            "braid_angle"},
           {"validate length-estimation --set nosuch.key=1 --out " + out.string(), "nosuch.key"},
           {"validate reaching --set sim.duration_s=5 --out " + out.string(), "window_s"},
           {"validate reaching --threads -1 --out " + out.string(), "--threads"},
           {"validate reaching --out /proc/pamsim_validate_out", "/proc/pamsim_validate_out"},
           {"validate length-estimation --pams B,B --out " + out.string(), "named twice"},
           {"validate length-estimation --set bodies.weight.mass_kg=3 --out " + out.string(),
            "set per trial"}}) {
    const CliResult r = run_pamsim(c.args);
    EXPECT_NE(r.exit_code, 0) << c.args;
    EXPECT_EQ(line_count(r.err), 1) << c.args << ": " << r.err;
    EXPECT_NE(r.err.find(c.says), std::string::npos) << c.args << ": " << r.err;
    EXPECT_FALSE(fs::exists(out / "table3.csv")) << c.args;
    EXPECT_FALSE(fs::exists(out / "table5.csv")) << c.args;
  }
}

// A reaching protocol of one short trial with the given [[budget_source]] tables (the
// shipped scenario, its path made absolute), written into dir.
fs::path budget_protocol(const fs::path& dir, const std::string& sources) {
  pamsim_test::write_text(dir / "budget.toml", "scenario = \"" + std::string(PAMSIM_SOURCE_DIR) +
                                                   "/scenarios/reaching.toml\"\n"
                                                   "trials = 1\nwindow_s = [2.0, 4.0]\n" +
                                                   sources);
  return dir / "budget.toml";
}

const char kBudgetSources[] =
    "[[budget_source]]\nname = \"white noise\"\n"
    "on = [\"sensors.noise_scale=1\"]\noff = [\"sensors.noise_scale=0\"]\n"
    "[[budget_source]]\nname = \"pressure sensor\"\n"
    "on = ['sensors.pressure.model=\"pse540\"']\n";

// --budget: the runs none, all, each alone and all but each, for every case; the table
// printed is the file; the same bytes on one and two threads.
TEST(CliValidateTest, BudgetHasEveryRunOfEveryCaseOnAnyThreadCount) {
  const fs::path dir = fresh_dir("cli_validate_budget");
  const fs::path protocol = budget_protocol(dir, kBudgetSources);
  // the shipped scenario's other instruments as hardware too would stay on in every run
  const std::string args = "validate reaching " + protocol.string() +
                           " --budget --set sim.duration_s=5 --set 'sensors.fiber.model=\"ideal\"'"
                           " --set 'sensors.encoder.model=\"ideal\"' --out ";
  const CliResult r = run_pamsim(args + (dir / "a").string() + " --threads 2");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto rows = csv_rows(read_file(dir / "a" / "budget.csv"));
  ASSERT_EQ(rows.size(), 1u + 4 * 6);  // (agonist, antagonist) x (model, fiber) x 6 runs
  EXPECT_EQ(rows[1][0], "agonist model");
  EXPECT_EQ(rows[1][1], "none");
  EXPECT_EQ(rows[6][1], "all but pressure sensor");
  EXPECT_EQ(rows[6][2], "pressure sensor");
  for (std::size_t i = 1; i < rows.size(); ++i) {
    EXPECT_TRUE(std::isfinite(std::stod(rows[i][4]))) << i;
  }
  // the fiber's only error without noise is the integration's rounding; with it, far more
  EXPECT_LT(std::stod(rows[6 + 1][4]), 1e-9) << "agonist fiber, none";
  EXPECT_GT(std::stod(rows[6 + 3][4]), 0.05) << "agonist fiber, only white noise";
  EXPECT_TRUE(fs::exists(dir / "a" / "budget.png"));
  EXPECT_EQ(r.out, read_file(dir / "a" / "budget.md"));
  ASSERT_EQ(run_pamsim(args + (dir / "b").string() + " --threads 1 --no-plot").exit_code, 0);
  EXPECT_EQ(read_file(dir / "a" / "budget.csv"), read_file(dir / "b" / "budget.csv"));
  EXPECT_FALSE(fs::exists(dir / "b" / "budget.png"));
}

TEST(CliValidateTest, BadBudgetIsOneLineAndLeavesNoBudget) {
  const fs::path dir = fresh_dir("cli_validate_budget_bad");
  const fs::path out = dir / "out";
  struct Case {
    std::string protocol, set, says;
  };
  for (const Case& c : std::vector<Case>{
           {"", "", "budget_source: --budget needs at least one [[budget_source]]"},
           {"[[budget_source]]\nname = \"p\"\non = ['sensors.pressure.model=\"psx\"']\n", "",
            "budget source \"p\" on: "},
           {"[[budget_source]]\nname = \"p\"\non = ['sensors.nosuch=1']\n", "", "sensors.nosuch"},
           {kBudgetSources, " --set sensors.noise_scale=2", "sets sensors.noise_scale"},
           {"[[budget_source]]\nname = \"p\"\non = []\n", "", "budget_source[0].on"}}) {
    const fs::path protocol = budget_protocol(dir, c.protocol);
    const CliResult r = run_pamsim("validate reaching " + protocol.string() + " --budget" + c.set +
                                   " --out " + out.string());
    EXPECT_EQ(r.exit_code, 2) << c.says;
    EXPECT_EQ(line_count(r.err), 1) << c.says << ": " << r.err;
    EXPECT_NE(r.err.find(c.says), std::string::npos) << r.err;
    EXPECT_NE(r.err.find(protocol.string()), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(out / "budget.csv")) << c.says;
  }
}

const char kBandBrackets[] =
    "[[bracket]]\nname = \"line re-seated\"\nkey = \"sensors.gauge.contact.reseat_mm\"\n"
    "from = -2.9\nto = 2.9\nsource = \"the stick band\"\n"
    "[[bracket]]\nname = \"line\"\nkey = \"muscles.agonist.line_diameter_mm\"\n"
    "from = 0.285\nto = 0.711\nsource = \"line sizes\"\n";

// the line's modulus, which its drawn diameter needs (the shipped protocol's line source sets it)
const std::string kLineModulus = "muscles.agonist.line_modulus_MPa=2000";

// --bands: every cell twice (max, RMSE) over the rigs, each rig's draws in draws.csv, the
// table printed is the file, the same bytes on one and two threads; --sensitivity: each
// bracket's swing per cell
TEST(CliValidateTest, BandsDrawEveryRigAndAreTheSameOnAnyThreadCount) {
  const fs::path dir = fresh_dir("cli_validate_bands");
  const fs::path protocol =
      budget_protocol(dir, std::string("[paper]\nmodel_agonist = [8.82, 5.24]\n") + kBandBrackets);
  const std::string args = "validate reaching " + protocol.string() +
                           " --bands 3 --set sim.duration_s=5 --set " + kLineModulus + " --out ";
  const CliResult r = run_pamsim(args + (dir / "a").string() + " --threads 2");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto rows = csv_rows(read_file(dir / "a" / "bands.csv"));
  ASSERT_EQ(rows.size(), 1u + 12 * 2);  // 2 muscles x 2 methods x 3 parts, max and RMSE
  EXPECT_EQ(rows[2][0], "agonist model all");
  EXPECT_EQ(rows[2][1], "rmse");
  EXPECT_EQ(rows[2][2], "3");
  EXPECT_EQ(rows[2][9], "outside");  // 5.24 %: far above a 2 s window's error
  const auto draws = csv_rows(read_file(dir / "a" / "draws.csv"));
  ASSERT_EQ(draws.size(), 4u);
  EXPECT_EQ(draws[0][1], "sensors.gauge.contact.reseat_mm");
  EXPECT_NE(draws[1][1], draws[2][1]);
  EXPECT_EQ(r.out, read_file(dir / "a" / "bands.md"));
  EXPECT_TRUE(fs::exists(dir / "a" / "bands.png"));
  ASSERT_EQ(run_pamsim(args + (dir / "b").string() + " --threads 1 --no-plot").exit_code, 0);
  EXPECT_EQ(read_file(dir / "a" / "bands.csv"), read_file(dir / "b" / "bands.csv"));
  EXPECT_EQ(read_file(dir / "a" / "draws.csv"), read_file(dir / "b" / "draws.csv"));

  const CliResult s = run_pamsim("validate reaching " + protocol.string() +
                                 " --sensitivity --set sim.duration_s=5 --set " + kLineModulus +
                                 " --no-plot --out " + (dir / "s").string());
  ASSERT_EQ(s.exit_code, 0) << s.err;
  const auto swings = csv_rows(read_file(dir / "s" / "sensitivity.csv"));
  ASSERT_EQ(swings.size(), 1u + 12 * 2);  // a row per cell and bracket
  // the re-seated line moves the agonist's model estimate; it cannot move the fiber's
  EXPECT_GT(std::stod(swings[1][7]), 0.01) << "agonist model all, line re-seated";
  EXPECT_EQ(std::stod(swings[7][7]), 0.0) << swings[7][0];
}

TEST(CliValidateTest, BadBandsAreOneLineAndLeaveNoBands) {
  const fs::path dir = fresh_dir("cli_validate_bands_bad");
  const fs::path out = dir / "out";
  const std::string creep =
      std::string(kBandBrackets) +
      "[[bracket]]\nname = \"creep\"\nkey = \"sensors.gauge.board.creep_exponent\"\n"
      "from = 0.2\nto = 0.9\nsource = \"s\"\n";
  struct Case {
    std::string protocol, args, says;
  };
  for (const Case& c : std::vector<Case>{
           {kBandBrackets, " --bands 0", "--bands must be in [1, 10000], got 0"},
           {"", " --bands 2", "bracket: --bands and --sensitivity need at least one"},
           {"[[bracket]]\nname = \"a\"\nkey = \"sim.duration_s\"\nfrom = 3\nto = 2\n"
            "source = \"s\"\n",
            " --bands 2", "bracket[0].from must be below to"},
           {creep, " --bands 2", "bracket \"creep\" (sensors.gauge.board.creep_exponent = 0.9): "},
           {kBandBrackets, " --sensitivity --set muscles.agonist.line_diameter_mm=0.3",
            "is drawn by"},
           {kBandBrackets, " --bands 2 --budget", "excludes"},
           {kBandBrackets, " --assumptions", "--assumptions needs --bands or --sensitivity"}}) {
    const fs::path protocol = budget_protocol(dir, c.protocol);
    const CliResult r = run_pamsim("validate reaching " + protocol.string() + c.args + " --set " +
                                   kLineModulus + " --out " + out.string());
    EXPECT_EQ(r.exit_code, 2) << c.says;
    EXPECT_EQ(line_count(r.err), 1) << c.says << ": " << r.err;
    EXPECT_NE(r.err.find(c.says), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(out / "bands.csv")) << c.says;
    EXPECT_FALSE(fs::exists(out / "sensitivity.csv")) << c.says;
  }
}

}  // namespace

// A rig whose line would break is refused (line_breaks.h): one line naming the key, exit 2,
// and not even the output folder the run had made is left
TEST(CliValidateTest, ARigWhoseLineBreaksIsOneLineAndLeavesNoFolder) {
  const fs::path out = fresh_dir("cli_validate_line_breaks") / "out";
  const CliResult r = run_pamsim(
      "validate reaching scenarios/validate_reaching.toml --no-plot --quiet"
      " --set muscles.antagonist.line_diameter_mm=0.285"
      " --set muscles.antagonist.line_modulus_MPa=2000"
      " --set muscles.antagonist.line_strength_MPa=920 --out " +
      out.string());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(line_count(r.err), 1) << r.err;
  EXPECT_NE(r.err.find("muscles.antagonist.line_strength_MPa: its line breaks"), std::string::npos)
      << r.err;
  EXPECT_FALSE(fs::exists(out));
}
