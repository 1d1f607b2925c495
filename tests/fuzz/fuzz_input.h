// fuzz_input.h: what the libFuzzer harnesses share: the input as a file for readers that
// take a path (one per process, rewritten for each input), a mirror of the source tree for
// readers whose files name others, and the rule every reader must
// keep: a bad input is an InputError (one line) and nothing else escapes; a crash, a
// sanitizer report, a hang or another exception is a finding.
#pragma once

#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>

#include "../source_mirror.h"

namespace pamsim_fuzz {

// Removes a file or folder when the process exits (libFuzzer ends with exit()).
struct RemovedAtExit {
  std::string path;
  ~RemovedAtExit() {
    std::error_code ignored;
    std::filesystem::remove_all(path, ignored);
  }
};

// Writes the input to `<tmp>/pamsim_fuzz_<pid><suffix>` (removed at exit) and returns that path.
inline std::string input_file(const std::uint8_t* data, std::size_t size, const char* suffix) {
  static const RemovedAtExit file{"/tmp/pamsim_fuzz_" + std::to_string(::getpid()) + suffix};
  std::ofstream out(file.path, std::ios::binary | std::ios::trunc);
  out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  return file.path;
}

inline std::string input_text(const std::uint8_t* data, std::size_t size) {
  return std::string(reinterpret_cast<const char*>(data), size);
}

// Writes the input to `path` as it is.
inline void write_input(const std::string& path, const std::uint8_t* data, std::size_t size) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
}

// A folder (returned; the caller removes it at exit) that looks like the source tree for a
// file in `dir` (../source_mirror.h); `tag` names it.
inline std::string source_mirror(const std::string& tag, const std::string& dir) {
  return pamsim_test::source_mirror(PAMSIM_SOURCE_DIR, "fuzz_" + tag, dir).string();
}

}  // namespace pamsim_fuzz
