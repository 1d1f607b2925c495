// cli_experiment_test.cc: the pulley and reaching scenarios as a user runs them (`run`,
// `render`, `sweep` + `export`), and the new keys' bad input: an unknown schedule kind, a
// schedule CSV whose time does not increase, an event naming a body the model lacks, a pair
// naming an unknown muscle, a muscle the model lacks, a PAM actuator without a muscle: one
// line each on stderr, a non-zero exit, and nothing written.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "sim/cli_util.h"
#include "sim/three_pam_model.h"
#include "sim/video_decode.h"
#include "sim/test_paths.h"

namespace {

namespace fs = std::filesystem;
using pamsim_test::CliResult;
using pamsim_test::fresh_dir;
using pamsim_test::line_count;
using pamsim_test::read_file;
using pamsim_test::run_pamsim;
using pamsim_test::write_text;

using pamsim_test::kSource;

// A shipped scenario's text with its ../models/ paths made absolute, to be written elsewhere.
std::string movable(const std::string& scenario) {
  std::string text = read_file(kSource + "/scenarios/" + scenario);
  const std::string from = "\"../models/", to = "\"" + kSource + "/models/";
  for (auto at = text.find(from); at != std::string::npos; at = text.find(from, at + to.size())) {
    text.replace(at, from.size(), to);
  }
  return text;
}

std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const auto at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  if (at != std::string::npos) text.replace(at, from.size(), to);
  return text;
}

nlohmann::json read_json(const fs::path& path) {
  std::ifstream in(path);
  return nlohmann::json::parse(in);
}

TEST(CliExperimentTest, PulleyRunWritesTrajectorySummaryAndPlot) {
  const fs::path out = fresh_dir("run_pulley");
  const CliResult r =
      run_pamsim("run scenarios/pulley_sine_5kg.toml --set sim.duration_s=5 --out " + out.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  for (const char* f : {"trajectory.csv", "summary.json", "position.png"}) {
    EXPECT_TRUE(fs::exists(out / f)) << f;
  }
  const std::string csv = read_file(out / "trajectory.csv");
  const std::string header = csv.substr(0, csv.find('\n'));
  for (const char* col : {"time_s", "position_mm", "velocity_mm_s", "p_cmd_pam_MPa", "p_pam_MPa",
                          "force_pam_N", "length_pam_mm", "length_est_pam_mm"}) {
    EXPECT_NE(header.find(col), std::string::npos) << col << " in " << header;
  }
  EXPECT_EQ(header.find("angle_deg"), std::string::npos) << "a slide logs millimetres";
  EXPECT_EQ(header.find("reflex_"), std::string::npos) << "no reflex columns without one";
  const nlohmann::json s = read_json(out / "summary.json");
  EXPECT_EQ(s["status"], "ok");
  EXPECT_EQ(s["steps"], 5000);
  EXPECT_EQ(s["scenario"]["controller"], "none");
  for (const char* key :
       {"pressure_rmse_pam_MPa", "length_est_rmse_pam_pct", "length_est_max_error_pam_pct",
        "position_min_mm", "position_max_mm", "length_est_rmse_mm"}) {
    EXPECT_TRUE(s.contains(key)) << key;
  }
  EXPECT_FALSE(s.contains("peak_drop_deg")) << "the pulley lists no drop metrics";
  EXPECT_GT(s["position_max_mm"].get<double>() - s["position_min_mm"].get<double>(), 10.0);
}

TEST(CliExperimentTest, CompareDrawsTheJointTheRunsLogAndRefusesToMixJoints) {
  const fs::path dir = fresh_dir("compare_joints");
  const std::string pulley = "run scenarios/pulley_sine_5kg.toml --set sim.duration_s=1 --no-plot";
  ASSERT_EQ(run_pamsim(pulley + " --out " + (dir / "a").string()).exit_code, 0);
  ASSERT_EQ(
      run_pamsim(pulley + " --set sensors.noise_scale=2 --out " + (dir / "b").string()).exit_code,
      0);
  const CliResult ok = run_pamsim("compare " + (dir / "a").string() + " " + (dir / "b").string() +
                                  " -o " + (dir / "ab.png").string());
  ASSERT_EQ(ok.exit_code, 0) << ok.err;
  EXPECT_TRUE(fs::is_regular_file(dir / "ab.png"));
  // a slide's runs against a hinge's: one line naming both, nothing written
  ASSERT_EQ(run_pamsim("run scenarios/drop_mass.toml --set sim.duration_s=1.2 --no-plot --out " +
                       (dir / "arm").string())
                .exit_code,
            0);
  const CliResult mixed = run_pamsim("compare " + (dir / "a").string() + " " +
                                     (dir / "arm").string() + " -o " + (dir / "mix.png").string());
  EXPECT_EQ(mixed.exit_code, 2);
  EXPECT_NE(mixed.err.find("compare runs of one kind of joint"), std::string::npos) << mixed.err;
  EXPECT_FALSE(fs::exists(dir / "mix.png"));
}

TEST(CliExperimentTest, ReachingRunWritesItsAnglePlot) {
  const fs::path out = fresh_dir("run_reaching");
  const CliResult r = run_pamsim("run scenarios/reaching.toml --out " + out.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  for (const char* f : {"trajectory.csv", "summary.json", "angle.png"}) {
    EXPECT_TRUE(fs::exists(out / f)) << f;
  }
  const nlohmann::json s = read_json(out / "summary.json");
  EXPECT_EQ(s["status"], "ok");
  EXPECT_EQ(s["steps"], 16000);
  EXPECT_GT(s["angle_final_deg"].get<double>(), s["angle_start_deg"].get<double>() + 20.0);
  EXPECT_TRUE(s.contains("length_est_rmse_ago_pct"));
  EXPECT_TRUE(s.contains("length_est_rmse_anta_pct"));
}

TEST(CliExperimentTest, RenderAcceptsTheReachingAndPulleyScenarios) {
  ::unsetenv("DISPLAY");
  ::unsetenv("PAMSIM_GL_BACKEND");
  const fs::path dir = fresh_dir("render_experiments");
  for (const char* scenario : {"reaching", "pulley_sine_5kg"}) {
    const std::string mp4 = (dir / (std::string(scenario) + ".mp4")).string();
    const CliResult r = run_pamsim(std::string("render scenarios/") + scenario +
                                   ".toml --set sim.duration_s=0.5 --fps 10 --width 320 "
                                   "--height 240 -o " +
                                   mp4);
    ASSERT_EQ(r.exit_code, 0) << scenario << ": " << r.err;
    const auto video = pamsim_test::decode_video(mp4);
    ASSERT_TRUE(video.opened) << mp4;
    EXPECT_EQ(video.width, 320);
    EXPECT_EQ(video.height, 240);
    EXPECT_EQ(video.frames, 5) << scenario << ": 0.5 s x 10 fps";
  }
}

TEST(CliExperimentTest, SweepOverThePulleysAmplitudeExportsItsTrackingMetrics) {
  const fs::path dir = fresh_dir("sweep_pulley");
  const fs::path sweep = dir / "amplitude.toml";
  write_text(sweep, "base = \"" + kSource +
                        "/scenarios/pulley_sine_5kg.toml\"\n"
                        "[fixed.sim]\nduration_s = 2.0\n"
                        "[[axis]]\nkey = \"muscles.pam.command.amplitude_MPa\"\n"
                        "values = [0.05, 0.2]\n");
  const std::string db = (dir / "a.db").string();
  const CliResult r = run_pamsim("sweep " + sweep.string() + " --threads 2 --db " + db);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const CliResult e = run_pamsim("export " + db + " --csv " + db + ".csv");
  ASSERT_EQ(e.exit_code, 0) << e.err;
  std::stringstream csv(read_file(db + ".csv"));
  std::vector<std::string> lines;
  for (std::string line; std::getline(csv, line);) lines.push_back(line);
  ASSERT_EQ(lines.size(), 3u);
  EXPECT_NE(lines[0].find("muscles.pam.command.amplitude_MPa"), std::string::npos) << lines[0];
  EXPECT_NE(lines[0].find("pressure_rmse_pam_MPa"), std::string::npos) << lines[0];
  EXPECT_EQ(lines[0].find("peak_drop_deg"), std::string::npos) << lines[0];
  EXPECT_NE(lines[1].find(",ok,"), std::string::npos) << lines[1];
  EXPECT_NE(lines[2].find(",ok,"), std::string::npos) << lines[2];
  EXPECT_NE(lines[1], lines[2]) << "the amplitude changes the trial";
}

struct BadCase {
  std::string what;
  std::string args;      // after `run`
  std::string expected;  // in the one-line message
};

TEST(CliExperimentTest, BadExperimentInputIsOneLineNonZeroAndWritesNothing) {
  const fs::path dir = fresh_dir("experiment_bad");
  const fs::path out = dir / "out";
  const std::string pulley = movable("pulley_sine_5kg.toml");
  const std::string sine_command =
      "command = { kind = \"sine\", offset_MPa = 0.6, amplitude_MPa = 0.2, period_s = 5.0 }";

  write_text(dir / "back_in_time.csv", "time_s,MPa\n0,0.5\n2,0.6\n1.5,0.7\n");
  write_text(dir / "table.toml",
             replaced(pulley, sine_command,
                      "command = { kind = \"table\", file = \"back_in_time.csv\" }"));
  write_text(dir / "square.toml", replaced(pulley, "kind = \"sine\"", "kind = \"square\""));
  write_text(dir / "ghost_body.toml",
             pulley +
                 "\n[events.lift]\naction = \"add_mass\"\nbody = \"ghost\"\nmass_kg = 1.0\n"
                 "when.at_s = 1.0\n");
  write_text(dir / "ghost_muscle.toml", pulley + "\n[muscles.biceps]\nparams = \"" + kSource +
                                            "/models/pams/table4_agonist.toml\"\nline_mm = 300\n"
                                            "command = { kind = \"constant\", MPa = 0.4 }\n");
  write_text(dir / "arm_3pam.xml", pamsim_test::three_pam_model());
  write_text(dir / "unbound_pam.toml",
             replaced(movable("reaching.toml"), "\"" + kSource + "/models/arm_2pam.xml\"",
                      "\"arm_3pam.xml\""));

  const std::vector<BadCase> cases = {
      {"an unknown schedule kind", (dir / "square.toml").string(),
       "muscles.pam.command.kind is \"square\", allowed"},
      {"a CSV with non-increasing time", (dir / "table.toml").string(),
       "muscles.pam.command.file: " + (dir / "back_in_time.csv").string() +
           ": line 4: time must increase strictly, got 1.5 s after 2 s"},
      {"an event naming a missing body", (dir / "ghost_body.toml").string(), "ghost"},
      {"a pair naming an unknown muscle",
       "scenarios/drop_mass.toml --set 'reflex.pairs=[[\"agonist\", \"biceps\"]]'", "biceps"},
      {"a muscle the model lacks", (dir / "ghost_muscle.toml").string(), "biceps"},
      {"a PAM actuator without a muscle", (dir / "unbound_pam.toml").string(), "agonist2"},
      {"a negative ramp duration",
       "scenarios/reaching.toml --set muscles.agonist.command.duration_s=-1",
       "muscles.agonist.command.duration_s"},
      {"a sine above the supply",
       "scenarios/pulley_sine_5kg.toml --set muscles.pam.command.amplitude_MPa=0.5",
       "muscles.pam.command"},
  };
  for (const BadCase& c : cases) {
    const CliResult r = run_pamsim("run " + c.args + " --out " + out.string());
    EXPECT_NE(r.exit_code, 0) << c.what;
    EXPECT_EQ(line_count(r.err), 1) << c.what << ": " << r.err;
    EXPECT_EQ(r.err.rfind("pamsim: ", 0), 0u) << c.what << ": " << r.err;
    EXPECT_NE(r.err.find(c.expected), std::string::npos) << c.what << ": " << r.err;
    EXPECT_FALSE(fs::exists(out)) << c.what;
  }
}

}  // namespace
