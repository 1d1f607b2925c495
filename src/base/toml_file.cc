// toml_file.cc: see toml_file.h.
#include "base/toml_file.h"

#include <sys/stat.h>

#include <cctype>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <iostream>
#include <sstream>

#include "base/format.h"
#include "base/input_error.h"

namespace pamsim {

std::string path_beside(const std::string& file, const std::string& path) {
  if (path.empty() || path[0] == '/') return path;
  const std::size_t slash = file.find_last_of('/');
  return (slash == std::string::npos ? "." : file.substr(0, slash)) + "/" + path;
}

toml::table parse_toml_text(const std::string& text, const std::string& name) {
  try {
    return toml::parse(text, name);
  } catch (const toml::parse_error& e) {
    const auto& where = e.source().begin;
    throw InputError(name + ":" + std::to_string(where.line) + ":" + std::to_string(where.column) +
                     ": TOML syntax error: " + std::string(e.description()));
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
  if (path == "-") {  // standard input, as much as a file may hold
    std::string text;
    char buffer[1 << 16];
    while (std::cin.read(buffer, sizeof(buffer)) || std::cin.gcount() > 0) {
      text.append(buffer, static_cast<std::size_t>(std::cin.gcount()));
      if (text.size() > kMaxTextInputBytes) {
        throw InputError("-: standard input is larger than " +
                         std::to_string(kMaxTextInputBytes >> 20) +
                         " MiB, not an input pamsim reads");
      }
    }
    return text;
  }
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

namespace {

// toml++'s flags without literal strings: strings in double quotes, as people write them
constexpr toml::format_flags kFormat =
    toml::toml_formatter::default_flags & ~toml::format_flags::allow_literal_strings;

bool is_bare_key(std::string_view key) {
  if (key.empty()) return false;
  for (const char c : key) {
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '_' && c != '-') return false;
  }
  return true;
}

std::string key_text(std::string_view key) {
  if (is_bare_key(key)) return std::string(key);
  std::ostringstream out;
  out << toml::toml_formatter{toml::value<std::string>(std::string(key)), kFormat};  // escaped
  return out.str();
}

bool is_array_of_tables(const toml::node& node) {
  const toml::array* a = node.as_array();
  return a && !a->empty() && a->is_array_of_tables();
}

}  // namespace

std::string toml_value_text(const toml::node& node) {
  if (const auto* f = node.as_floating_point()) return format_number(f->get());
  if (const toml::array* a = node.as_array()) {
    std::string out = "[";
    for (std::size_t i = 0; i < a->size(); ++i)
      out += (i ? ", " : "") + toml_value_text(*a->get(i));
    return out + "]";
  }
  if (const toml::table* t = node.as_table()) {
    std::string out = "{ ";
    bool first = true;
    for (const auto& [k, v] : *t) {
      out += (first ? "" : ", ") + key_text(k.str()) + " = " + toml_value_text(v);
      first = false;
    }
    return out + (first ? "}" : " }");
  }
  std::ostringstream out;
  node.visit([&](const auto& value) { out << toml::toml_formatter{value, kFormat}; });
  return out.str();
}

namespace {

void write_table(const toml::table& table, const std::string& path, std::string* out) {
  for (const auto& [k, v] : table) {
    if (v.is_table() || is_array_of_tables(v)) continue;
    *out += key_text(k.str()) + " = " + toml_value_text(v) + "\n";
  }
  for (const auto& [k, v] : table) {
    const std::string child = (path.empty() ? "" : path + ".") + key_text(k.str());
    if (const toml::table* t = v.as_table()) {
      *out += "\n[" + child + "]\n";
      write_table(*t, child, out);
    } else if (is_array_of_tables(v)) {
      for (const toml::node& item : *v.as_array()) {
        *out += "\n[[" + child + "]]\n";
        write_table(*item.as_table(), child, out);
      }
    }
  }
}

}  // namespace

std::string toml_text(const toml::table& table) {
  std::string out;
  write_table(table, "", &out);
  // a document that starts with a table has no values before its first header
  return out.rfind("\n", 0) == 0 ? out.substr(1) : out;
}

}  // namespace pamsim
