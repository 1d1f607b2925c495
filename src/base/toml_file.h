// toml_file.h: reading a TOML document with errors a user can act on. Every parameter and
// scenario file in pamsim goes through here, so a missing file or a syntax error always
// reads "<path>: cannot open file" or "<path>:<line>:<column>: TOML syntax error: <what>".
#pragma once

#include <cstdint>
#include <string>

#include <toml++/toml.h>

namespace pamsim {

// Parses `text`, naming it `name` in errors. Throws InputError on a syntax error.
toml::table parse_toml_text(const std::string& text, const std::string& name);

// Inputs are regular files of a bounded size: a directory or a device (/dev/null would read
// as an empty file and give the defaults silently, /dev/zero would be read without end) is
// refused, and so is a file larger than `max_bytes`. Throws InputError "<path>: <problem>".
inline constexpr std::uintmax_t kMaxTextInputBytes = 64u << 20;  // 64 MiB
void require_input_file(const std::string& path, std::uintmax_t max_bytes = kMaxTextInputBytes);

// `path` as a file at `file` gives it: as it is when absolute (or empty), else relative to
// that file's folder ("." for a bare name): "scenarios/a.toml" gives "../models/m.xml" as
// "scenarios/../models/m.xml".
std::string path_beside(const std::string& file, const std::string& path);

// The whole file at `path` (require_input_file first), or standard input for "-" (read
// once: it is empty the second time). Throws InputError "<path>: cannot open file" and the
// like.
std::string read_text_file(const std::string& path);

// Reads and parses the file at `path`. Throws InputError if it cannot be read or parsed.
toml::table parse_toml_file(const std::string& path);

// `table` as TOML text, as toml++ writes it except for floats, which are written in their
// shortest exact form (format_number: "0.14", where toml++ writes 0.14000000000000001):
// values first, then each sub-table under its [header], arrays of tables as [[header]].
// parse_toml_text of the result gives back an equal table.
std::string toml_text(const toml::table& table);
// One value as TOML text, inline, with floats as in toml_text ("0.14", "[1.0, 2.5]", "\"x\"").
std::string toml_value_text(const toml::node& value);

}  // namespace pamsim
