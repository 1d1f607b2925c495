// file_changes.cc: see file_changes.h.
#include "base/file_changes.h"

namespace pamsim {
namespace {

void write_table(toml::table& root, const toml::table& changes, const std::string& at,
                 const std::string& prefix, std::vector<std::string>* changed) {
  for (const auto& [k, v] : changes) {
    const std::string key = at + std::string(k.str());
    if (const toml::table* sub = v.as_table()) {
      toml::node* there = root.get(k.str());
      if (there && !there->is_table()) {
        throw file_key_error("", prefix + key, "is a value, not a table");
      }
      if (!there) root.insert_or_assign(k.str(), toml::table{});
      write_table(*root.get(k.str())->as_table(), *sub, key + ".", prefix, changed);
    } else {
      root.insert_or_assign(k.str(), v);
      changed->push_back(key);
    }
  }
}

}  // namespace

std::vector<std::string> write_changes(toml::table& root, const toml::table& changes,
                                       const std::string& prefix) {
  std::vector<std::string> changed;
  write_table(root, changes, "", prefix, &changed);
  return changed;
}

void rethrow_as_change(const InputError& error, const std::string& path,
                       const std::vector<std::string>& changed, const std::string& prefix) {
  const InputErrorParts& parts = error.parts();
  if (parts.file != path || parts.key.empty()) return;
  for (const std::string& k : changed) {
    // the changed value itself, or a table the change made ("pipes" of "pipes.x")
    if (k == parts.key || k.rfind(parts.key + ".", 0) == 0) {
      throw file_key_error("", prefix + parts.key, parts.problem);
    }
  }
}

}  // namespace pamsim
