// controller_export.cc: an export folder from the built-in sources and a configuration.
#include "sim/io/controller_export.h"

#include <filesystem>

#include "base/atomic_file.h"
#include "sim/io/embedded_config.h"
#include "sim/io/embedded_sources.h"
#include "sim/io/staged_outputs.h"

namespace pamsim {
namespace {

// `text` as a C string literal: quotes and backslashes escaped
std::string c_string(const std::string& text) {
  std::string out = "\"";
  for (char ch : text) {
    if (ch == '"' || ch == '\\') out += '\\';
    out += ch;
  }
  return out + "\"";
}

// the generated header: the muscles' count and names into the template
std::string export_header(const std::string& templ, const std::vector<std::string>& muscles) {
  std::string names;
  for (const std::string& m : muscles) names += (names.empty() ? "" : ", ") + c_string(m);
  std::string text = templ;
  const auto put = [&text](const std::string& key, const std::string& value) {
    text.replace(text.find(key), key.size(), value);
  };
  put("@MUSCLE_COUNT@", std::to_string(muscles.size()));
  put("@MUSCLE_NAMES@", names);
  return text;
}

}  // namespace

const std::vector<std::string>& controller_export_entries() {
  static const std::vector<std::string> entries = [] {
    std::vector<std::string> names = {"pamctl", "pamctl_export.h", "pamctl_export.c",
                                      "pamctl_config.json"};
    for (const EmbeddedFile& f : embedded_sources()) {
      const std::string path = f.path;
      if (path.rfind("pamctl/", 0) != 0 && path != "pamctl_export.h.in") names.push_back(path);
    }
    return names;
  }();
  return entries;
}

void write_controller_export(const std::string& dir, const pamctl_config& config,
                             const std::vector<std::string>& muscles, const std::string& comment,
                             bool force) {
  if (!force) refuse_earlier_outputs(dir, controller_export_entries());
  StagedOutputs staged(dir, controller_export_entries());
  staged.write([&] {
    // the library and the templates as built into pamsim
    std::filesystem::create_directories(staged.path("pamctl"));
    for (const EmbeddedFile& f : embedded_sources()) {
      const std::string path = f.path;
      if (path == "pamctl_export.h.in") {
        write_file_atomically(staged.path("pamctl_export.h"), export_header(f.text, muscles));
      } else {
        write_file_atomically(staged.path(path), f.text);
      }
    }
    // this controller's configuration, as C and as JSON
    write_file_atomically(staged.path("pamctl_export.c"),
                          embedded_config_c(config, muscles, comment));
    write_file_atomically(staged.path("pamctl_config.json"),
                          embedded_config_json(config, muscles).dump(2) + "\n");
  });
  staged.publish();
}

}  // namespace pamsim
