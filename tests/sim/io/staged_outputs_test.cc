// staged_outputs_test.cc: a command's outputs published together (StagedOutputs): the new
// set replaces the old one whole, a user's own files stay, and an unpublished staging leaves
// nothing behind, not even the folders it made on the way.
#include "sim/io/staged_outputs.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <set>
#include <stdexcept>
#include <string>

#include "sim/cli_util.h"
#include "base/atomic_file.h"
#include "base/input_error.h"

namespace {

namespace fs = std::filesystem;
using pamsim::InputError;
using pamsim::StagedOutputs;
using pamsim::write_file_atomically;
using pamsim_test::fresh_dir;
using pamsim_test::read_file;

std::set<std::string> names_in(const fs::path& dir) {
  std::set<std::string> names;
  for (const auto& e : fs::directory_iterator(dir)) names.insert(e.path().filename());
  return names;
}

TEST(StagedOutputsTest, ThePublishedSetReplacesTheOwnedOneAndKeepsTheUsersFiles) {
  const fs::path dir = fresh_dir("staged_publish");
  const fs::path out = dir / "out";
  fs::create_directories(out / "trial_0003");
  write_file_atomically((out / "summary.json").string(), "old");
  write_file_atomically((out / "trial_0003" / "summary.json").string(), "old trial");
  write_file_atomically((out / "notes.txt").string(), "the user's");
  {
    StagedOutputs staged(out.string(), {"summary.json", "trial_[0-9][0-9][0-9][0-9]"});
    fs::create_directories(staged.path("trial_0000"));
    write_file_atomically(staged.path("summary.json"), "new");
    write_file_atomically(staged.path("trial_0000/summary.json"), "new trial");
    EXPECT_EQ(read_file(out / "summary.json"), "old") << "nothing changes before publish";
    staged.publish();
  }
  EXPECT_EQ(names_in(out), (std::set<std::string>{"notes.txt", "summary.json", "trial_0000"}));
  EXPECT_EQ(read_file(out / "summary.json"), "new");
  EXPECT_EQ(read_file(out / "trial_0000" / "summary.json"), "new trial");
  EXPECT_EQ(read_file(out / "notes.txt"), "the user's");
  EXPECT_EQ(names_in(dir), std::set<std::string>{"out"}) << "no staging folder left";
}

TEST(StagedOutputsTest, AnUnpublishedStagingLeavesNothingAndNamesTheOutputInErrors) {
  const fs::path dir = fresh_dir("staged_abandon");
  const fs::path out = dir / "new" / "deeper" / "out";
  std::string message;
  try {
    StagedOutputs staged(out.string(), {"*.csv"});
    write_file_atomically(staged.path("a.csv"), "x");
    staged.write([&] { write_file_atomically(staged.path("no_folder/b.csv"), "y"); });
  } catch (const InputError& e) {
    message = e.what();
  }
  // the error names the file where the user will look for it, not the staging folder
  EXPECT_EQ(message.rfind((out / "no_folder/b.csv").string() + ": ", 0), 0u) << message;
  EXPECT_TRUE(names_in(dir).empty()) << "neither the staging folder nor the folders made for it";
}

TEST(StagedOutputsTest, AFileWhereTheFolderShouldBeIsRefused) {
  const fs::path dir = fresh_dir("staged_file");
  write_file_atomically((dir / "out").string(), "a file");
  EXPECT_THROW(StagedOutputs((dir / "out").string(), {}), InputError);
  EXPECT_EQ(read_file(dir / "out"), "a file");
}

}  // namespace
