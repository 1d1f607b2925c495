// temp_path.cc: see temp_path.h.
#include "sim/io/temp_path.h"

#include <filesystem>
#include <system_error>

namespace pamsim {

TempPath::TempPath(const std::string& output, TempKind kind)
    : path_(make_temp_beside(output, kind)) {}

TempPath::~TempPath() {
  if (released_) return;
  std::error_code ignored;
  std::filesystem::remove_all(path_, ignored);
}

}  // namespace pamsim
