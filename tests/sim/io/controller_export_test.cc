// controller_export_test.cc: the embedded controller exported and built outside pamsim,
// back to back with the simulator: fed a trial's lossless readings (pamsim run --readings),
// the export built by its own Makefile with gcc and with clang gives the simulator's commands
// bit for bit, on the model and fiber reflexes, Ia with Ib, the leg's eight muscles, and
// estimators of Eq. (4) and Eq. (5) (whose inversion runs the cubic root solve). pamsim's own
// replay gives the same; the configuration survives its JSON; bad logs and bad exports are
// refused in one line with nothing written.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "sim/cli_util.h"
#include "sim/io/embedded_config.h"

namespace {

using namespace pamsim_test;
namespace fs = std::filesystem;

// `make` of an export in `dir` with `cc` (and more make variables), then its replay of
// `readings`: the replay's exit code and its one line
CliResult build_and_replay(const fs::path& dir, const std::string& make_vars,
                           const fs::path& readings) {
  const std::string build = "b_" + std::to_string(std::hash<std::string>{}(make_vars));
  const std::string make = "make -s -C " + dir.string() + " BUILD=" + build + " " + make_vars +
                           " > " + (dir / "make.log").string() + " 2>&1";
  CliResult r;
  if (std::system(make.c_str()) != 0) {
    r.err = "make failed: " + read_file(dir / "make.log");
    return r;
  }
  const std::string replay = (dir / build / "pamctl_replay").string() + " " + readings.string() +
                             " " + (dir / (build + ".csv")).string() + " 2> " +
                             (dir / "replay.err").string();
  const int status = std::system(replay.c_str());
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  r.err = read_file(dir / "replay.err");
  return r;
}

// a trial's readings and its controller's export, in `dir`
void export_trial(const fs::path& dir, const std::string& scenario, const std::string& set) {
  const CliResult run =
      run_pamsim("run " + scenario + set + " --readings --no-plot --out " + (dir / "run").string());
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const CliResult exported =
      run_pamsim("controller export " + scenario + set + " -o " + (dir / "export").string());
  ASSERT_EQ(exported.exit_code, 0) << exported.err;
}

// where line `n` (0: the header) of `text` starts
std::size_t line_start(const std::string& text, int n) {
  std::size_t at = 0;
  for (int k = 0; k < n; ++k) at = text.find('\n', at) + 1;
  return at;
}

void expect_bit_for_bit(const fs::path& dir) {
  for (const std::string cc : {"gcc", "clang"}) {
    const CliResult r = build_and_replay(dir / "export", "CC=" + cc, dir / "run/readings.csv");
    EXPECT_EQ(r.exit_code, 0) << cc << ": " << r.err;
    EXPECT_NE(r.err.find("commands equal"), std::string::npos) << cc << ": " << r.err;
  }
}

TEST(ControllerExportTest, BuiltOutsideItGivesTheSimulatorsCommandsBitForBit) {
  const fs::path root = fresh_dir("export_b2b");
  for (const std::string s :
       {"drop_mass", "drop_mass_fiber", "drop_mass_heavy_ia_ib", "landing_reflex"}) {
    SCOPED_TRACE(s);
    export_trial(root / s, "scenarios/" + s + ".toml", "");
    expect_bit_for_bit(root / s);
  }
}

TEST(ControllerExportTest, Eq4AndEq5EstimatorsRunTheRootSolveBitForBit) {
  const fs::path root = fresh_dir("export_eq45");
  const CliResult tensile = run_pamsim(
      "tensile --plant models/pams/plant_agonist.toml --pressures-MPa 0.2,0.4,0.6 "
      "--max-deformation-mm 15 --seed 1 -o " +
      (root / "agonist.csv").string());
  ASSERT_EQ(tensile.exit_code, 0) << tensile.err;
  for (const std::string law : {"eq4", "eq5"}) {
    SCOPED_TRACE(law);
    const fs::path params = root / ("agonist_" + law + ".toml");
    const CliResult fit =
        run_pamsim("fit --model " + law + " " + (root / "agonist.csv").string() +
                   " --sensors-from models/pams/table4_agonist.toml -o " + params.string());
    ASSERT_EQ(fit.exit_code, 0) << fit.err;
    export_trial(root / law, "scenarios/drop_mass.toml",
                 " --set model.agonist_params=" + params.string());
    expect_bit_for_bit(root / law);
  }
}

TEST(ControllerExportTest, PamsimsReplayOfAnExportEqualsTheSimulatorAndNamesItsTriggers) {
  const fs::path dir = fresh_dir("export_replay");
  export_trial(dir, "scenarios/drop_mass.toml", kShortDrop);
  for (const std::string& from : {"--export " + (dir / "export").string(),
                                  "--scenario scenarios/drop_mass.toml" + kShortDrop}) {
    SCOPED_TRACE(from);
    fs::remove_all(dir / "replay");
    const CliResult r = run_pamsim("controller replay " + (dir / "run/readings.csv").string() +
                                   " " + from + " --no-plot --out " + (dir / "replay").string());
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const nlohmann::json j = nlohmann::json::parse(read_file(dir / "replay/replay.json"));
    EXPECT_TRUE(j["commands_equal"].get<bool>());
    // the reflex triggered where the trial's summary says it first did
    const nlohmann::json summary = nlohmann::json::parse(read_file(dir / "run/summary.json"));
    const double first = summary["first_trigger_time_s"].get<double>();
    ASSERT_FALSE(j["stretch_triggers_s"]["ago"].empty());
    EXPECT_NEAR(j["stretch_triggers_s"]["ago"][0].get<double>(), first, 1e-9);
  }
}

TEST(ControllerExportTest, TheConfigurationSurvivesItsJson) {
  const fs::path dir = fresh_dir("export_json");
  ASSERT_EQ(run_pamsim("controller export scenarios/drop_mass_heavy_ia_ib.toml -o " +
                       (dir / "e").string())
                .exit_code,
            0);
  const nlohmann::json j = nlohmann::json::parse(read_file(dir / "e/pamctl_config.json"));
  std::vector<std::string> muscles;
  const pamctl_config c = pamsim::embedded_config_from_json(j, "pamctl_config.json", &muscles);
  EXPECT_EQ(pamsim::embedded_config_json(c, muscles), j);
  EXPECT_EQ(muscles, (std::vector<std::string>{"ago", "anta"}));
  EXPECT_TRUE(c.reflex.tension);
}

TEST(ControllerExportTest, BadExportsAndBadLogsAreRefusedInOneLineWithNothingWritten) {
  const fs::path dir = fresh_dir("export_bad");
  export_trial(dir, "scenarios/drop_mass.toml", kShortDrop);
  const std::string readings = read_file(dir / "run/readings.csv");
  std::string gap = readings, text = readings, no_column = readings;
  gap.erase(line_start(gap, 3), line_start(gap, 4) - line_start(gap, 3));  // drop row 3
  text.replace(text.find('\n') + 1, 1, "x");
  no_column.replace(0, no_column.find(','), "t");
  const std::vector<std::pair<std::string, std::string>> logs = {
      {gap, "the control period is 0.01 s"},
      {text, "is not a number"},
      {no_column, "no column time_s"}};
  for (const auto& [log, says] : logs) {
    SCOPED_TRACE(says);
    write_text(dir / "bad.csv", log);
    const CliResult r =
        run_pamsim("controller replay " + (dir / "bad.csv").string() + " --export " +
                   (dir / "export").string() + " --out " + (dir / "out").string());
    EXPECT_EQ(r.exit_code, 2) << r.err;
    EXPECT_NE(r.err.find(says), std::string::npos) << r.err;
    EXPECT_EQ(line_count(r.err), 1) << r.err;
    EXPECT_FALSE(fs::exists(dir / "out"));
  }
  // an export whose configuration a hand edited out of range
  std::string json = read_file(dir / "export/pamctl_config.json");
  json.insert(json.find("\"v_thr_m_s\": ") + 13, "-");
  write_text(dir / "export/pamctl_config.json", json);
  const CliResult r =
      run_pamsim("controller replay " + (dir / "run/readings.csv").string() + " --export " +
                 (dir / "export").string() + " --out " + (dir / "out").string());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("reflex.ia.v_thr_m_s must be finite and > 0"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir / "out"));
  // a scenario the export cannot read
  const CliResult bad = run_pamsim(
      "controller export scenarios/drop_mass.toml --set "
      "reflex.v_thr_mm_s=-1 -o " +
      (dir / "bad_export").string());
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_EQ(line_count(bad.err), 1) << bad.err;
  EXPECT_FALSE(fs::exists(dir / "bad_export"));
}

}  // namespace
