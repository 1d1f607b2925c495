// identify_log_test.cc: a lab's log held against the model (`pamsim identify` with no
// [[parameter]], a recording of commands = "log"). The log's own valve commands, held from
// tick to tick, drive the model with its controller off: a log pamsim made under a stretch
// reflex is reproduced to its printed digits and every channel is explained; a log of an arm
// whose regulator acts 60 ms later than the model's is not.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include "sim/cli_util.h"
#include "sim/identify_test_arm.h"
#include "sim/optimize/identify.h"
#include "sim/optimize/identify_outputs.h"

namespace pamsim {
namespace {

namespace fs = std::filesystem;

// the reflex drop: the ball released at 1 s onto the arm under the stretch reflex
const std::vector<std::string> kReflexDrop = {
    "events.fall.action=\"release\"", "events.fall.body=\"ball\"", "events.fall.when.at_s=1.0",
    "controller.kind=\"stretch_reflex\""};
const std::vector<std::string> kLogged = {"angle_deg", "p_meas_ago_MPa", "p_meas_anta_MPa",
                                          "p_cmd_ago_MPa", "p_cmd_anta_MPa"};

// The true arm's log of the reflex drop (every control tick, full precision) with `lab`'s
// changes, and the trial that made it.
TrialResult log_reflex_drop(const fs::path& file, std::vector<std::string> lab) {
  lab.insert(lab.end(), {"sim.duration_s=2.5", "seed=7"});
  lab.insert(lab.end(), kReflexDrop.begin(), kReflexDrop.end());
  const Scenario sc = load_scenario(kArm, lab);
  TrialResult t = run_trial(load_trial_model(sc), sc, sc.seed, true);
  std::string csv = "time_s";
  for (const std::string& c : kLogged) csv += "," + c;
  csv += "\n";
  for (std::size_t row = 0; row < t.trajectory.rows(); ++row) {
    csv += format_shortest(t.trajectory.at(row, 0));
    for (const std::string& c : kLogged)
      csv += "," + format_shortest(t.trajectory.at(row, t.trajectory.column(c)));
    csv += "\n";
  }
  pamsim_test::write_text(file, csv);
  return t;
}

// the check file: no parameter, the log driving the model (noise-free sensors predict the
// expected reading)
IdentifyDefinition check_file(const fs::path& dir) {
  std::string set;
  for (const std::string& s : kReflexDrop) set += (set.empty() ? "'" : ", '") + s + "'";
  pamsim_test::write_text(dir / "check.toml",
                          "base = \"" + kArm +
                              "\"\noverrides = [\"sim.duration_s=2.5\", "
                              "\"sensors.noise_scale=0\"]\n[[recording]]\nfile = \"log.csv\"\n"
                              "commands = \"log\"\nset = [" +
                              set + "]\n");
  return load_identify_definition((dir / "check.toml").string());
}

IdentifyResult hold_against(const fs::path& dir, const IdentifyDefinition& def) {
  IdentifyDb db = IdentifyDb::create((dir / "check.db").string(), def);
  IdentifyRunOptions options;
  options.threads = 2;
  return run_identify(def, db, options);
}

TEST(IdentifyLogTest, ALogsHeldCommandsReproduceItsTrial) {
  const fs::path dir = pamsim_test::fresh_dir("identify_log_own");
  const TrialResult lab = log_reflex_drop(dir / "log.csv", {});
  const IdentifyDefinition def = check_file(dir);
  ASSERT_EQ(def.recordings.size(), 1u);
  const IdentifyRecording& r = def.recordings[0];
  ASSERT_EQ(r.channels.size(), 3u) << "the commands drive the trial, no channel to match";
  // the model's trial under the log's commands gives the lab's commands and angle back
  const Scenario sc = load_scenario_text(def.base_text, def.base_path, def.overrides_at(r, {}));
  const TrialResult model = run_trial(load_trial_model(sc), sc, sc.seed, true);
  ASSERT_EQ(model.trajectory.rows(), lab.trajectory.rows());
  double most_command = 0.0, most_angle = 0.0;
  for (std::size_t row = 0; row < lab.trajectory.rows(); ++row) {
    for (const char* c : {"p_cmd_ago_MPa", "p_cmd_anta_MPa"}) {
      const double d = model.trajectory.at(row, model.trajectory.column(c)) -
                       lab.trajectory.at(row, lab.trajectory.column(c));
      most_command = std::max(most_command, std::abs(d));
    }
    most_angle =
        std::max(most_angle, std::abs(model.trajectory.at(row, 1) - lab.trajectory.at(row, 1)));
  }
  EXPECT_LT(most_command, 1e-12) << "MPa: the reflex's commands, held at its ticks";
  EXPECT_LT(most_angle, 1e-6) << "deg";
  // so every channel is explained, and the report says no parameter was fitted
  const IdentifyResult result = hold_against(dir, def);
  ASSERT_EQ(result.fits.size(), 3u);
  for (const ChannelFit& f : result.fits) {
    EXPECT_TRUE(f.judged && f.explained)
        << f.channel << ": RMSE " << f.rmse_after << " noise " << f.noise_floor;
  }
  EXPECT_TRUE(result.parameters.empty());
  EXPECT_TRUE(identify_warnings(def, result).empty());
  EXPECT_NE(identify_markdown(def, result).find("No parameter is fitted"), std::string::npos);
}

TEST(IdentifyLogTest, ARegulator60MsSlowerThanTheModelsIsNotExplained) {
  const fs::path dir = pamsim_test::fresh_dir("identify_log_slow");
  // the model's regulator's dead time, and the lab's 60 ms more
  const Scenario model = load_scenario(kArm, {});
  const double dead_time_ms = 1e3 * model.pneumatics.regulator_dead_time_s;
  log_reflex_drop(dir / "log.csv", {"valve.dead_time_ms=" + format_shortest(dead_time_ms + 60.0)});
  const IdentifyDefinition def = check_file(dir);
  const IdentifyResult result = hold_against(dir, def);
  bool angle_judged = false;
  for (const ChannelFit& f : result.fits) {
    if (f.channel != "angle_deg") continue;
    angle_judged = true;
    EXPECT_TRUE(f.judged);
    EXPECT_FALSE(f.explained) << "RMSE " << f.rmse_after << " deg, noise " << f.noise_floor;
  }
  EXPECT_TRUE(angle_judged);
  const std::vector<std::string> warnings = identify_warnings(def, result);
  ASSERT_FALSE(warnings.empty());
  EXPECT_NE(warnings[0].find("the model does not explain recording log"), std::string::npos)
      << warnings[0];
}

// clang-format off
TEST(IdentifyLogTest, ALogThatCannotDriveTheModelIsOneLine) {
  const fs::path dir = pamsim_test::fresh_dir("identify_log_bad");
  log_reflex_drop(dir / "log.csv", {});
  pamsim_test::write_text(dir / "angle.csv", "time_s,angle_deg\n0,-36\n0.01,-36\n");
  const std::string good = "base = \"" + kArm + "\"\noverrides = [\"sim.duration_s=2.5\"]\n"
                           "[[recording]]\nfile = \"log.csv\"\ncommands = \"log\"\n";
  auto with = [&](const std::string& from, const std::string& to) {
    std::string t = good;
    t.replace(t.find(from), from.size(), to);
    return t;
  };
  for (const auto& [text, says] : std::vector<std::pair<std::string, std::string>>{
           {with("log.csv", "angle.csv"), "recording[0].commands is \"log\", but"},
           {with("commands = \"log\"", "commands = \"csv\""), "recording[0].commands"},
           {good + "channels = [\"angle_deg\", \"p_cmd_ago_MPa\"]\n",
            "names p_cmd_ago_MPa, a command that drives the trial"},
           {good + "set = ['events.log_commands.when.at_s=2']\n",
            "recording[0].set names an event \"log_commands\", the name commands = \"log\" uses"},
           {good + "set = ['events.on.action=\"controller_on\"', 'events.on.when.at_s=1']\n",
            "recording[0].set switches the controller on (events.on)"}}) {
    pamsim_test::expect_file_refused(dir, "identify", text, "", says);
  }
  pamsim_test::write_text(dir / "check.toml", good + "[[candidate]]\nname = \"c\"\nchannels = [\"angle_deg\"]\n");
  const pamsim_test::CliResult plan =
      pamsim_test::run_pamsim("identify " + (dir / "check.toml").string() + " --plan --out " + (dir / "out").string());
  EXPECT_EQ(plan.exit_code, 2);
  EXPECT_NE(plan.err.find("--plan ranks experiments by the parameters' uncertainty"), std::string::npos) << plan.err;
}
// clang-format on

}  // namespace
}  // namespace pamsim
