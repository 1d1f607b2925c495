// schedule_hold_test.cc: a table schedule held from row to row (a zero-order hold, as a
// regulator holds a logged command) against its closed form, read from a named column of a
// wider CSV such as a lab's log, and the one-line errors of a column that cannot be one.
#include <gtest/gtest.h>

#include <string>

#include "base/input_error.h"
#include "sim/cli_util.h"
#include "sim/core/schedule.h"
#include "sim/scenario/schedule_csv.h"

namespace pamsim {
namespace {

constexpr double kPaPerMPaHold = 1e6;

TEST(ScheduleHoldTest, EachRowHoldsUntilTheNextFromItsOwnTime) {
  PressureSchedule s = table_schedule(
      {0.5, 1.0, 2.0}, {0.2 * kPaPerMPaHold, 0.6 * kPaPerMPaHold, 0.3 * kPaPerMPaHold}, "");
  s.hold = true;
  EXPECT_EQ(s.at(0.0), 0.2 * kPaPerMPaHold) << "the first row before its time";
  EXPECT_EQ(s.at(0.5), 0.2 * kPaPerMPaHold);
  EXPECT_EQ(s.at(0.99), 0.2 * kPaPerMPaHold) << "held, not interpolated towards 0.6";
  EXPECT_EQ(s.at(1.0), 0.6 * kPaPerMPaHold);
  EXPECT_EQ(s.at(1.9), 0.6 * kPaPerMPaHold);
  EXPECT_EQ(s.at(7.0), 0.3 * kPaPerMPaHold) << "the last row after its time";
  // a tick a rounding below a row's printed time meets the row: 0.07 is not 7 x 0.01
  PressureSchedule tick =
      table_schedule({0.06, 0.07}, {0.1 * kPaPerMPaHold, 0.4 * kPaPerMPaHold}, "");
  tick.hold = true;
  EXPECT_EQ(tick.at(0.07 - 1e-12), 0.4 * kPaPerMPaHold);
  EXPECT_EQ(tick.at(0.07 - 1e-6), 0.1 * kPaPerMPaHold) << "a microsecond is not a rounding";
  // without hold the same rows are linear between
  s.hold = false;
  EXPECT_NEAR(s.at(0.75), 0.4 * kPaPerMPaHold, 1e-6);
}

class ScheduleColumnTest : public ::testing::Test {
 protected:
  std::string write(const std::string& text) {
    const auto path = dir_ / "log.csv";
    pamsim_test::write_text(path, text);
    return path.string();
  }
  std::string error_of(const std::string& text, const std::string& column) {
    try {
      read_schedule_column(write(text), column, true);
    } catch (const InputError& e) {
      return e.what();
    }
    return "";
  }
  std::filesystem::path dir_ = pamsim_test::fresh_dir("schedule_column");
};

TEST_F(ScheduleColumnTest, ALogsCommandColumnIsHeldAndItsGapsSkipped) {
  const std::string log =
      "time_s,angle_deg,p_cmd_ago_MPa,p_cmd_anta_MPa\n"
      "0.00,-30,0.30,0.40\n"
      "0.01,-29,,0.41\n"
      "0.02,-28,0.50,0.42\n";
  const PressureSchedule s = read_schedule_column(write(log), "p_cmd_ago_MPa", true);
  EXPECT_EQ(s.kind, ScheduleKind::kTable);
  EXPECT_TRUE(s.hold);
  EXPECT_EQ(s.column, "p_cmd_ago_MPa");
  ASSERT_EQ(s.times_s.size(), 2u) << "the empty cell is no row";
  EXPECT_EQ(s.at(0.015), 0.30 * kPaPerMPaHold);
  EXPECT_EQ(s.at(0.02), 0.50 * kPaPerMPaHold);
  const PressureSchedule anta = read_schedule_column(write(log), "p_cmd_anta_MPa", false);
  EXPECT_FALSE(anta.hold);
  EXPECT_NEAR(anta.at(0.005), 0.405 * kPaPerMPaHold, 1e-6);
  // "MPa" is the two-column file's
  const PressureSchedule two =
      read_schedule_column(write("time_s,MPa\n0,0.2\n1,0.4\n"), "MPa", true);
  EXPECT_EQ(two.at(0.9), 0.2 * kPaPerMPaHold);
}

TEST_F(ScheduleColumnTest, AColumnThatCannotBeACommandIsOneLineNamingTheFile) {
  const std::string log = "time_s,angle_deg,p_cmd_ago_MPa\n0,-30,0.3\n0.01,-29,0.3\n";
  const struct {
    std::string text, column, expected;
  } cases[] = {
      {log, "p_cmd_anta_MPa", "has no column p_cmd_anta_MPa"},
      {log, "angle_deg", "column angle_deg is not in MPa"},
      {log, "_MPa", "is not in MPa"},
      {"time_s,p_cmd_ago_MPa\n0,0.3\n0,0.4\n", "p_cmd_ago_MPa", "line 3"},
      {"time_s,p_cmd_ago_MPa\n0,nan\n1,0.4\n", "p_cmd_ago_MPa", "line 2"},
      {"time_s,MPa\n0,0.4,7\n", "MPa", "line 2: expected two finite numbers"},
  };
  for (const auto& c : cases) {
    const std::string message = error_of(c.text, c.column);
    EXPECT_NE(message.find("log.csv"), std::string::npos) << message;
    EXPECT_NE(message.find(c.expected), std::string::npos) << c.column << " -> " << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
  }
}

}  // namespace
}  // namespace pamsim
