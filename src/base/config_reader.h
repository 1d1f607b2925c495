// config_reader.h: typed, validated access to a TOML document (scenarios, sweeps).
// Every key read is marked; reject_unknown() then names the first key nobody asked for,
// so a typo is an error, not a silently ignored setting. `--set a.b=v` overrides are
// applied to the document before reading and go through exactly the same checks.
#pragma once

#include <cstdint>
#include <initializer_list>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include <toml++/toml.h>

#include "base/format.h"  // format_value, for the messages
#include "base/input_error.h"
#include "base/entry_keys.h"

namespace pamsim {

class ConfigReader {
 public:
  // Parses `path`. Throws InputError "<path>: <problem>" (missing file, syntax error + line).
  explicit ConfigReader(const std::string& path);
  // For tests and inline documents.
  ConfigReader(const std::string& text, const std::string& name);

  // Applies "a.b=value" (value parsed as TOML: 1.5, true, "x", [1,2]; bare words become
  // strings). Throws InputError "--set <arg>: ..." when malformed.
  void apply_override(const std::string& assignment);
  void apply_overrides(const std::vector<std::string>& assignments);
  // If `key` holds a value (not a table), makes it a table holding that value as `field`:
  // how a key that is a file's path grows keys of its own ("plant" -> "plant.file").
  void nest_value(const std::string& key, const std::string& field);

  bool has(const std::string& key) const;
  double get_double(const std::string& key, double fallback);
  double require_double(const std::string& key);
  std::int64_t get_int(const std::string& key, std::int64_t fallback);
  bool get_bool(const std::string& key, bool fallback);
  std::string get_string(const std::string& key, const std::string& fallback);
  std::string require_string(const std::string& key);
  // A path value, resolved relative to the folder of the file that holds the document.
  std::string get_path(const std::string& key, const std::string& fallback);
  // A path that must be given: "<file>: <key> is required (<what>)" when it is not.
  std::string require_path(const std::string& key, const std::string& what);
  // A path to a file to read (get_path), which must exist as a regular file of bounded size
  // (require_input_file); otherwise InputError "<file>: <key>: <path>: <problem>", so that the
  // message names the key that points at the file.
  std::string get_input_path(const std::string& key, const std::string& fallback);
  // A list of strings or of finite numbers (a single value is not a list).
  std::vector<std::string> get_string_list(const std::string& key,
                                           const std::vector<std::string>& fallback);
  std::vector<double> get_double_list(const std::string& key, const std::vector<double>& fallback);
  // A table of tables or values the caller interprets itself (marks the whole subtree read).
  const toml::node* raw(const std::string& key);
  // The names of a table's entries, in the document's order; empty if `table` is not one
  // ("" for the top level). Marks nothing read.
  std::vector<std::string> child_keys(const std::string& table) const;
  bool is_table(const std::string& key) const;
  // Every value's dotted key (tables descended into, arrays are values).
  std::vector<std::string> leaf_keys() const;
  // True if the key (or a key under it) came from a --set override.
  bool overridden(const std::string& key) const;

  // The document with the overrides applied (to write it back out, e.g. a sweep's best setting).
  const toml::table& document() const { return doc_; }

  // Throws InputError naming the first key that was never read, with the nearest key the
  // reader asked for ("did you mean reflex.v_thr_mm_s?").
  void reject_unknown() const;

  // Every key the reader asked for (read, or asked whether present), given or not.
  std::vector<std::string> asked_keys() const;
  // The keys read with a fallback that the document does not give, and the fallback used,
  // as TOML value text ("0.001", "true", "\"iso6358\""): the defaults in effect. Empty
  // fallbacks ("", []: "not given") are not listed.
  const std::map<std::string, std::string>& defaults_used() const { return defaults_; }

  // "<file>: <key> <problem>" (with "--set" named when the key came from an override).
  [[noreturn]] void fail(const std::string& key, const std::string& problem) const;
  // "<file>: <key>" or "<file>: --set <key>": where a key's value came from, for messages.
  std::string where(const std::string& key) const;
  // "sim.duration_s = 1 (--set)", "drop.time_s = 1 (default)" or "... (file)": another key's
  // value in a message about two keys, so that a refusal caused by one key's default or by an
  // override of the other says so.
  std::string described(const std::string& key, double value) const;
  const std::string& name() const { return name_; }

  // Convenience checks that throw through fail().
  void check(bool ok, const std::string& key, const std::string& problem) const {
    if (!ok) fail(key, problem);
  }

 private:
  const toml::node* find(const std::string& key) const;
  void collect_leaves(const toml::table& t, const std::string& prefix,
                      std::vector<std::string>* out) const;

  toml::table doc_;
  std::string name_;
  std::set<std::string> read_;
  mutable std::set<std::string> asked_;  // has() and is_table() queries
  std::map<std::string, std::string> defaults_;
  std::set<std::string> overridden_;
};

// One table of an array of tables of a reader's document (the i-th [[parameter]]): typed
// reads whose messages go through the reader's fail and name "<name>[i].<key>".
struct TableEntry {
  ConfigReader& in;
  const toml::table& table;
  std::string where;  // "parameter[0]."

  // Refuses a key not in `keys` ("<where><key> is not a key of this table (...)") and a value
  // its row's type, range or names exclude (entry_value_problem).
  void allow(const std::vector<EntryKey>& keys) const;
  // A string ("... must be a string"); a missing one is refused if `required`, else `fallback`.
  std::string text(const char* key, bool required, const std::string& fallback = "") const;
  // A finite number, or nothing if the key is absent.
  std::optional<double> number(const char* key) const;
  // A list of strings ("... must be a list of strings"); a missing one is refused if
  // `required`, else empty.
  std::vector<std::string> texts(const char* key, bool required) const;
};

// The array of tables `name` ([[name]]) of a reader's document, marked read; empty if absent.
// Refuses a value that is not an array ("<name> must be an array of tables ([[name]])") and,
// when it is asked for, an entry that is not a table ("<name>[i] must be a table").
class TableArray {
 public:
  TableArray(ConfigReader& in, const std::string& name);
  std::size_t size() const { return array_ ? array_->size() : 0; }
  TableEntry operator[](std::size_t i) const;
  // Every entry, in order, each refusing a key not in `keys` and a value its row's type,
  // range or names exclude (TableEntry::allow).
  std::vector<TableEntry> entries(const std::vector<EntryKey>& keys) const;

 private:
  ConfigReader& in_;
  std::string name_;
  const toml::array* array_ = nullptr;
};

// "a.b.c" -> {"a", "b", "c"}: a dotted key's parts.
std::vector<std::string> split_key(const std::string& key);

// True if `s` is longer than `suffix` and ends with it (a key with a name before its suffix).
inline bool ends_with(const std::string& s, const std::string& suffix) {
  return s.size() > suffix.size() &&
         s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

// Runs `parse` (a parser of one value, which knows nothing of files), prefixing any
// InputError it throws with the document's name: "<file>: <key>: <problem>".
template <typename F>
auto in_file(const ConfigReader& in, F&& parse) -> decltype(parse()) {
  try {
    return parse();
  } catch (const InputError& e) {
    InputErrorParts parts = e.parts();  // a key's error found in this file
    if (!parts.key.empty() && parts.file.empty()) parts.file = in.name();
    throw InputError(in.name() + ": " + e.what(), std::move(parts));
  }
}

}  // namespace pamsim
