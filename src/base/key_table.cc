// key_table.cc: see key_table.h.
#include "base/key_table.h"

#include <cmath>
#include <sstream>

#include "base/format.h"
#include "base/input_error.h"

namespace pamsim {
namespace {

// "a | b": the names a choice allows
std::string choices_text(const ChoiceRow& row) {
  std::string allowed;
  for (const std::string& a : row.allowed) allowed += (allowed.empty() ? "" : " | ") + a;
  return allowed;
}

void read_number(const std::string& path, const std::string& key, const NumberRow& row,
                 const toml::node& node) {
  if (!node.is_number()) {
    std::ostringstream type;
    type << node.type();
    throw file_key_error(path, key, "must be a number, got a " + type.str());
  }
  const double v = node.value<double>().value();
  if (!row.range.contains(v)) {
    throw file_key_error(path, key,
                         "value " + format_value(v) + " out of range, allowed " + row.range.text());
  }
  if (row.optional_target != nullptr) {
    *row.optional_target = v * row.to_si;
  } else {
    *row.target = v * row.to_si;
  }
}

void read_choice(const std::string& path, const std::string& key, const ChoiceRow& row,
                 const toml::node& node) {
  const auto value = node.value<std::string>();
  if (!value) throw file_key_error(path, key, "must be a string, allowed " + choices_text(row));
  for (const std::string& a : row.allowed) {
    if (*value == a) return row.set(*value);
  }
  throw file_key_error(path, key,
                       "unknown value \"" + *value + "\", allowed " + choices_text(row));
}

// One key of a table: read by its row, or refused with the keys the table has.
void read_key(const std::string& path, const KeyTable& table, const std::string& name,
              const toml::node& node) {
  const std::string key = table.name + "." + name;
  for (const NumberRow& row : table.numbers) {
    if (row.name == name) return read_number(path, key, row, node);
  }
  for (const ChoiceRow& row : table.choices) {
    if (row.name == name) return read_choice(path, key, row, node);
  }
  std::string allowed;
  for (const NumberRow& row : table.numbers) allowed += (allowed.empty() ? "" : ", ") + row.name;
  for (const ChoiceRow& row : table.choices) allowed += (allowed.empty() ? "" : ", ") + row.name;
  throw file_key_error(path, key, "unknown key (allowed: " + allowed + ")");
}

}  // namespace

bool KeyRange::contains(double v) const {
  return std::isfinite(v) && (lo_open ? v > lo : v >= lo) && (hi_open ? v < hi : v <= hi);
}

std::string KeyRange::text() const {
  const auto bound = [](double b) {
    return std::isinf(b) ? std::string(b < 0 ? "-inf" : "inf") : format_value(b);
  };
  return std::string(lo_open ? "(" : "[") + bound(lo) + ", " + bound(hi) + (hi_open ? ")" : "]");
}

void read_key_tables(const toml::table& doc, const std::string& path,
                     const std::vector<KeyTable>& tables) {
  for (const auto& [table_key, table_node] : doc) {
    const std::string name(table_key.str());
    const KeyTable* table = nullptr;
    std::string names;
    for (const KeyTable& t : tables) {
      if (t.name == name) table = &t;
      names += (names.empty() ? "" : ", ") + t.name;
    }
    if (table == nullptr) {
      throw file_key_error(path, name, "unknown table (allowed: " + names + ")");
    }
    const toml::table* entries = table_node.as_table();
    if (entries == nullptr) throw file_key_error(path, name, "must be a table");
    for (const auto& [key, node] : *entries) read_key(path, *table, std::string(key.str()), node);
  }
}

std::vector<KeyDoc> key_table_docs(const std::vector<KeyTable>& tables) {
  std::vector<KeyDoc> docs;
  for (const KeyTable& t : tables) {
    for (const NumberRow& row : t.numbers) {
      const bool unset = row.optional_target != nullptr && !row.optional_target->has_value();
      const double si = row.optional_target ? row.optional_target->value_or(0.0) : *row.target;
      docs.push_back({t.name + "." + row.name, row.unit,
                      unset ? "(unset)" : format_number(si / row.to_si), row.range.text(),
                      row.doc});
    }
    for (const ChoiceRow& row : t.choices) {
      docs.push_back({t.name + "." + row.name, "", "\"" + row.get() + "\"", choices_text(row),
                      row.doc});
    }
  }
  return docs;
}

}  // namespace pamsim
