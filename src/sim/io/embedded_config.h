// embedded_config.h: the embedded controller's configuration (src/embedded/pamctl.h) as the
// files `pamsim controller export` writes: pamctl_config.json, which `pamsim controller
// replay --export DIR` reads back, and the C source pamctl_export.c that a board compiles.
// Both are written from one list of the struct's fields, every number exactly: the JSON's as
// the shortest decimal that reads back to the same double, the C source's as hex floats.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "embedded/pamctl.h"

namespace pamsim {

// {"pamctl_version", "muscle_names": [...], and every field by its path}
nlohmann::json embedded_config_json(const pamctl_config& config,
                                    const std::vector<std::string>& muscles);

// The configuration in `j` (read from `path`), its muscles' names into *muscles. Throws
// InputError "<path>: <field> ..." for a missing field or one of the wrong type, and
// "<path>: <problem>" for what pamctl_check_config refuses.
pamctl_config embedded_config_from_json(const nlohmann::json& j, const std::string& path,
                                        std::vector<std::string>* muscles);

// pamctl_export.c: `void pamctl_export_config(pamctl_config* config)` setting every field,
// under `comment` (the scenario's digest, pamsim's version); PAMCTL_FLOAT builds round each
// value to float once, as the compiler reads the literal.
std::string embedded_config_c(const pamctl_config& config, const std::vector<std::string>& muscles,
                              const std::string& comment);

}  // namespace pamsim
