// embedded_sources.h: the embedded controller's sources and the export's templates, built
// into pamsim (scripts/embed-sources.cmake writes their definition from src/embedded), so
// that `pamsim controller export` writes the very code pamsim runs.
#pragma once

#include <string>
#include <vector>

namespace pamsim {

struct EmbeddedFile {
  const char* path;  // in the export: pamctl/pamctl.h, Makefile, pamctl_export.h.in, ...
  const char* text;
};

const std::vector<EmbeddedFile>& embedded_sources();

}  // namespace pamsim
