// temp_path.h: the temp file or folder an output is built in before it is renamed into
// place (the same scheme as write_file_atomically: `<output>.tmp.<pid>`, beside the output).
// The guard removes it when destroyed unless released, so an output that was not completed,
// whatever the exit path, leaves nothing behind.
#pragma once

#include <string>

namespace pamsim {

class TempPath {
 public:
  // Guards `<output>.tmp.<pid>`; creates nothing.
  explicit TempPath(const std::string& output);
  ~TempPath();   // removes the file or folder (recursively) unless released
  TempPath(const TempPath&) = delete;
  TempPath& operator=(const TempPath&) = delete;

  const std::string& path() const { return path_; }
  // The output is complete and was renamed away from the temp path: nothing to remove.
  void release() { released_ = true; }

 private:
  std::string path_;
  bool released_ = false;
};

}  // namespace pamsim
