// source_mirror.h: a folder that looks like the source tree for the files of one of its
// folders, for tests and fuzz harnesses that must read a changed copy of a shipped file
// without writing into the source tree (a read-only checkout, two test runs at once).
#pragma once

#include <unistd.h>

#include <filesystem>
#include <string>

namespace pamsim_test {

// A folder (returned; the caller removes it) for a file in `dir` ("scenarios",
// "examples/identify") of the source tree `source`: `dir` holds links to the source's files
// there and models/ is a link, so that a reader's relative paths ("../models/...") resolve as
// in the source tree, and a file written into `dir` lands in the folder. `tag` names it.
inline std::filesystem::path source_mirror(const std::filesystem::path& source,
                                           const std::string& tag, const std::string& dir) {
  namespace fs = std::filesystem;
  const fs::path root =
      fs::temp_directory_path() / ("pamsim_mirror_" + tag + "_" + std::to_string(::getpid()));
  fs::remove_all(root);
  fs::create_directories(root / dir);
  fs::create_directory_symlink(source / "models", root / "models");
  for (const auto& e : fs::directory_iterator(source / dir)) {
    fs::create_symlink(e.path(), root / dir / e.path().filename());
  }
  return root;
}

}  // namespace pamsim_test
