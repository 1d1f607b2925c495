// input_file_test.cc: pamsim reads only regular files of a bounded size: a folder or
// /dev/null as a parameter file must not give the defaults silently, nor /dev/zero be read
// without end. Each is one error naming the path, through every reader.
#include "base/toml_file.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdio>
#include <fstream>
#include <functional>
#include <string>

#include "base/input_error.h"
#include "pam_actuator/pam_params.h"
#include "pam_actuator/plant_params.h"
#include "pam_actuator/tensile_csv.h"

namespace pamsim {
namespace {

std::string error_of(const std::function<void()>& read) {
  try {
    read();
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(InputFileTest, FoldersDevicesAndHugeFilesAreRefusedByEveryReader) {
  const std::string dir = ::testing::TempDir();
  const std::string huge = dir + "input_file_test_huge_" + std::to_string(::getpid()) + ".toml";
  {
    std::ofstream out(huge);
    out.seekp((64 << 20) + 10);  // sparse: 64 MiB + 10 bytes, nothing written
    out << 'x';
  }
  struct Case {
    std::string path, says;
  };
  for (const Case& c :
       {Case{dir, "is a folder, not a file"}, Case{"/dev/null", "not a regular file"},
        Case{"/dev/zero", "not a regular file"}, Case{huge, "larger than 64 MiB"},
        Case{dir + "no_such_input.toml", "cannot open file"}}) {
    SCOPED_TRACE(c.path);
    for (const auto& read : std::vector<std::function<void()>>{
             [&] { read_text_file(c.path); }, [&] { load_pam_params(c.path); },
             [&] { load_plant_params(c.path); }, [&] { read_tensile_csv(c.path); }}) {
      const std::string e = error_of(read);
      EXPECT_EQ(e.rfind(c.path, 0), 0u) << e;
      EXPECT_NE(e.find(c.says), std::string::npos) << e;
    }
  }
  std::remove(huge.c_str());
}

}  // namespace
}  // namespace pamsim
