// schedule_test.cc: the pressure schedules of core/schedule.h against their closed forms
// (constant, ramp, sine, steps, piecewise-linear table), their ranges, the CSV reader's
// one-line errors (naming the file and the line) and validate's.
#include "sim/core/schedule.h"
#include "sim/scenario/schedule_csv.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "sim/cli_util.h"
#include "base/input_error.h"

namespace pamsim {
namespace {

constexpr double kMPa = 1e6;
constexpr double kPi = 3.14159265358979323846;

TEST(ScheduleTest, ConstantIsItsValueExactly) {
  PressureSchedule s;
  s.p0_pa = 0.4 * kMPa;
  for (double t : {0.0, 1.0, 1e3}) EXPECT_EQ(s.at(t), 0.4 * kMPa);
  EXPECT_EQ(s.min_pa(), 0.4 * kMPa);
  EXPECT_EQ(s.max_pa(), 0.4 * kMPa);
}

// the reaching task's agonist: 0.2 -> 0.6 MPa over 12 s from t = 2 s
TEST(ScheduleTest, RampHoldsThenRunsLinearlyThenHolds) {
  PressureSchedule s;
  s.kind = ScheduleKind::kRamp;
  s.p0_pa = 0.2 * kMPa;
  s.p1_pa = 0.6 * kMPa;
  s.start_s = 2.0;
  s.duration_s = 12.0;
  EXPECT_DOUBLE_EQ(s.at(0.0), 0.2 * kMPa);
  EXPECT_DOUBLE_EQ(s.at(2.0), 0.2 * kMPa);
  EXPECT_DOUBLE_EQ(s.at(5.0), 0.3 * kMPa);
  EXPECT_DOUBLE_EQ(s.at(8.0), 0.4 * kMPa);
  EXPECT_DOUBLE_EQ(s.at(14.0), 0.6 * kMPa);
  EXPECT_DOUBLE_EQ(s.at(100.0), 0.6 * kMPa);
  EXPECT_EQ(s.min_pa(), 0.2 * kMPa);
  EXPECT_EQ(s.max_pa(), 0.6 * kMPa);

  // a falling ramp (the antagonist's) has the same range
  std::swap(s.p0_pa, s.p1_pa);
  EXPECT_DOUBLE_EQ(s.at(8.0), 0.4 * kMPa);
  EXPECT_EQ(s.min_pa(), 0.2 * kMPa);
  EXPECT_EQ(s.max_pa(), 0.6 * kMPa);
}

// the length-estimation test: p = 0.2 sin(2 pi t / 5) + 0.6 MPa
TEST(ScheduleTest, SineIsThePapersSinusoid) {
  PressureSchedule s;
  s.kind = ScheduleKind::kSine;
  s.p0_pa = 0.6 * kMPa;
  s.amplitude_pa = 0.2 * kMPa;
  s.period_s = 5.0;
  for (double t = 0.0; t < 20.0; t += 0.37) {
    EXPECT_NEAR(s.at(t), (0.2 * std::sin(2 * kPi * t / 5) + 0.6) * kMPa, 1e-6) << t;
  }
  EXPECT_NEAR(s.at(1.25), 0.8 * kMPa, 1e-6);  // a quarter period: the top
  EXPECT_NEAR(s.at(3.75), 0.4 * kMPa, 1e-6);
  EXPECT_EQ(s.min_pa(), 0.4 * kMPa);
  EXPECT_EQ(s.max_pa(), 0.8 * kMPa);

  // a start time holds the offset before it; a phase shifts it; a negative amplitude
  // keeps the range
  s.start_s = 1.0;
  s.phase_rad = kPi / 2;
  s.amplitude_pa = -0.2 * kMPa;
  EXPECT_EQ(s.at(0.5), 0.6 * kMPa);
  EXPECT_NEAR(s.at(1.0), 0.4 * kMPa, 1e-6);
  EXPECT_EQ(s.min_pa(), 0.4 * kMPa);
  EXPECT_EQ(s.max_pa(), 0.8 * kMPa);
}

TEST(ScheduleTest, StepsTakeEachLevelFromItsTime) {
  PressureSchedule s;
  s.kind = ScheduleKind::kSteps;
  s.times_s = {1.0, 2.0, 3.0};
  s.values_pa = {0.1 * kMPa, 0.5 * kMPa, 0.3 * kMPa};
  EXPECT_EQ(s.at(0.0), 0.1 * kMPa);  // before the first time: the first level
  EXPECT_EQ(s.at(1.0), 0.1 * kMPa);
  EXPECT_EQ(s.at(1.999), 0.1 * kMPa);
  EXPECT_EQ(s.at(2.0), 0.5 * kMPa);
  EXPECT_EQ(s.at(2.5), 0.5 * kMPa);
  EXPECT_EQ(s.at(3.0), 0.3 * kMPa);
  EXPECT_EQ(s.at(50.0), 0.3 * kMPa);
  EXPECT_EQ(s.min_pa(), 0.1 * kMPa);
  EXPECT_EQ(s.max_pa(), 0.5 * kMPa);
}

class ScheduleCsvTest : public ::testing::Test {
 protected:
  std::string write(const std::string& name, const std::string& text) {
    const auto path = dir_ / name;
    pamsim_test::write_text(path, text);
    return path.string();
  }
  // the message of the InputError reading `text` throws, or "" if none
  std::string error_of(const std::string& text) {
    const std::string path = write("bad.csv", text);
    try {
      read_schedule_csv(path);
    } catch (const InputError& e) {
      return e.what();
    }
    return "";
  }
  std::filesystem::path dir_ = pamsim_test::fresh_dir("schedule_csv");
};

TEST_F(ScheduleCsvTest, TableInterpolatesLinearlyAndHoldsItsEnds) {
  const std::string path = write("ok.csv",
                                 "# a comment, then the header\r\n"
                                 "time_s, MPa\r\n"
                                 "\n"
                                 "1.0, 0.2\r\n"
                                 "3.0,0.6\n"
                                 "4.0,+0.1\n");
  const PressureSchedule s = read_schedule_csv(path);
  EXPECT_EQ(s.kind, ScheduleKind::kTable);
  EXPECT_EQ(s.source, path);
  ASSERT_EQ(s.times_s.size(), 3u);
  EXPECT_EQ(s.at(0.0), 0.2 * kMPa);
  EXPECT_NEAR(s.at(2.0), 0.4 * kMPa, 1e-9);
  EXPECT_NEAR(s.at(3.5), 0.35 * kMPa, 1e-9);
  EXPECT_EQ(s.at(9.0), 0.1 * kMPa);
  EXPECT_EQ(s.min_pa(), 0.1 * kMPa);
  EXPECT_EQ(s.max_pa(), 0.6 * kMPa);
  EXPECT_NO_THROW(validate(s, "muscles.pam.command", 0.7 * kMPa));
}

TEST_F(ScheduleCsvTest, EveryMalformedFileIsOneLineNamingFileAndLine) {
  struct Case {
    std::string text, expected;
  };
  const Case cases[] = {
      {"", "empty file"},
      {"# only a comment\n", "empty file"},
      {"time,pressure\n0,0.4\n", "line 1: expected the header"},
      {"time_s,MPa\n", "no (time_s, MPa) rows"},
      {"time_s,MPa\n0,0.4\n1\n", "line 3: expected two finite numbers"},
      {"time_s,MPa\n0,0.4,7\n", "line 2: expected two finite numbers"},
      {"time_s,MPa\n0,abc\n", "line 2: expected two finite numbers"},
      {"time_s,MPa\n0,nan\n", "line 2: expected two finite numbers"},
      {"time_s,MPa\n0,0.4 MPa\n", "line 2: expected two finite numbers"},
      {"time_s,MPa\n0,0.4\n2,0.5\n1,0.6\n", "line 4: time must increase strictly"},
      {"time_s,MPa\n0,0.4\n0,0.5\n", "line 3: time must increase strictly"},
  };
  for (const Case& c : cases) {
    const std::string message = error_of(c.text);
    EXPECT_NE(message.find("bad.csv"), std::string::npos) << message;
    EXPECT_NE(message.find(c.expected), std::string::npos) << c.text << " -> " << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
  }
  // a file far larger than any schedule (sparse: no disk is spent) is refused before reading
  const auto huge = dir_ / "huge.csv";
  pamsim_test::write_text(huge, "time_s,MPa\n");
  std::filesystem::resize_file(huge, 65u << 20);
  try {
    read_schedule_csv(huge.string());
    ADD_FAILURE() << "a 65 MiB file was read as a schedule";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("huge.csv: larger than 64 MiB"), std::string::npos);
  }
  std::filesystem::remove(huge);
  try {
    read_schedule_csv((dir_ / "missing.csv").string());
    ADD_FAILURE() << "a missing file was read";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("missing.csv: cannot open"), std::string::npos);
  }
}

TEST(ScheduleTest, ValidateNamesTheFieldThatIsWrong) {
  const std::string key = "muscles.agonist.command";
  auto error_of = [&](const PressureSchedule& s) -> std::string {
    try {
      validate(s, key, 0.7 * kMPa);
    } catch (const InputError& e) {
      return e.what();
    }
    return "";
  };
  PressureSchedule ok;
  ok.p0_pa = 0.4 * kMPa;
  EXPECT_EQ(error_of(ok), "");

  PressureSchedule ramp = ok;
  ramp.kind = ScheduleKind::kRamp;
  ramp.duration_s = 0.0;
  EXPECT_EQ(error_of(ramp), key + ".duration_s must be > 0");

  PressureSchedule sine = ok;
  sine.kind = ScheduleKind::kSine;
  sine.period_s = -5.0;
  EXPECT_EQ(error_of(sine), key + ".period_s must be > 0");
  sine.period_s = 5.0;
  sine.amplitude_pa = NAN;
  EXPECT_EQ(error_of(sine), key + " must have finite values");
  sine.amplitude_pa = 0.3 * kMPa;  // 0.4 +- 0.3 MPa fits the 0.7 MPa supply exactly
  EXPECT_EQ(error_of(sine), "");
  sine.p0_pa = 0.5 * kMPa;
  EXPECT_NE(error_of(sine).find(key + " must stay within [0, 0.7] MPa"), std::string::npos);
  EXPECT_NE(error_of(sine).find("goes from 0.2 to 0.8 MPa"), std::string::npos);
  sine.p0_pa = 0.2 * kMPa;
  EXPECT_NE(error_of(sine).find("goes from -0.1 to 0.5 MPa"), std::string::npos);

  PressureSchedule steps = ok;
  steps.kind = ScheduleKind::kSteps;
  steps.times_s = {0.0, 1.0};
  steps.values_pa = {0.1 * kMPa};
  EXPECT_NE(error_of(steps).find(key + ".times_s must give one pressure per time"),
            std::string::npos);
  steps.values_pa = {0.1 * kMPa, 0.2 * kMPa};
  EXPECT_EQ(error_of(steps), "");
  steps.times_s = {1.0, 1.0};
  EXPECT_EQ(error_of(steps), key + ".times_s must increase strictly");
}

TEST(ScheduleTest, KindsParseByNameAndAnUnknownOneIsNamed) {
  for (ScheduleKind k : {ScheduleKind::kConstant, ScheduleKind::kRamp, ScheduleKind::kSine,
                         ScheduleKind::kSteps, ScheduleKind::kTable}) {
    EXPECT_EQ(parse_schedule_kind(to_string(k), "k"), k);
  }
  try {
    parse_schedule_kind("square", "muscles.pam.command.kind");
    ADD_FAILURE() << "\"square\" was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("muscles.pam.command.kind must be one of"),
              std::string::npos);
    EXPECT_NE(std::string(e.what()).find("got \"square\""), std::string::npos);
  }
}

}  // namespace
}  // namespace pamsim
