// wickramatunge_test.cc: Eq. (1)-(2) of Wickramatunge and Leephakpreeda with their Table 1,
// branch and range selection, inversion, and the parameter file.
#include "pam_actuator/wickramatunge.h"

#include <gtest/gtest.h>

#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <fstream>

#include "base/input_error.h"

namespace pamsim {
namespace {

const std::string kFile = std::string(PAMSIM_SOURCE_DIR) + "/models/pams/wickramatunge_table1.toml";

TEST(WickramatungeTest, HandComputedTable1Value) {
  const WickramatungeModel m = load_wickramatunge(kFile);
  // extension, low range, P = 2 bar, Ls = 3 cm:
  // K = -2.299*4 - 5.741*2*3 + 2.741*9 + 119.304 = 100.331 N/cm, F = 300.993 N
  const double k = -2.299 * 4 - 5.741 * 2 * 3 + 2.741 * 9 + 119.304;
  EXPECT_NEAR(k, 100.331, 1e-9);
  EXPECT_NEAR(wickramatunge_force(m, 2e5, 0.03, StretchDirection::kExtension), 300.993, 1e-9);
  EXPECT_NEAR(wickramatunge_stiffness(m, 2e5, 0.03, StretchDirection::kExtension), 10033.1, 1e-7);
  // contraction, high range, P = 4 bar, Ls = 5 cm
  const double kc = 3.837 * 16 - 2.389 * 4 * 5 + 1.850 * 25 + 53.021;
  EXPECT_NEAR(wickramatunge_force(m, 4e5, 0.05, StretchDirection::kContraction), kc * 5, 1e-9);
}

TEST(WickramatungeTest, PressureRangeAndBranchSelection) {
  const WickramatungeModel m = load_wickramatunge(kFile);
  EXPECT_EQ(m.range(2.49e5), PressureRange::kLow);
  EXPECT_EQ(m.range(2.5e5), PressureRange::kHigh);
  // at Ls = 0 only a0 P^2 + a3 remains: picks the set by range and direction
  const double ls = 1e-9;
  EXPECT_NEAR(wickramatunge_stiffness(m, 1e5, ls, StretchDirection::kExtension),
              (-2.299 + 119.304) * 100, 1e-3);
  EXPECT_NEAR(wickramatunge_stiffness(m, 3e5, ls, StretchDirection::kExtension),
              (4.182 * 9 + 70.377) * 100, 1e-3);
  EXPECT_NEAR(wickramatunge_stiffness(m, 1e5, ls, StretchDirection::kContraction),
              (-2.977 + 104.824) * 100, 1e-3);
  EXPECT_NEAR(wickramatunge_stiffness(m, 3e5, ls, StretchDirection::kContraction),
              (3.837 * 9 + 53.021) * 100, 1e-3);

  // the branch follows the sign of dLs/dt and holds at rest
  EXPECT_EQ(stretch_direction(0.01, StretchDirection::kContraction), StretchDirection::kExtension);
  EXPECT_EQ(stretch_direction(-0.01, StretchDirection::kExtension), StretchDirection::kContraction);
  EXPECT_EQ(stretch_direction(0.0, StretchDirection::kContraction), StretchDirection::kContraction);
  EXPECT_EQ(stretch_direction(0.0, StretchDirection::kExtension), StretchDirection::kExtension);
}

TEST(WickramatungeTest, SlackGivesZeroForce) {
  const WickramatungeModel m = load_wickramatunge(kFile);
  EXPECT_EQ(wickramatunge_force(m, 3e5, 0.0, StretchDirection::kExtension), 0.0);
  EXPECT_EQ(wickramatunge_force(m, 3e5, -0.01, StretchDirection::kExtension), 0.0);
}

TEST(WickramatungeTest, InversionRoundTrip) {
  const WickramatungeModel m = load_wickramatunge(kFile);
  for (StretchDirection dir : {StretchDirection::kExtension, StretchDirection::kContraction}) {
    for (double p_bar = 1.0; p_bar <= 5.0; p_bar += 0.5) {
      for (double ls_cm = 0.25; ls_cm <= 7.0; ls_cm += 0.25) {
        const double f = wickramatunge_force(m, p_bar * 1e5, ls_cm * 1e-2, dir);
        const DeformationEstimate e = invert_wickramatunge(m, p_bar * 1e5, f, dir);
        ASSERT_EQ(e.status, InversionStatus::kOk);
        EXPECT_NEAR(e.d_m, ls_cm * 1e-2, 1e-9 * ls_cm * 1e-2) << p_bar << " " << ls_cm;
      }
    }
  }
  EXPECT_EQ(invert_wickramatunge(m, 3e5, -1.0, StretchDirection::kExtension).status,
            InversionStatus::kSlack);
  EXPECT_EQ(invert_wickramatunge(m, NAN, 10.0, StretchDirection::kExtension).status,
            InversionStatus::kNoPhysicalRoot);
}

class WickramatungeFileTest : public ::testing::Test {
 protected:
  std::string path_ = "/tmp/wickramatunge_test_" + std::to_string(::getpid()) + ".toml";
  void TearDown() override { std::remove(path_.c_str()); }

  void expect_error(const std::string& from, const std::string& to, const std::string& needle) {
    std::ifstream in(kFile);
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const auto at = text.find(from);
    ASSERT_NE(at, std::string::npos) << from;
    std::ofstream(path_) << text.replace(at, from.size(), to);
    try {
      load_wickramatunge(path_);
      ADD_FAILURE() << "no error for " << needle;
    } catch (const InputError& e) {
      const std::string msg = e.what();
      EXPECT_EQ(msg.rfind(path_, 0), 0u) << msg;
      EXPECT_NE(msg.find(needle), std::string::npos) << msg;
    }
  }
};

TEST_F(WickramatungeFileTest, BadFiles) {
  expect_error("a2 = 1.818", "", "extension.high.a2: missing");
  expect_error("a2 = 1.818", "a2 = nan", "extension.high.a2: must be finite");
  expect_error("a2 = 1.818", "a5 = 1.818", "extension.high.a5: unknown key");
  expect_error("length = \"cm\"", "length = \"mm\"", "units.length");
  expect_error("[contraction.low]", "[contraction.lo]", "contraction.lo: unknown key");
  expect_error("pressure_split_bar = 2.5", "pressure_split_bar = -1", "pressure_split_bar");
  expect_error("a0 = 4.182", "a0 = = 4", "TOML syntax error");
  EXPECT_THROW(load_wickramatunge("/nonexistent.toml"), InputError);
}

}  // namespace
}  // namespace pamsim
