// entry_keys.cc: see entry_keys.h.
#include "base/entry_keys.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <optional>

#include "base/format.h"
#include "base/key_table_text.h"

namespace pamsim {
namespace {

using key_table_text::names_text;

// " mm" for a unit of its own, "" for none or another key's ("(the key's)")
std::string unit_suffix(const EntryKey& k) {
  return k.unit.empty() || k.unit.front() == '(' ? "" : " " + k.unit;
}

std::string number_problem(const EntryKey& k, const toml::node& value) {
  // an integer beyond 2^53 has no exact double: toml++ gives none
  const bool numeric = value.is_integer() || value.is_floating_point();
  const std::optional<double> v = numeric ? value.value<double>() : std::nullopt;
  if (!v) return "must be a number";
  if (!std::isfinite(*v)) return "must be finite, got " + format_value(*v);
  if (!k.range.contains(*v)) {
    return "must be in " + k.range.text() + unit_suffix(k) + ", got " + format_value(*v);
  }
  return "";
}

std::string integer_problem(const EntryKey& k, const toml::node& value) {
  if (!value.is_integer()) return "must be an integer";
  const std::int64_t v = *value.value<std::int64_t>();
  if (!k.range.contains(static_cast<double>(v))) {
    return "must be in " + k.range.text() + ", got " + std::to_string(v);
  }
  return "";
}

std::string texts_problem(const toml::node& value) {
  const toml::array* list = value.as_array();
  const bool strings = list && std::all_of(list->begin(), list->end(),
                                           [](const toml::node& n) { return n.is_string(); });
  return strings ? "" : "must be a list of strings";
}

std::string choice_problem(const EntryKey& k, const toml::node& value) {
  const std::optional<std::string> name = value.value<std::string>();
  if (!value.is_string() || !name) return "must be a string, allowed " + names_text(k.choices);
  if (std::find(k.choices.begin(), k.choices.end(), *name) != k.choices.end()) return "";
  return "is \"" + *name + "\", allowed " + names_text(k.choices);
}

// what the type, range or names allow, as the reference writes it; "" for kAny, and for a
// string, a list or a table whose `allowed` says what it holds
std::string typed_allowed(const EntryKey& k) {
  switch (k.type) {
    case EntryType::kNumber:
      return std::isinf(k.range.lo) && std::isinf(k.range.hi) ? "a number" : k.range.text();
    case EntryType::kInteger:
      return "an integer in " + k.range.text();
    case EntryType::kBool:
      return "true | false";
    case EntryType::kChoice:
      return names_text(k.choices);
    case EntryType::kTexts:
      return k.allowed.empty() ? "a list of strings" : "";
    case EntryType::kTable:
      return k.allowed.empty() ? "a table" : "";
    case EntryType::kText:
      return k.allowed.empty() ? "a string" : "";
    case EntryType::kAny:
      break;
  }
  return "";
}

}  // namespace

bool is_entry_key(const std::vector<EntryKey>& keys, const std::string& key) {
  return std::any_of(keys.begin(), keys.end(), [&](const EntryKey& k) { return key == k.name; });
}

std::string entry_value_problem(const std::vector<EntryKey>& keys, const std::string& key,
                                const toml::node& value) {
  const auto row =
      std::find_if(keys.begin(), keys.end(), [&](const EntryKey& k) { return key == k.name; });
  if (row == keys.end()) {
    std::string names;
    for (const EntryKey& k : keys) names += (names.empty() ? "" : ", ") + k.name;
    return "is not a key of this table (" + names + ")";
  }
  switch (row->type) {
    case EntryType::kNumber:
      return number_problem(*row, value);
    case EntryType::kInteger:
      return integer_problem(*row, value);
    case EntryType::kText:
      return value.is_string() ? "" : "must be a string";
    case EntryType::kTexts:
      return texts_problem(value);
    case EntryType::kBool:
      return value.is_boolean() ? "" : "must be true or false";
    case EntryType::kChoice:
      return choice_problem(*row, value);
    case EntryType::kTable:
      return value.is_table() ? "" : "must be " + (row->allowed.empty() ? "a table" : row->allowed);
    case EntryType::kAny:
      break;
  }
  return "";
}

std::vector<KeyDoc> entry_key_docs(const std::string& array, const std::vector<EntryKey>& keys) {
  std::vector<KeyDoc> docs;
  for (const EntryKey& k : keys) {
    const std::string typed = typed_allowed(k);
    const std::string allowed = typed.empty()       ? k.allowed
                                : k.allowed.empty() ? typed
                                                    : typed + "; " + k.allowed;
    docs.push_back({array + "[]." + k.name, k.unit, k.fallback, allowed, k.meaning});
  }
  return docs;
}

}  // namespace pamsim
