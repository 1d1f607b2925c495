// atomic_file_test.cc: write_file_atomically writes, leaves no temp file, and reports
// an unwritable folder.
#include "pam_actuator/atomic_file.h"

#include <gtest/gtest.h>

#include <dirent.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>

#include "pam_actuator/input_error.h"

namespace pamsim {
namespace {

std::string read_all(const std::string& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

int count_entries(const std::string& dir) {
  int n = 0;
  DIR* d = opendir(dir.c_str());
  while (dirent* e = readdir(d)) n += e->d_name[0] != '.';
  closedir(d);
  return n;
}

class AtomicFileTest : public ::testing::Test {
 protected:
  std::string dir_;
  void SetUp() override {
    char tmpl[] = "/tmp/atomic_file_test_XXXXXX";
    dir_ = mkdtemp(tmpl);
  }
  void TearDown() override {
    std::remove((dir_ + "/out.txt").c_str());
    rmdir(dir_.c_str());
  }
};

TEST_F(AtomicFileTest, WritesAndReplacesWithoutTempLeftBehind) {
  const std::string path = dir_ + "/out.txt";
  write_file_atomically(path, "first\n");
  EXPECT_EQ(read_all(path), "first\n");
  write_file_atomically(path, std::string("second\0with nul", 15));
  EXPECT_EQ(read_all(path), std::string("second\0with nul", 15));
  EXPECT_EQ(count_entries(dir_), 1);
}

TEST_F(AtomicFileTest, MissingFolderThrowsNamingThePath) {
  const std::string path = dir_ + "/no/such/dir/out.txt";
  try {
    write_file_atomically(path, "x");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(path), std::string::npos);
  }
  EXPECT_EQ(count_entries(dir_), 0);
}

TEST_F(AtomicFileTest, UnwritableFolderThrows) {
  if (::geteuid() == 0) GTEST_SKIP() << "root ignores directory permissions";
  chmod(dir_.c_str(), 0500);
  EXPECT_THROW(write_file_atomically(dir_ + "/out.txt", "x"), InputError);
  chmod(dir_.c_str(), 0700);
  EXPECT_EQ(count_entries(dir_), 0);
}

TEST_F(AtomicFileTest, ReadOnlyFilesystemThrows) {
  // /proc refuses new files even for root, where permission bits do not apply
  EXPECT_THROW(write_file_atomically("/proc/pamsim_atomic_file_test.txt", "x"), InputError);
}

TEST_F(AtomicFileTest, TargetIsADirectoryThrowsAndCleansUp) {
  // rename onto a non-empty directory fails after the temp file was written
  const std::string sub = dir_ + "/out.txt";
  mkdir(sub.c_str(), 0700);
  std::ofstream(sub + "/keep") << "k";
  EXPECT_THROW(write_file_atomically(sub, "x"), InputError);
  std::remove((sub + "/keep").c_str());
  EXPECT_EQ(count_entries(dir_), 1);   // only the directory itself
}

}  // namespace
}  // namespace pamsim
