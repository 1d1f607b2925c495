// config_reader.cc: see config_reader.h.
#include "base/config_reader.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>

#include "base/input_error.h"
#include "base/toml_file.h"
#include "base/suggest.h"

namespace pamsim {

std::vector<std::string> split_key(const std::string& key) {
  std::vector<std::string> parts;
  std::string part;
  std::istringstream in(key);
  while (std::getline(in, part, '.')) parts.push_back(part);
  return parts;
}

ConfigReader::ConfigReader(const std::string& path) : name_(path) { doc_ = parse_toml_file(path); }

ConfigReader::ConfigReader(const std::string& text, const std::string& name) : name_(name) {
  doc_ = parse_toml_text(text, name);
}

void ConfigReader::apply_overrides(const std::vector<std::string>& assignments) {
  for (const std::string& a : assignments) apply_override(a);
}

void ConfigReader::apply_override(const std::string& assignment) {
  const auto eq = assignment.find('=');
  if (eq == std::string::npos || eq == 0) {
    throw InputError(name_ + ": --set " + assignment + ": expected key=value");
  }
  const std::string key = assignment.substr(0, eq);
  const std::string value = assignment.substr(eq + 1);
  const auto parts = split_key(key);
  for (const auto& p : parts) {
    if (p.empty())
      throw InputError(name_ + ": --set " + assignment + ": malformed key '" + key + "'");
  }

  // parse the value as TOML; a bare word is taken as a string
  toml::table parsed;
  try {
    parsed = toml::parse("v = " + value);
  } catch (const toml::parse_error&) {
    parsed.insert_or_assign("v", value);
  }

  // walk (and create) the tables down to the key
  toml::table* t = &doc_;
  for (size_t i = 0; i + 1 < parts.size(); ++i) {
    toml::node* n = t->get(parts[i]);
    if (!n) {
      t->insert_or_assign(parts[i], toml::table{});
      n = t->get(parts[i]);
    }
    if (!n->is_table()) {
      throw InputError(name_ + ": --set " + assignment + ": '" + parts[i] + "' is not a table");
    }
    t = n->as_table();
  }
  t->insert_or_assign(parts.back(), *parsed.get("v"));
  overridden_.insert(key);
}

void ConfigReader::nest_value(const std::string& key, const std::string& field) {
  const auto parts = split_key(key);
  toml::table* t = &doc_;
  for (std::size_t i = 0; i + 1 < parts.size(); ++i) {
    toml::node* n = t->get(parts[i]);
    if (!n || !n->is_table()) return;
    t = n->as_table();
  }
  toml::node* value = t->get(parts.back());
  if (!value || value->is_table()) return;
  toml::table nested;
  nested.insert_or_assign(field, *value);
  t->insert_or_assign(parts.back(), std::move(nested));
  if (overridden_.count(key)) overridden_.insert(key + "." + field);
}

const toml::node* ConfigReader::find(const std::string& key) const {
  const toml::node* n = &doc_;
  for (const auto& part : split_key(key)) {
    const toml::table* t = n->as_table();
    if (!t) return nullptr;
    n = t->get(part);
    if (!n) return nullptr;
  }
  return n;
}

bool ConfigReader::has(const std::string& key) const {
  asked_.insert(key);
  return find(key) != nullptr;
}

std::string ConfigReader::where(const std::string& key) const {
  return overridden_.count(key) ? name_ + ": --set " + key : name_ + ": " + key;
}

std::string ConfigReader::described(const std::string& key, double value) const {
  const char* origin = overridden(key) ? "--set" : defaults_.count(key) ? "default" : "file";
  return key + " = " + format_value(value) + " (" + origin + ")";
}

void ConfigReader::fail(const std::string& key, const std::string& problem) const {
  throw InputError(where(key) + " " + problem, {name_, key, problem});
}

double ConfigReader::get_double(const std::string& key, double fallback) {
  read_.insert(key);
  const toml::node* n = find(key);
  if (!n) {
    defaults_[key] = format_number(fallback);
    return fallback;
  }
  std::optional<double> v = n->value<double>();
  if (!v || n->is_boolean()) fail(key, "must be a number");
  check(std::isfinite(*v), key, "must be finite, got " + format_value(*v));
  return *v;
}

double ConfigReader::require_double(const std::string& key) {
  if (!has(key)) fail(key, "is required");
  return get_double(key, 0.0);
}

std::int64_t ConfigReader::get_int(const std::string& key, std::int64_t fallback) {
  read_.insert(key);
  const toml::node* n = find(key);
  if (!n) {
    defaults_[key] = std::to_string(fallback);
    return fallback;
  }
  if (!n->is_integer()) fail(key, "must be an integer");
  return *n->value<std::int64_t>();
}

bool ConfigReader::get_bool(const std::string& key, bool fallback) {
  read_.insert(key);
  const toml::node* n = find(key);
  if (!n) {
    defaults_[key] = fallback ? "true" : "false";
    return fallback;
  }
  if (!n->is_boolean()) fail(key, "must be true or false");
  return *n->value<bool>();
}

std::string ConfigReader::get_string(const std::string& key, const std::string& fallback) {
  read_.insert(key);
  const toml::node* n = find(key);
  if (!n) {
    if (!fallback.empty()) defaults_[key] = toml_value_text(toml::value<std::string>(fallback));
    return fallback;
  }
  if (!n->is_string()) fail(key, "must be a string");
  return *n->value<std::string>();
}

std::string ConfigReader::require_string(const std::string& key) {
  if (!has(key)) fail(key, "is required");
  return get_string(key, "");
}

std::string ConfigReader::get_input_path(const std::string& key, const std::string& fallback) {
  const std::string path = get_path(key, fallback);
  if (path.empty()) return path;
  try {
    require_input_file(path);
  } catch (const InputError& e) {
    throw InputError(where(key) + ": " + e.what(), {name_, key, e.what()});
  }
  return path;
}

std::string ConfigReader::get_path(const std::string& key, const std::string& fallback) {
  return path_beside(name_, get_string(key, fallback));
}

std::string ConfigReader::require_path(const std::string& key, const std::string& what) {
  const std::string path = get_path(key, "");
  check(!path.empty(), key, "is required (" + what + ")");
  return path;
}

std::vector<std::string> ConfigReader::get_string_list(const std::string& key,
                                                       const std::vector<std::string>& fallback) {
  read_.insert(key);
  const toml::node* n = find(key);
  if (!n) {
    if (!fallback.empty()) {
      toml::array list;
      for (const auto& item : fallback) list.push_back(item);
      defaults_[key] = toml_value_text(list);
    }
    return fallback;
  }
  const toml::array* a = n->as_array();
  if (!a) fail(key, "must be a list of strings");
  std::vector<std::string> out;
  for (const toml::node& item : *a) {
    if (!item.is_string()) fail(key, "must be a list of strings");
    out.push_back(*item.value<std::string>());
  }
  return out;
}

std::vector<double> ConfigReader::get_double_list(const std::string& key,
                                                  const std::vector<double>& fallback) {
  read_.insert(key);
  const toml::node* n = find(key);
  if (!n) {
    if (!fallback.empty()) {
      toml::array list;
      for (const double item : fallback) list.push_back(item);
      defaults_[key] = toml_value_text(list);
    }
    return fallback;
  }
  const toml::array* a = n->as_array();
  if (!a) fail(key, "must be a list of numbers");
  std::vector<double> out;
  for (const toml::node& item : *a) {
    const std::optional<double> v = item.value<double>();
    if (!v || item.is_boolean()) fail(key, "must be a list of numbers");
    check(std::isfinite(*v), key, "must hold finite numbers, got " + format_value(*v));
    out.push_back(*v);
  }
  return out;
}

std::vector<std::string> ConfigReader::child_keys(const std::string& table) const {
  const toml::node* n = table.empty() ? &doc_ : find(table);
  std::vector<std::string> keys;
  if (!n || !n->is_table()) return keys;
  for (const auto& [k, v] : *n->as_table()) keys.emplace_back(k.str());
  return keys;
}

std::vector<std::string> ConfigReader::leaf_keys() const {
  std::vector<std::string> leaves;
  collect_leaves(doc_, "", &leaves);
  return leaves;
}

bool ConfigReader::is_table(const std::string& key) const {
  asked_.insert(key);
  const toml::node* n = find(key);
  return n && n->is_table();
}

bool ConfigReader::overridden(const std::string& key) const {
  for (const std::string& o : overridden_) {
    if (o == key || o.rfind(key + ".", 0) == 0) return true;
  }
  return false;
}

const toml::node* ConfigReader::raw(const std::string& key) {
  const toml::node* n = find(key);
  if (n && n->is_table()) {
    std::vector<std::string> leaves;
    collect_leaves(*n->as_table(), key + ".", &leaves);
    read_.insert(leaves.begin(), leaves.end());
  }
  read_.insert(key);
  return n;
}

void ConfigReader::collect_leaves(const toml::table& t, const std::string& prefix,
                                  std::vector<std::string>* out) const {
  for (const auto& [k, v] : t) {
    const std::string key = prefix + std::string(k.str());
    if (v.is_table()) {
      collect_leaves(*v.as_table(), key + ".", out);
    } else {
      out->push_back(key);
    }
  }
}

void ConfigReader::reject_unknown() const {
  std::vector<std::string> leaves;
  collect_leaves(doc_, "", &leaves);
  for (const auto& key : leaves) {
    if (read_.count(key)) continue;
    const std::string nearest = nearest_name(key, asked_keys());
    fail(key, "is not a known key" + (nearest.empty() ? "" : "; did you mean " + nearest + "?"));
  }
}

std::vector<std::string> ConfigReader::asked_keys() const {
  std::set<std::string> all = read_;
  all.insert(asked_.begin(), asked_.end());
  return {all.begin(), all.end()};
}

void TableEntry::allow(const std::vector<EntryKey>& keys) const {
  for (const auto& [k, v] : table) {
    const std::string key(k.str());
    const std::string problem = entry_value_problem(keys, key, v);
    if (!problem.empty()) in.fail(where + key, problem);
  }
}

std::string TableEntry::text(const char* key, bool required, const std::string& fallback) const {
  const toml::node* n = table.get(key);
  if (!n) {
    if (required) in.fail(where + key, "is required");
    return fallback;
  }
  if (!n->is_string()) in.fail(where + key, "must be a string");
  return *n->value<std::string>();
}

std::optional<double> TableEntry::number(const char* key) const {
  const toml::node* n = table.get(key);
  if (!n) return std::nullopt;
  // an integer beyond 2^53 has no exact double: toml++ gives none
  const bool numeric = n->is_integer() || n->is_floating_point();
  const std::optional<double> value = numeric ? n->value<double>() : std::nullopt;
  if (!value) in.fail(where + key, "must be a number");
  const double v = *value;
  in.check(std::isfinite(v), where + key, "must be finite, got " + format_value(v));
  return v;
}

std::vector<std::string> TableEntry::texts(const char* key, bool required) const {
  const toml::node* n = table.get(key);
  if (!n) {
    if (required) in.fail(where + key, "is required");
    return {};
  }
  const toml::array* list = n->as_array();
  std::vector<std::string> out;
  if (list) {
    for (const toml::node& item : *list) {
      if (!item.is_string()) break;
      out.push_back(*item.value<std::string>());
    }
  }
  if (!list || out.size() != list->size()) in.fail(where + key, "must be a list of strings");
  return out;
}

TableArray::TableArray(ConfigReader& in, const std::string& name) : in_(in), name_(name) {
  const toml::node* n = in.raw(name);
  if (!n) return;
  array_ = n->as_array();
  if (!array_) in.fail(name, "must be an array of tables ([[" + name + "]])");
}

TableEntry TableArray::operator[](std::size_t i) const {
  const std::string at = name_ + "[" + std::to_string(i) + "]";
  const toml::table* t = (*array_)[i].as_table();
  if (!t) in_.fail(at, "must be a table");
  return TableEntry{in_, *t, at + "."};
}

std::vector<TableEntry> TableArray::entries(const std::vector<EntryKey>& keys) const {
  std::vector<TableEntry> out;
  for (std::size_t i = 0; i < size(); ++i) {
    out.push_back((*this)[i]);
    out.back().allow(keys);
  }
  return out;
}

}  // namespace pamsim
