// file_changes.h: a parameter file read with some of its fields replaced, the way scenario
// keys change them (muscles.<m>.plant.<table>.<field>, pneumatics.<table>.<field>). The
// changes are written over the parsed file, table by table, and the file's own reader
// validates the result, so a changed field obeys exactly the file's rules; a value it
// refuses that came from a change is named by the change's key ("<prefix><table>.<field>:
// <problem>"), one that came from the file by the file ("<path>: <table>.<field>: ...").
#pragma once

#include <string>
#include <vector>

#include <toml++/toml.h>

#include "base/input_error.h"
#include "base/toml_file.h"

namespace pamsim {

// Writes `changes` over `root`; returns the dotted keys of the values written. A change
// whose path runs into a value ("geometry.length_mm.x") is refused: InputError
// "<prefix><key>: is a value, not a table".
std::vector<std::string> write_changes(toml::table& root, const toml::table& changes,
                                       const std::string& prefix);

// If `error` names a key of the file at `path` (its parts) that is one of `changed` or a
// table holding one, throws it as "<prefix><key>: <problem>"; otherwise returns.
void rethrow_as_change(const InputError& error, const std::string& path,
                       const std::vector<std::string>& changed, const std::string& prefix);

// The file at `path` parsed, `changes` written over it, and read by `read(table, path)`,
// which throws InputError "<path>: <key>: <problem>" for a bad value (file_key_error).
template <class Read>
auto read_with_changes(const std::string& path, const toml::table& changes,
                       const std::string& prefix, Read read) {
  toml::table root = parse_toml_file(path);
  const std::vector<std::string> changed = write_changes(root, changes, prefix);
  try {
    return read(root, path);
  } catch (const InputError& e) {
    rethrow_as_change(e, path, changed, prefix);
    throw;
  }
}

}  // namespace pamsim
