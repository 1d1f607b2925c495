// temp_path.h: the temp file or folder an output is built in before it is renamed into
// place, `<output>.tmp.XXXXXX` beside the output, made exclusively by make_temp_beside (a
// name nobody can predict or plant a symlink at). The guard removes it when destroyed unless
// released, so an output that was not completed, whatever the exit path, leaves nothing
// behind.
#pragma once

#include <string>

#include "base/atomic_file.h"

namespace pamsim {

class TempPath {
 public:
  // Creates the temp file (empty) or folder. Throws InputError "<output>: cannot write
  // (why)" when the folder is missing or not writable.
  TempPath(const std::string& output, TempKind kind);
  ~TempPath();  // removes the file or folder (recursively) unless released
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
