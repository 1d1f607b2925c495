// staged_outputs.h: a command's output files built in a hidden staging folder inside their
// destination folder (`.pamsim-staging.tmp.XXXXXX`: the same file system, so the moves are
// renames) and moved into place only once every one of them is written. A failure half way
// (a plot gnuplot cannot draw, a full disk, a bad value found late) leaves the destination as
// it was: no mix of old and new files, no half-filled trial folders, and no empty folder made
// for outputs that never came. A process killed outright (SIGKILL, or Ctrl-C in `run`, which
// keeps the default handler) leaves its staging folder behind, and only that.
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "sim/io/outputs.h"
#include "sim/io/temp_path.h"

namespace pamsim {

class StagedOutputs {
 public:
  // `dir`: the destination (it and any missing parents are made here, and removed again if
  // nothing is published into them). `owned`: fnmatch(3) patterns of the entries a run of
  // the same command writes in `dir`; those the new set lacks are removed on publish, so the
  // folder never holds one run's files beside another's (trial_0009/ of a 10-trial run
  // beside a 5-trial run's summary). Throws InputError naming `dir` if it cannot be made.
  StagedOutputs(std::string dir, std::vector<std::string> owned);
  ~StagedOutputs();  // unpublished: removes the staging folder and the folders it made
  StagedOutputs(const StagedOutputs&) = delete;
  StagedOutputs& operator=(const StagedOutputs&) = delete;

  const std::string& dir() const { return dir_; }
  // The staging folder (write the outputs there), and its path for `name`.
  const std::string& staging() const { return staging_->path(); }
  std::string path(const std::string& name) const;

  // Runs `write_outputs` (which writes into the staging folder); an error it throws
  // (InputError or std::runtime_error) is thrown again naming the output in `dir`, where the
  // user looks for it, not the staging folder.
  void write(const std::function<void()>& write_outputs) const;

  // Moves every staged entry into `dir`, replacing a same-named one, and removes the owned
  // entries the new set lacks. A rename that fails puts the old entries back and throws
  // InputError naming the entry (and, if they cannot be put back, the folder that keeps
  // them). The moves are renames one after another: a kill in that instant can leave a mix.
  void publish();

 private:
  std::string dir_;
  std::vector<std::string> owned_;
  std::unique_ptr<FolderGuard> folder_;  // `dir` and the parents made for it (before
                                         // staging_: destroyed after it)
  std::unique_ptr<TempPath> staging_;
  bool published_ = false;
};

// Outputs are not replaced silently: throws InputError "<dir>/<entry>: exists, from an
// earlier run; add --force to replace that run's outputs, or choose another --out" if `dir`
// holds an entry matching one of `owned` (a command's own outputs, as for StagedOutputs).
// The user's other files in `dir` do not count.
void refuse_earlier_outputs(const std::string& dir, const std::vector<std::string>& owned);

}  // namespace pamsim
