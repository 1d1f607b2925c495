// mujoco_util_test.cc: MuJoCo's own messages go through pamsim's handlers: a warning is one
// "pamsim: MuJoCo warning" line on stderr and leaves no MUJOCO_LOG.TXT in the working folder
// (MuJoCo's default handler appends to that file wherever the user happens to be); a model
// that fails to load is an InputError naming the file.
#include "sim/core/mujoco_util.h"

#include <gtest/gtest.h>
#include <mujoco/mujoco.h>
#include <unistd.h>

#include <filesystem>
#include <string>

#include "sim/cli_util.h"
#include "base/input_error.h"

namespace {

namespace fs = std::filesystem;

TEST(MujocoUtilTest, WarningsAreOurLinesAndLeaveNoLogFile) {
  const fs::path dir = pamsim_test::fresh_dir("mujoco_log");
  const fs::path before = fs::current_path();
  fs::current_path(dir);
  pamsim::install_mujoco_handlers();
  ::testing::internal::CaptureStderr();
  mju_warning("a test warning");
  const std::string err = ::testing::internal::GetCapturedStderr();
  fs::current_path(before);
  EXPECT_EQ(err, "pamsim: MuJoCo warning: a test warning\n");
  EXPECT_FALSE(fs::exists(dir / "MUJOCO_LOG.TXT"));
}

TEST(MujocoUtilTest, AModelThatFailsToLoadNamesTheFile) {
  const fs::path dir = pamsim_test::fresh_dir("mujoco_bad_model");
  pamsim_test::write_text(dir / "bad.xml", "<mujoco><worldbody><body></mujoco>");
  try {
    pamsim::load_mjcf((dir / "bad.xml").string());
    FAIL() << "expected an InputError";
  } catch (const pamsim::InputError& e) {
    EXPECT_EQ(
        std::string(e.what()).rfind((dir / "bad.xml").string() + ": model failed to load: ", 0), 0u)
        << e.what();
    EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos) << "one line";
  }
  EXPECT_FALSE(fs::exists(dir / "MUJOCO_LOG.TXT"));
  EXPECT_FALSE(fs::exists("MUJOCO_LOG.TXT"));
}

}  // namespace
