// live_session_test.cc: a live session's record, without a window: the scenario.toml it
// writes runs the trial that was shown, bit for bit (a drop, the reflex switched, a setting,
// a restart with another seed, a window closed early); a drop no scenario can hold is marked,
// and `run --from` names it; a script's lines are checked before anything runs.
#include "sim/view/live_session.h"

#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "base/input_error.h"
#include "sim/io/outputs.h"
#include "sim/scenario/scenario_file.h"
#include "sim/view/view_script.h"

namespace pamsim {
namespace {

namespace fs = std::filesystem;

const std::string kDropMass = std::string(PAMSIM_SOURCE_DIR) + "/scenarios/drop_mass.toml";
const std::string kReaching = std::string(PAMSIM_SOURCE_DIR) + "/scenarios/reaching.toml";

std::string temp_dir(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("pamsim_live_" + name);
  fs::remove_all(dir);
  return dir.string();
}

std::string file_text(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

// The record's scenario run again, its trajectory.csv beside the record's
void expect_rerun_is_the_record(const std::string& record) {
  const Scenario sc = load_scenario(record + "/scenario.toml");
  const TrialResult again = run_trial(load_trial_model(sc), sc, sc.seed);
  EXPECT_EQ(trajectory_to_csv(again.trajectory), file_text(record + "/trajectory.csv"));
}

void step_to(LiveSession& s, double t) {
  while (s.time_s() < t - 1e-9 && s.step()) {
  }
}

TEST(LiveSessionTest, TheRecordRunsTheTrialThatWasShown) {
  LiveSession s(kDropMass, {"sim.duration_s=1.5", "drop.enabled=false"});
  step_to(s, 0.2);
  s.set_setting("reflex.v_thr_mm_s", 45, "test");
  step_to(s, 0.3);
  s.restart(4);  // the setting is kept, from t = 0
  step_to(s, 0.35);
  EXPECT_TRUE(s.drop_now());
  EXPECT_FALSE(s.drop_now());  // it has fallen
  step_to(s, 0.6);
  s.set_reflex(false);
  step_to(s, 0.8);
  s.set_reflex(true);
  step_to(s, 1.2);  // closed before the end
  ASSERT_EQ(s.changes().size(), 4u);
  EXPECT_EQ(s.changes()[0].tick, 0);  // the kept setting
  EXPECT_EQ(s.changes()[1].what, "drop");
  EXPECT_EQ(s.changes()[1].tick, 35);
  const std::string record = temp_dir("shown");
  s.write_record(record);
  expect_rerun_is_the_record(record);
  EXPECT_TRUE(unreproduced_live_changes(record).empty());
  EXPECT_EQ(load_scenario(record + "/scenario.toml").seed, 4u);
}

TEST(LiveSessionTest, ADropOnAConditionIsMarkedAndNamed) {
  LiveSession s(kReaching, {"events.let_go.action=release", "events.let_go.body=ball",
                            "events.let_go.when.joint=shoulder",
                            "events.let_go.when.below_deg=-170", "sim.duration_s=1"});
  EXPECT_TRUE(s.has_mass_to_drop());
  EXPECT_FALSE(LiveSession(kReaching, {}).has_mass_to_drop());  // its ball is held, never let go
  step_to(s, 0.25);
  ASSERT_TRUE(s.drop_now());
  const std::string record = temp_dir("condition");
  s.write_record(record);
  const std::vector<std::string> lines = unreproduced_live_changes(record);
  ASSERT_EQ(lines.size(), 1u);
  EXPECT_NE(lines[0].find("t = 0.25 s (drop) is not reproduced: events.let_go fires on a "
                          "condition"),
            std::string::npos)
      << lines[0];
}

TEST(LiveSessionTest, AScriptsBadLinesAreRefusedNamingTheLine) {
  LiveSession s(kDropMass, {"sim.duration_s=1.5"});
  const std::string dir = temp_dir("script");
  fs::create_directories(dir);
  const auto refusal = [&](const std::string& text) {
    std::ofstream(dir + "/s.txt") << text;
    try {
      read_view_script(dir + "/s.txt", s);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  EXPECT_EQ(refusal("# fine\n0 pause\n0.5 step 3\n1 slow 4\n1 set reflex.v_thr_mm_s 50\n"
                    "1.2 restart 7\n0.1 drop\n0.2 reflex off\n0.3 screenshot " +
                    dir + "/a.png\n0.3 wait 1\n0.4 close\n"),
            "accepted");
  const std::string where = dir + "/s.txt:2: ";
  EXPECT_EQ(refusal("0 pause\n0.5 jump\n").rfind(where + "unknown command 'jump'", 0), 0u);
  EXPECT_EQ(refusal("0 pause\nsoon play\n").rfind(where + "the time must be", 0), 0u);
  EXPECT_EQ(refusal("1 pause\n0.5 play\n").rfind(where + "the time 0.5 is before", 0), 0u);
  EXPECT_EQ(refusal("0 pause\n1 slow 3\n").rfind(where + "slow takes 1, 2, 4, 8 or 16", 0), 0u);
  EXPECT_EQ(refusal("0 pause\n1 step 0\n").rfind(where + "N must be a whole number", 0), 0u);
  EXPECT_EQ(refusal("0 pause\n1 reflex maybe\n").rfind(where + "reflex takes on or off", 0), 0u);
  EXPECT_EQ(refusal("0 pause\n1 wait 100\n").rfind(where + "wait takes (0, 60]", 0), 0u);
  EXPECT_EQ(refusal("0 pause\n1 screenshot a.jpg\n").rfind(where + "a screenshot is a .png", 0),
            0u);
  EXPECT_EQ(refusal("0 pause\n1 screenshot /no/such/a.png\n").rfind(where + "no folder", 0), 0u);
  EXPECT_NE(refusal("0 pause\n1 set reflex.v_thr_mm_s -4\n").find("s.txt:2"), std::string::npos);
  EXPECT_NE(refusal("0 pause\n1 set reflex.duration_s 0.3\n").find("cannot change during a trial"),
            std::string::npos);
  EXPECT_EQ(refusal("0 pause\n1 pause now\n").rfind(where + "expected no argument", 0), 0u);
}

}  // namespace
}  // namespace pamsim
