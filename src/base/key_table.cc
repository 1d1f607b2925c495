// key_table.cc: see key_table.h.
#include "base/key_table.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <sstream>

#include "base/config_reader.h"
#include "base/format.h"
#include "base/input_error.h"

namespace pamsim {
namespace {

// "\"a\" | \"b\"": the names a choice allows, as TOML strings
std::string choices_text(const ChoiceRow& row) {
  std::string allowed;
  for (const std::string& a : row.allowed) {
    allowed += (allowed.empty() ? "\"" : " | \"") + a + "\"";
  }
  return allowed;
}

// "[0, 64]"
std::string int_range(const IntRow& row) {
  return "[" + std::to_string(row.lo) + ", " + std::to_string(row.hi) + "]";
}

bool allows(const ChoiceRow& row, const std::string& value) {
  for (const std::string& a : row.allowed) {
    if (value == a) return true;
  }
  return false;
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
  if (allows(row, *value)) return row.set(*value);
  throw file_key_error(path, key,
                       "unknown value \"" + *value + "\", allowed " + choices_text(row));
}

// The field a number row fills, as a pointer to its SI value (nullptr: an unset optional)
const double* field(const NumberRow& row) {
  if (row.optional_target == nullptr) return row.target;
  return row.optional_target->has_value() ? &**row.optional_target : nullptr;
}

void read_number_row(ConfigReader& in, const std::string& key, const NumberRow& row) {
  if (!in.has(key)) {
    in.check(!row.required, key, "is required");
    if (const double* si = field(row)) in.get_double(key, from_si(row, *si));   // the default
    return;
  }
  const double v = in.get_double(key, 0.0);
  in.check(row.range.contains(v), key,
           "must be in " + row.range.text() + ", got " + format_value(v));
  in.check(std::isfinite(v * row.to_si), key,
           "is " + format_value(v) + ", beyond what a double holds in SI units");
  if (row.optional_target != nullptr) {
    *row.optional_target = v * row.to_si;
  } else {
    *row.target = v * row.to_si;
  }
}

// One key of a table: read by its row, or refused with the keys the table has.
void read_key(const std::string& path, const KeyTable& table, const std::string& name,
              const toml::node& node) {
  const std::string key = row_key(table, name);
  for (const NumberRow& row : table.numbers) {
    if (row.name == name) return read_number(path, key, row, node);
  }
  for (const ChoiceRow& row : table.choices) {
    if (row.name == name) return read_choice(path, key, row, node);
  }
  for (const IntRow& row : table.ints) {
    if (row.name != name) continue;
    const auto v = node.value<std::int64_t>();
    if (!node.is_integer() || !v) throw file_key_error(path, key, "must be an integer");
    if (*v < row.lo || *v > row.hi) {
      throw file_key_error(path, key, "value " + std::to_string(*v) +
                                          " out of range, allowed " + int_range(row));
    }
    row.set(*v);
    return;
  }
  for (const BoolRow& row : table.bools) {
    if (row.name != name) continue;
    if (!node.is_boolean()) throw file_key_error(path, key, "must be true or false");
    *row.target = *node.value<bool>();
    return;
  }
  std::string allowed;
  for (const NumberRow& row : table.numbers) allowed += (allowed.empty() ? "" : ", ") + row.name;
  for (const ChoiceRow& row : table.choices) allowed += (allowed.empty() ? "" : ", ") + row.name;
  for (const BoolRow& row : table.bools) allowed += (allowed.empty() ? "" : ", ") + row.name;
  for (const IntRow& row : table.ints) allowed += (allowed.empty() ? "" : ", ") + row.name;
  throw file_key_error(path, key, "unknown key (allowed: " + allowed + ")");
}

}  // namespace

std::string row_key(const KeyTable& table, const std::string& name) {
  return table.name.empty() ? name : table.name + "." + name;
}

std::vector<std::string> key_names(const KeyTable& table) {
  std::vector<std::string> keys;
  for (const ChoiceRow& row : table.choices) keys.push_back(row_key(table, row.name));
  for (const BoolRow& row : table.bools) keys.push_back(row_key(table, row.name));
  for (const IntRow& row : table.ints) keys.push_back(row_key(table, row.name));
  for (const NumberRow& row : table.numbers) keys.push_back(row_key(table, row.name));
  return keys;
}

bool KeyRange::contains(double v) const {
  return std::isfinite(v) && (lo_open ? v > lo : v >= lo) && (hi_open ? v < hi : v <= hi);
}

std::string KeyRange::text() const {
  const auto bound = [](double b) {
    return std::isinf(b) ? std::string(b < 0 ? "-inf" : "inf") : format_value(b);
  };
  // an infinite end is never in (contains() takes finite values only)
  return std::string(lo_open || std::isinf(lo) ? "(" : "[") + bound(lo) + ", " + bound(hi) +
         (hi_open || std::isinf(hi) ? ")" : "]");
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

void read_key_rows(ConfigReader& in, const KeyTable& table) {
  const auto key = [&](const std::string& name) { return row_key(table, name); };
  for (const ChoiceRow& row : table.choices) {
    const std::string k = key(row.name);
    const std::string value = in.get_string(k, row.get());
    if (!in.has(k)) continue;
    in.check(allows(row, value), k,
             "is \"" + value + "\", allowed " + choices_text(row));
    row.set(value);
  }
  for (const BoolRow& row : table.bools) *row.target = in.get_bool(key(row.name), *row.target);
  for (const IntRow& row : table.ints) {
    const std::string k = key(row.name);
    const std::int64_t v = in.get_int(k, row.get());
    in.check(v >= row.lo && v <= row.hi, k, "must be in " + int_range(row) + ", got " +
                                                std::to_string(v));
    row.set(v);
  }
  for (const NumberRow& row : table.numbers) read_number_row(in, key(row.name), row);
}

KeyTable rows_given(const ConfigReader& in, KeyTable table) {
  const auto drop_absent = [&](auto* rows) {
    rows->erase(std::remove_if(rows->begin(), rows->end(),
                               [&](const auto& row) { return !in.has(row_key(table, row.name)); }),
                rows->end());
  };
  drop_absent(&table.numbers);
  drop_absent(&table.choices);
  drop_absent(&table.bools);
  drop_absent(&table.ints);
  return table;
}

void check_key_rows(const KeyTable& table) {
  for (const NumberRow& row : table.numbers) {
    const double* si = field(row);
    if (si == nullptr) continue;
    const double v = from_si(row, *si);
    require_value(row.range.contains(v), row_key(table, row.name), "in " + row.range.text(), v);
  }
  for (const IntRow& row : table.ints) {
    const std::int64_t v = row.get();
    require_value(v >= row.lo && v <= row.hi, row_key(table, row.name), "in " + int_range(row),
                  static_cast<double>(v));
  }
  for (const ChoiceRow& row : table.choices) {
    const std::string key = row_key(table, row.name);
    const std::string value = row.get();
    if (!allows(row, value)) {
      const std::string problem = "must be " + choices_text(row) + ", got \"" + value + "\"";
      throw InputError(key + " " + problem, {"", key, problem});
    }
  }
}

double from_si(const NumberRow& row, double si) {
  // the shortest of 15, 16 or 17 significant digits that the reader takes back to `si`
  for (int digits = 15; digits <= 16; ++digits) {
    char buf[40];
    std::snprintf(buf, sizeof(buf), "%.*g", digits, si / row.to_si);
    const double v = std::strtod(buf, nullptr);
    if (v * row.to_si == si) return v;
  }
  return si / row.to_si;
}

double file_value(const KeyTable& table, const std::string& name) {
  for (const NumberRow& row : table.numbers) {
    if (row.name != name) continue;
    const double* si = field(row);
    return si ? from_si(row, *si) : std::numeric_limits<double>::quiet_NaN();
  }
  assert(false && "file_value: no such row");
  return std::numeric_limits<double>::quiet_NaN();
}

std::vector<KeyDoc> key_table_docs(const std::vector<KeyTable>& tables) {
  std::vector<KeyDoc> docs;
  for (const KeyTable& t : tables) {
    for (const ChoiceRow& row : t.choices) {
      docs.push_back({row_key(t, row.name), "", "\"" + row.get() + "\"", choices_text(row),
                      row.doc});
    }
    for (const BoolRow& row : t.bools) {
      docs.push_back({row_key(t, row.name), "", *row.target ? "true" : "false",
                      "true | false", row.doc});
    }
    for (const IntRow& row : t.ints) {
      docs.push_back({row_key(t, row.name), "", std::to_string(row.get()), int_range(row),
                      row.doc});
    }
    for (const NumberRow& row : t.numbers) {
      const double* si = field(row);
      std::string fallback = si ? format_number(from_si(row, *si)) : "(unset)";
      if (row.required) fallback = "(required)";
      if (!row.fallback_doc.empty()) fallback = row.fallback_doc;
      docs.push_back({row_key(t, row.name), row.unit, fallback, row.range.text(), row.doc});
    }
  }
  return docs;
}

}  // namespace pamsim
