// input_error.h: the exception type for bad user input (files, keys, values).
// Its message is one line naming the file, the key or row, the value and what is allowed;
// the command line prints it and exits non-zero. Internal invariants use assert instead.
#pragma once

#include <stdexcept>
#include <string>

#include "base/format.h"

namespace pamsim {

class InputError : public std::runtime_error {
 public:
  // (kept printable: an echoed value may hold a NUL, which what() would stop at)
  explicit InputError(const std::string& message)
      : std::runtime_error(printable_message(message)) {}
};

// Throws InputError "<key> must be <allowed>, got <value>" unless `ok`: the one line a
// validated parameter's bad value gets.
inline void require_value(bool ok, const std::string& key, const std::string& allowed,
                          double value) {
  if (!ok) throw InputError(key + " must be " + allowed + ", got " + format_value(value));
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
