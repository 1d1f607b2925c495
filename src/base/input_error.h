// input_error.h: the exception type for bad user input (files, keys, values).
// Its message is one line naming the file, the key or row, the value and what is allowed;
// the command line prints it and exits non-zero. Internal invariants use assert instead.
// An error about one key also keeps the file, the key and the problem as fields (parts()),
// so that a reader that re-throws it under another name (a plant file's SI field as the
// file's key, a changed field as the scenario key that changed it) never parses the text.
#pragma once

#include <stdexcept>
#include <string>
#include <utility>

#include "base/format.h"

namespace pamsim {

// What an error about one key says: where (a file's path, or "" when the thrower does not
// know it), which key, and the problem ("must be > 0, got -1").
struct InputErrorParts {
  std::string file;
  std::string key;
  std::string problem;
};

class InputError : public std::runtime_error {
 public:
  // A line whose parts are not told apart (a file that cannot be opened, a syntax error).
  // (kept printable: an echoed value may hold a NUL, which what() would stop at)
  explicit InputError(const std::string& message)
      : std::runtime_error(printable_message(message)) {}
  // `message` as the user reads it, and the parts it was made of.
  InputError(const std::string& message, InputErrorParts parts)
      : std::runtime_error(printable_message(message)), parts_(std::move(parts)) {}

  // The parts; parts().key is empty for an error that names no one key.
  const InputErrorParts& parts() const { return parts_; }

 private:
  InputErrorParts parts_;
};

// "<file>: <key>: <problem>" (a parameter file's style), "<key>: <problem>" without a file.
inline InputError file_key_error(const std::string& file, const std::string& key,
                                 const std::string& problem) {
  const std::string where = file.empty() ? key : file + ": " + key;
  return InputError(where + ": " + problem, {file, key, problem});
}

// Throws InputError "<key> must be <allowed>, got <value>" unless `ok`: the one line a
// validated parameter's bad value gets.
inline void require_value(bool ok, const std::string& key, const std::string& allowed,
                          double value) {
  if (ok) return;
  const std::string problem = "must be " + allowed + ", got " + format_value(value);
  throw InputError(key + " " + problem, {"", key, problem});
}

}  // namespace pamsim

namespace pamsim {

// Thrown by a command whose run finished but whose simulation diverged: the details were
// already printed, one line per trial; main() exits non-zero without another message.
class SimulationFailed : public std::runtime_error {
 public:
  SimulationFailed() : std::runtime_error("simulation diverged") {}
};

}  // namespace pamsim
