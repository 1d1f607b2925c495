// toml_file.h: reading a TOML document with errors a user can act on. Every parameter and
// scenario file in pamsim goes through here, so a missing file or a syntax error always
// reads "<path>: cannot open file" or "<path>:<line>:<column>: TOML syntax error: <what>".
#pragma once

#include <string>

#include <toml++/toml.h>

namespace pamsim {

// Parses `text`, naming it `name` in errors. Throws InputError on a syntax error.
toml::table parse_toml_text(const std::string& text, const std::string& name);

// The whole file at `path`. Throws InputError "<path>: cannot open file".
std::string read_text_file(const std::string& path);

// Reads and parses the file at `path`. Throws InputError if it cannot be read or parsed.
toml::table parse_toml_file(const std::string& path);

}  // namespace pamsim
