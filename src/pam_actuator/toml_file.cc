// toml_file.cc: see toml_file.h.
#include "pam_actuator/toml_file.h"

#include <sys/stat.h>

#include <cerrno>
#include <cstring>
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

void require_input_file(const std::string& path, std::uintmax_t max_bytes) {
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0) {
    throw InputError(path + ": cannot open file (" + std::strerror(errno) + ")");
  }
  if (!S_ISREG(st.st_mode)) {
    throw InputError(path + (S_ISDIR(st.st_mode) ? ": is a folder, not a file"
                                                  : ": not a regular file (a device or pipe)"));
  }
  if (static_cast<std::uintmax_t>(st.st_size) > max_bytes) {
    throw InputError(path + ": larger than " + std::to_string(max_bytes >> 20) +
                     " MiB, not an input pamsim reads");
  }
}

std::string read_text_file(const std::string& path) {
  require_input_file(path);
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
