// fuzz_input.h: what the libFuzzer harnesses share: the input as a file for readers that
// take a path (one per process, rewritten for each input), and the rule every reader must
// keep: a bad input is an InputError (one line) and nothing else escapes; a crash, a
// sanitizer report, a hang or another exception is a finding.
#pragma once

#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>

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

}  // namespace pamsim_fuzz
