// identify_file_recordings.h: an identification file's [[recording]] tables (the lab's
// recordings) and [[candidate]] tables (experiments a lab could run next, for
// `pamsim identify --plan`, identify_plan.h); identify_file.h lists their keys.
#pragma once

#include "base/config_reader.h"
#include "sim/optimize/identify_file.h"

namespace pamsim {

// The keys of a [[tensile]], a [[recording]] and a [[candidate]] table, as the readers take
// them and the key reference lists them.
const std::vector<EntryKey>& tensile_entry_keys();
const std::vector<EntryKey>& recording_entry_keys();
const std::vector<EntryKey>& candidate_entry_keys();

// The event a recording of commands = "log" adds to switch its controller off at 0 s.
inline constexpr const char* kLogCommandsEvent = "log_commands";

// Every [[recording]] into def->recordings (names unique), after the base scenario and its
// overrides.
void read_recordings(ConfigReader& in, IdentifyDefinition* def);

// Every [[candidate]] into def->candidates, after the recordings: its channels sampled at
// rate_hz over duration_s (default: its scenario's sim.duration_s), each channel's noise
// floor given or measured by a fitted recording.
void read_candidates(ConfigReader& in, IdentifyDefinition* def);

}  // namespace pamsim
