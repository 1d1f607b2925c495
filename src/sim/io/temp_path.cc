// temp_path.cc: see temp_path.h.
#include "sim/io/temp_path.h"

#include <unistd.h>

#include <filesystem>
#include <system_error>

namespace pamsim {

TempPath::TempPath(const std::string& output)
    : path_(output + ".tmp." + std::to_string(::getpid())) {}

TempPath::~TempPath() {
  if (released_) return;
  std::error_code ignored;   // it may never have been created
  std::filesystem::remove_all(path_, ignored);
}

}  // namespace pamsim
