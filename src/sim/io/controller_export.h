// controller_export.h: the folder `pamsim controller export` writes, which a lab copies to
// its controller board's project: the embedded controller's sources (pamctl/), this
// controller's configuration as C (pamctl_export.{h,c}) and as JSON (pamctl_config.json,
// which `pamsim controller replay --export` reads back), an example main loop with its board
// hooks, a host program that replays a readings file, and a Makefile and a CMakeLists.txt.
#pragma once

#include <string>
#include <vector>

#include "embedded/pamctl.h"

namespace pamsim {

// What an export holds, by name, relative to its folder (StagedOutputs' owned entries).
const std::vector<std::string>& controller_export_entries();

// Writes the export of `config` (its muscles named `muscles`) into `dir`, every file staged
// and published together; `comment` heads the generated files (the scenario's digest,
// pamsim's version). Refuses (InputError) an earlier export in `dir` unless `force`.
void write_controller_export(const std::string& dir, const pamctl_config& config,
                             const std::vector<std::string>& muscles, const std::string& comment,
                             bool force);

}  // namespace pamsim
