// sweep_cases_test.cc: a sweep's case axes (named bundles of scenario keys): the points they
// cross, the overrides each point gets, a case's trials equal to the same keys swept as an
// axis (the independent truth: a case is only a name for its keys), the report's table and
// best setting, and a bad case axis refused in one line with no database.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "sim/cli_util.h"
#include "sim/scenario/scenario_file.h"
#include "sim/sweep/sweep.h"
#include "sim/test_paths.h"
#include "sim/sweep_process.h"

namespace {

namespace fs = std::filesystem;
using pamsim_test::fresh_dir;
using pamsim_test::line_count;
using pamsim_test::lines_of;
using pamsim_test::read_file;
using pamsim_test::run_pamsim;
using pamsim_test::short_sweep;
using pamsim_test::write_text;

const std::string kGainCases =
    "[[axis]]\nname = \"gain\"\n"
    "[[axis.case]]\nname = \"Table II\"\n"
    "[[axis.case]]\nname = \"high, slow\"\n"
    "set = { \"reflex.k_MPa_s_per_mm\" = 0.004, reflex.v_thr_mm_s = 90.0 }\n";

pamsim::SweepDefinition cases_sweep(const fs::path& dir, const std::string& body) {
  const fs::path file = dir / "cases.toml";
  write_text(file, short_sweep(body));
  return pamsim::load_sweep(file.string());
}

TEST(SweepCasesTest, CasesCrossTheOtherAxesAndSetTheirKeys) {
  const fs::path dir = fresh_dir("sweep_cases_unit");
  const pamsim::SweepDefinition s = cases_sweep(
      dir, "seeds = 2\n" + kGainCases + "[[axis]]\nkey = \"drop.mass_kg\"\nvalues = [0.1, 0.2]\n");
  ASSERT_EQ(s.points(), 4);
  EXPECT_EQ(s.value(0, 0).text, "Table II");
  EXPECT_EQ(s.value(3, 0).text, "high, slow");
  // the base's case sets nothing: the fixed keys, then the mass
  const std::vector<std::string> base = s.overrides(1);
  EXPECT_EQ(base.back(), "drop.mass_kg=0.2");
  EXPECT_EQ(base.size(), s.fixed.size() + 1);
  // the other case's keys, in key order (a quoted dotted key reads as a nested one)
  const std::vector<std::string> high = s.overrides(2);
  ASSERT_EQ(high.size(), s.fixed.size() + 3);
  EXPECT_EQ(high[s.fixed.size()], "reflex.v_thr_mm_s=90.0");
  EXPECT_EQ(high[s.fixed.size() + 1], "reflex.k_MPa_s_per_mm=0.004");
  EXPECT_EQ(high.back(), "drop.mass_kg=0.1");
  EXPECT_NE(s.canonical_json().find("\"cases\""), std::string::npos);
  // a sweep with no case axis keeps the definition it had before cases existed
  const pamsim::SweepDefinition plain =
      cases_sweep(dir, "[[axis]]\nkey = \"drop.mass_kg\"\nvalues = [0.1]\n");
  EXPECT_EQ(plain.canonical_json().find("cases"), std::string::npos);
}

// A case may take its keys from a table of another file (the regulator bracket's end, kept
// with its sources), then its own set.
TEST(SweepCasesTest, ACaseTakesItsKeysFromAnotherFilesTable) {
  const fs::path dir = fresh_dir("sweep_cases_from");
  write_text(dir / "bracket.toml",
             "[fast]\n\"valve.dead_time_ms\" = 2.0\n"
             "valve.proportional_band_kPa = 250.0\n"
             "\"sensors.fiber.creep_times_s\" = [10.0, 100.0]\n"
             "\"sensors.fiber.creep_weights\" = [0.05, 0.01]\n");
  const pamsim::SweepDefinition s =
      cases_sweep(dir,
                  "[[axis]]\nname = \"regulator\"\n[[axis.case]]\nname = \"fast\"\n"
                  "from = { file = \"bracket.toml\", table = \"fast\" }\n"
                  "set = { reflex.v_thr_mm_s = 60.0 }\n");
  const std::vector<std::string> o = s.overrides(0);
  ASSERT_EQ(o.size(), s.fixed.size() + 5);
  const std::size_t f = s.fixed.size();  // in key order; a list as one value
  EXPECT_EQ(o[f], "sensors.fiber.creep_times_s=[10.0, 100.0]");
  EXPECT_EQ(o[f + 1], "sensors.fiber.creep_weights=[0.05, 0.01]");
  EXPECT_EQ(o[f + 2], "valve.proportional_band_kPa=250.0");
  EXPECT_EQ(o[f + 3], "valve.dead_time_ms=2.0");
  EXPECT_EQ(o.back(), "reflex.v_thr_mm_s=60.0");
}

// A case is a name for its keys: its trials are those of the same keys swept as an axis.
TEST(SweepCasesTest, ACasesTrialsAreThoseOfItsKeysAsAnAxis) {
  const fs::path dir = fresh_dir("sweep_cases_truth");
  write_text(dir / "cases.toml",
             short_sweep("seeds = 2\n[[axis]]\nname = \"threshold\"\n"
                         "[[axis.case]]\nname = \"low\"\nset = { reflex.v_thr_mm_s = 40.0 }\n"
                         "[[axis.case]]\nname = \"high\"\nset = { reflex.v_thr_mm_s = 100.0 }\n"));
  write_text(dir / "axis.toml", short_sweep("seeds = 2\n[[axis]]\nkey = \"reflex.v_thr_mm_s\"\n"
                                            "values = [40.0, 100.0]\n"));
  for (const char* name : {"cases", "axis"}) {
    const std::string db = (dir / (std::string(name) + ".db")).string();
    const auto r =
        run_pamsim("sweep " + (dir / (std::string(name) + ".toml")).string() + " --db " + db);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    ASSERT_EQ(run_pamsim("export " + db + " -o " + (dir / name).string() + ".csv").exit_code, 0);
  }
  const auto cases = lines_of(read_file(dir / "cases.csv"));
  const auto axis = lines_of(read_file(dir / "axis.csv"));
  ASSERT_EQ(cases.size(), 5u);
  ASSERT_EQ(axis.size(), cases.size());
  // trial,point,seed_index,seed,<the axis's column>,status,...: equal but for that column
  const auto without_axis = [](const std::string& line) {
    std::size_t at = 0;
    for (int comma = 0; comma < 4; ++comma) at = line.find(',', at) + 1;
    return line.substr(0, at) + line.substr(line.find(',', at));
  };
  for (std::size_t i = 1; i < cases.size(); ++i)
    EXPECT_EQ(without_axis(cases[i]), without_axis(axis[i])) << i;
  EXPECT_NE(cases[1].find("low"), std::string::npos) << cases[1];
}

TEST(SweepCasesTest, TheReportTablesTheCasesAndItsBestSettingCarriesTheirKeys) {
  const fs::path dir = fresh_dir("sweep_cases_report");
  write_text(dir / "s.toml", short_sweep("[[axis]]\nname = \"load\"\n[[axis.case]]\n"
                                         "name = \"Table II\"\n[[axis.case]]\n"
                                         "name = \"light, high gain\"\n[axis.case.set]\n"
                                         "drop.mass_kg = 0.02\nreflex.k_MPa_s_per_mm = 0.004\n"));
  const std::string db = (dir / "s.db").string();
  ASSERT_EQ(run_pamsim("sweep " + (dir / "s.toml").string() + " --db " + db).exit_code, 0);
  const fs::path out = dir / "report";
  const auto r = run_pamsim("report " + db + " --out " + out.string() +
                            " --table peak_drop_deg,mass_retained");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto table = lines_of(read_file(out / "table.md"));
  ASSERT_EQ(table.size(), 4u);
  EXPECT_EQ(table[0], "| load | ok / trials | peak drop [deg] | mass retained |");
  EXPECT_EQ(table[3].rfind("| light, high gain | 1 / 1 | ", 0), 0u) << table[3];
  // a tenth of the mass drops the arm less: the best point, whose scenario has the case's keys
  const std::string best = read_file(out / "best.toml");
  EXPECT_NE(best.find("load = 'light, high gain'"), std::string::npos) << best;
  EXPECT_NE(best.find("mass_kg = 0.02"), std::string::npos) << best;
  EXPECT_NE(best.find("k_MPa_s_per_mm = 0.004"), std::string::npos) << best;
  const auto bad = run_pamsim("report " + db + " --table nope --out " + (dir / "bad").string());
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_NE(bad.err.find("--table nope: not a sweep metric"), std::string::npos) << bad.err;
  EXPECT_FALSE(fs::exists(dir / "bad"));
}

// The findings' sweep files name the fiber reflex by its keys: with them, drop_mass.toml is
// drop_mass_fiber.toml (one scenario, not two copies that could drift). Loading each file
// also binds every one of its points (load_sweep checks them all).
TEST(SweepCasesTest, TheFindingsFiberCaseIsTheFiberScenario) {
  const std::string fiber = pamsim_test::kScenarios + "drop_mass_fiber.toml";
  const std::string dir = fresh_dir("sweep_cases_fiber").string();
  const std::string want =
      pamsim::resolved_scenario_toml(pamsim_test::read_file(fiber), fiber, {}, dir, "");
  // (the shipped regulator and hardware, every gate on, the fiber reflex)
  for (const auto& [file, point] : {std::pair<const char*, int>{"sweep_findings_regulator", 9},
                                    std::pair<const char*, int>{"sweep_findings_gates", 1},
                                    std::pair<const char*, int>{"sweep_hardware_losses", 1}}) {
    const pamsim::SweepDefinition s = pamsim::load_sweep(pamsim_test::kScenarios + file + ".toml");
    ASSERT_EQ(s.value(point, s.axes.size() - 1).text, "fiber (1/300)") << file;
    EXPECT_EQ(pamsim::resolved_scenario_toml(s.base_text, s.base_path, s.overrides(point), dir, ""),
              want)
        << file;
  }
}

// The landing and tension-reflex sweeps run one reflex scenario with a gain (or the reflex)
// off in place of a scenario file without it: the trial is that file's, metric for metric.
TEST(SweepCasesTest, AReflexSwitchedOffByItsKeysIsTheScenarioWithoutIt) {
  const fs::path dir = fresh_dir("sweep_cases_off");
  struct Pair {
    const char* without;  // the scenario file without the reflex
    const char* with;     // the one the sweep runs, and the keys that switch it off
    const char* off;
    std::vector<const char*> metrics;
  };
  const std::vector<Pair> pairs = {
      {"landing.toml",
       "landing_reflex.toml",
       "reflex.enabled=false",
       {"knee_angle_max_deg", "grf_max_N", "peak_tension_VAS_N", "trunk_z_min_mm"}},
      {"drop_mass_heavy.toml",
       "drop_mass_heavy_ia_ib.toml",
       "reflex.ib.k_MPa_per_N=0",
       {"peak_drop_deg", "peak_tension_ago_N", "reflex_triggers_ago", "recovery_time_s"}}};
  for (const Pair& p : pairs) {
    const auto summary = [&](const std::string& args, const std::string& name) {
      const fs::path out = dir / name;
      const auto r = run_pamsim("run " + pamsim_test::kScenarios + args + " --out " + out.string());
      EXPECT_EQ(r.exit_code, 0) << r.err;
      return nlohmann::json::parse(read_file(out / "summary.json"));
    };
    const auto a = summary(p.without, std::string(p.without) + "_a");
    const auto b = summary(std::string(p.with) + " --set " + p.off, std::string(p.with) + "_b");
    for (const char* m : p.metrics) {
      ASSERT_TRUE(a.contains(m)) << p.without << " " << m;
      EXPECT_EQ(a[m].dump(), b[m].dump()) << p.without << ": " << m;
    }
  }
}

// clang-format off
TEST(SweepCasesTest, BadCaseAxesFailWithOneLineAndNoDatabase) {
  const std::string one = "[[axis.case]]\nname = \"a\"\n";
  struct Bad {
    const char* name;
    std::string body;
    const char* message;
  };
  const std::vector<Bad> bad = {
      {"no_cases", "[[axis]]\nname = \"c\"\n", "axis[0].case must be one or more"},
      {"no_name", "[[axis]]\n" + one, "axis[0].name is required"},
      {"odd_name", "[[axis]]\nname = \"a b\"\n" + one, "must be letters, digits and _"},
      {"reserved_name", "[[axis]]\nname = \"status\"\n" + one, "a column pamsim keeps"},
      {"metric_name", "[[axis]]\nname = \"peak_drop_deg\"\n" + one, "is a metric's column"},
      {"with_values", "[[axis]]\nname = \"c\"\nvalues = [1.0]\n" + one, "axis[0].values does not go"},
      {"random", "design = \"random\"\nsamples = 2\n[[axis]]\nname = \"c\"\n" + one,
       "is for grid designs"},
      {"case_without_name", "[[axis]]\nname = \"c\"\n[[axis.case]]\nset = {}\n",
       "case[0].name is required"},
      {"same_name", "[[axis]]\nname = \"c\"\n" + one + one, "names another case"},
      {"set_not_table", "[[axis]]\nname = \"c\"\n[[axis.case]]\nname = \"a\"\nset = 3\n",
       "case[0].set must be a table"},
      {"unknown_case_key", "[[axis]]\nname = \"c\"\n[[axis.case]]\nname = \"a\"\nsett = {}\n",
       "case[0].sett is not a case key"},
      {"bad_value", "[[axis]]\nname = \"c\"\n[[axis.case]]\nname = \"a\"\n"
                    "set = { reflex.v_thr_mm_s = nan }\n", "must be finite"},
      {"two_axes_one_key", "[[axis]]\nname = \"c\"\n[[axis.case]]\nname = \"a\"\n"
                           "set = { reflex.v_thr_mm_s = 50.0 }\n"
                           "[[axis]]\nkey = \"reflex.v_thr_mm_s\"\nvalues = [60.0]\n",
       "axis[1] sets reflex.v_thr_mm_s, which axis[0] sets too"},
      {"case_and_fixed", "[[axis]]\nname = \"c\"\n[[axis.case]]\nname = \"a\"\n"
                         "set = { sim.duration_s = 0.9 }\n",   // short_sweep's [fixed] sets it
       "axis[0] sets sim.duration_s, which [fixed] sets too"},
      {"from_missing_file", "[[axis]]\nname = \"c\"\n[[axis.case]]\nname = \"a\"\n"
                            "from = { file = \"nowhere.toml\", table = \"fast\" }\n",
       "case[0].from " },
      {"from_missing_table", "[[axis]]\nname = \"c\"\n[[axis.case]]\nname = \"a\"\n"
                             "from = { file = \"" + pamsim_test::kSource +
                             "/models/pams/regulator_bracket.toml\", table = \"medium\" }\n",
       "has no table [medium]"},
      {"from_not_table", "[[axis]]\nname = \"c\"\n[[axis.case]]\nname = \"a\"\nfrom = 1\n",
       "case[0].from must be { file"},
      {"unknown_scenario_key", "[[axis]]\nname = \"c\"\n[[axis.case]]\nname = \"a\"\n"
                               "set = { reflex.v_thr = 50.0 }\n", "point 0"},
  };
  const fs::path dir = fresh_dir("sweep_cases_bad");
  for (const Bad& c : bad) {
    const fs::path file = dir / (std::string(c.name) + ".toml");
    write_text(file, short_sweep(c.body));
    const fs::path out = dir / (std::string(c.name) + "_out");
    const auto r = run_pamsim("sweep " + file.string() + " --out " + out.string());
    EXPECT_EQ(r.exit_code, 2) << c.name << ": " << r.err;
    EXPECT_EQ(line_count(r.err), 1) << c.name << ": " << r.err;
    EXPECT_NE(r.err.find(c.message), std::string::npos) << c.name << ": " << r.err;
    EXPECT_FALSE(fs::exists(out / "sweep.db")) << c.name;
  }
}
// clang-format on

}  // namespace
