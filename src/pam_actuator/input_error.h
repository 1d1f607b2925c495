// input_error.h: the exception type for bad user input (files, keys, values).
// Its message is one line naming the file, the key or row, the value and what is allowed;
// the command line prints it and exits non-zero. Internal invariants use assert instead.
#pragma once

#include <stdexcept>
#include <string>

namespace pamsim {

class InputError : public std::runtime_error {
 public:
  explicit InputError(const std::string& message) : std::runtime_error(message) {}
};

}  // namespace pamsim
