// toml_file.cc: see toml_file.h.
#include "pam_actuator/toml_file.h"

#include <fstream>
#include <sstream>

#include "pam_actuator/input_error.h"

namespace pamsim {

toml::table parse_toml_text(const std::string& text, const std::string& name) {
  try {
    return toml::parse(text, name);
  } catch (const toml::parse_error& e) {
    const auto& where = e.source().begin;
    throw InputError(name + ":" + std::to_string(where.line) + ":" +
                     std::to_string(where.column) + ": TOML syntax error: " +
                     std::string(e.description()));
  }
}

std::string read_text_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path + ": cannot open file");
  std::stringstream buffer;
  buffer << in.rdbuf();
  return buffer.str();
}

toml::table parse_toml_file(const std::string& path) {
  return parse_toml_text(read_text_file(path), path);
}

}  // namespace pamsim
