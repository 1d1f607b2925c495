// atomic_file_test.cc: write_file_atomically writes, leaves no temp file, and reports
// an unwritable folder.
#include "base/atomic_file.h"

#include <gtest/gtest.h>

#include <dirent.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cstdio>
#include <fstream>
#include <sstream>
#include <thread>
#include <string>

#include "base/input_error.h"

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
  EXPECT_EQ(count_entries(dir_), 1);  // only the directory itself
}

// A symlink planted at a guessable temp file name (`<out>.tmp.<pid>`) must not be written
// through: the target keeps its content.
TEST_F(AtomicFileTest, APlantedSymlinkIsNotWrittenThrough) {
  const std::string victim = dir_ + "/victim.txt";
  std::ofstream(victim) << "precious\n";
  const std::string path = dir_ + "/out.txt";
  const std::string planted = path + ".tmp." + std::to_string(::getpid());
  ASSERT_EQ(::symlink(victim.c_str(), planted.c_str()), 0);
  write_file_atomically(path, "new\n");
  EXPECT_EQ(read_all(victim), "precious\n");
  EXPECT_EQ(read_all(path), "new\n");
  struct stat st {};
  ASSERT_EQ(::lstat(planted.c_str(), &st), 0);
  EXPECT_TRUE(S_ISLNK(st.st_mode)) << "the planted link is left alone";
  std::remove(planted.c_str());
  std::remove(victim.c_str());
}

// The file gets the permissions of a plain create (0666 less the umask), not mkstemp's 0600.
TEST_F(AtomicFileTest, PermissionsAreAPlainCreates) {
  const mode_t old = ::umask(022);
  const std::string path = dir_ + "/out.txt";
  write_file_atomically(path, "x");
  ::umask(old);
  struct stat st {};
  ASSERT_EQ(::stat(path.c_str(), &st), 0);
  EXPECT_EQ(st.st_mode & 0777, 0644u);
}

// A full disk, emulated by a file-size limit (a write past it fails with EFBIG): the error
// names the path and nothing is left, neither temp file nor half a file.
TEST_F(AtomicFileTest, AFullDiskIsAnErrorAndLeavesNothing) {
  struct rlimit old {};
  ASSERT_EQ(::getrlimit(RLIMIT_FSIZE, &old), 0);
  struct rlimit small = old;
  small.rlim_cur = 1024;
  ::signal(SIGXFSZ, SIG_IGN);  // a write past the limit then fails with EFBIG
  ASSERT_EQ(::setrlimit(RLIMIT_FSIZE, &small), 0);
  const std::string path = dir_ + "/out.txt";
  bool threw = false;
  try {
    write_file_atomically(path, std::string(4096, 'x'));
  } catch (const InputError& e) {
    threw = std::string(e.what()).find(path) != std::string::npos;
  }
  ::setrlimit(RLIMIT_FSIZE, &old);
  EXPECT_TRUE(threw);
  EXPECT_EQ(count_entries(dir_), 0) << "no temp file and no half file";
}

// "-", a FIFO or a device is a stream: written through, never replaced by a rename (which
// would turn /dev/stdout or a FIFO into a regular file); regular files and new names are not.
TEST_F(AtomicFileTest, StreamOutputsAreWrittenThroughNotReplaced) {
  EXPECT_TRUE(is_stream_output("-"));
  EXPECT_TRUE(is_stream_output("/dev/null"));
  EXPECT_FALSE(is_stream_output(dir_ + "/new.txt"));
  EXPECT_FALSE(is_stream_output(dir_));
  const std::string fifo = dir_ + "/fifo";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  EXPECT_TRUE(is_stream_output(fifo));
  std::string received;
  std::thread reader([&] {
    std::ifstream in(fifo, std::ios::binary);
    std::stringstream ss;
    ss << in.rdbuf();
    received = ss.str();
  });
  write_file_atomically(fifo, "through the pipe\n");
  reader.join();
  EXPECT_EQ(received, "through the pipe\n");
  struct stat st {};
  ASSERT_EQ(::stat(fifo.c_str(), &st), 0);
  EXPECT_TRUE(S_ISFIFO(st.st_mode)) << "the FIFO was replaced";
  EXPECT_EQ(count_entries(dir_), 1) << "no temp file beside it";

  ::testing::internal::CaptureStdout();
  write_file_atomically("-", "to standard output\n");
  EXPECT_EQ(::testing::internal::GetCapturedStdout(), "to standard output\n");
  EXPECT_NO_THROW(write_file_atomically("/dev/null", "discarded"));
}

}  // namespace
}  // namespace pamsim
