// key_table_file.cc: read_key_tables (key_table.h): a parameter file read by its tables,
// every key by its row, nested tables by their dotted names, then the required rows.
#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>
#include <vector>

#include "base/format.h"
#include "base/input_error.h"
#include "base/key_table.h"
#include "base/key_table_text.h"
#include "base/toml_file.h"

namespace pamsim {
namespace {

// `value`, a path given by the file at `path`, resolved against that file's folder; refused
// unless it is a file to read (require_input_file)
std::string input_file_beside(const std::string& path, const std::string& key,
                              const std::string& value) {
  const std::string resolved = path_beside(path, value);
  try {
    require_input_file(resolved);
  } catch (const InputError& e) {
    throw file_key_error(path, key, e.what());
  }
  return resolved;
}

using namespace key_table_text;

void read_number(const std::string& path, const std::string& key, const NumberRow& row,
                 const toml::node& node) {
  if (!node.is_number()) {
    std::ostringstream type;
    type << node.type();
    throw file_key_error(path, key, "must be a number, got a " + type.str());
  }
  const double v = node.value<double>().value();
  if (!std::isfinite(v)) throw file_key_error(path, key, "must be finite, got " + format_value(v));
  if (!row.range.contains(v)) throw file_key_error(path, key, out_of_range(row, v));
  if (row.optional_target != nullptr) {
    *row.optional_target = row.si(v);
  } else {
    *row.target = row.si(v);
  }
}

void read_choice(const std::string& path, const std::string& key, const ChoiceRow& row,
                 const toml::node& node) {
  const auto value = node.value<std::string>();
  if (!value) throw file_key_error(path, key, "must be a string, allowed " + choices_text(row));
  if (allows(row, *value)) return row.set(*value);
  throw file_key_error(path, key, "unknown value \"" + *value + "\", allowed " + choices_text(row));
}

void read_list(const std::string& path, const std::string& key, const ListRow& row,
               const toml::node& node) {
  const toml::array* list = node.as_array();
  if (list == nullptr) throw file_key_error(path, key, "must be a list of numbers");
  const std::string count = list_count_problem(row, list->size());
  if (!count.empty()) throw file_key_error(path, key, count);
  std::vector<double> values;
  for (std::size_t i = 0; i < list->size(); ++i) {
    const toml::node& item = *list->get(i);
    const std::string at = "[" + std::to_string(i) + "]";
    if (!item.is_number()) throw file_key_error(path, key, at + " must be a number");
    const double v = item.value<double>().value();
    if (!row.range.contains(v)) throw file_key_error(path, key, at + " " + out_of_range(row, v));
    values.push_back(v * row.to_si);
  }
  *row.target = std::move(values);
}

void read_name_list(const std::string& path, const std::string& key, const NameListRow& row,
                    const toml::node& node) {
  const toml::array* list = node.as_array();
  if (list == nullptr) throw file_key_error(path, key, "must be " + name_list_allowed(row));
  std::vector<std::string> names;
  for (std::size_t i = 0; i < list->size(); ++i) {
    const toml::node& item = *list->get(i);
    if (!item.is_string())
      throw file_key_error(path, key, "[" + std::to_string(i) + "] must be a string");
    names.push_back(*item.value<std::string>());
  }
  const std::string problem = name_list_problem(row, names);
  if (!problem.empty()) throw file_key_error(path, key, problem);
  *row.target = std::move(names);
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
      throw file_key_error(
          path, key, "value " + std::to_string(*v) + " out of range, allowed " + int_range(row));
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
  for (const TextRow& row : table.texts) {
    if (row.name != name) continue;
    if (!node.is_string()) throw file_key_error(path, key, "must be a string");
    *row.target = *node.value<std::string>();
    if (row.input_file) *row.target = input_file_beside(path, key, *row.target);
    return;
  }
  for (const ListRow& row : table.lists) {
    if (row.name == name) return read_list(path, key, row, node);
  }
  for (const NameListRow& row : table.name_lists) {
    if (row.name == name) return read_name_list(path, key, row, node);
  }
  std::string allowed;
  const auto list = [&](const auto& rows) {
    for (const auto& row : rows) allowed += (allowed.empty() ? "" : ", ") + row.name;
  };
  list(table.numbers);
  list(table.choices);
  list(table.bools);
  list(table.ints);
  list(table.texts);
  list(table.lists);
  list(table.name_lists);
  throw file_key_error(path, key, "unknown key (allowed: " + allowed + ")");
}

const KeyTable* table_named(const std::vector<KeyTable>& tables, const std::string& name) {
  for (const KeyTable& t : tables) {
    if (t.name == name) return &t;
  }
  return nullptr;
}

// The entries of `table` (named `name`): a table in it is table "<name>.<key>", read in turn.
void read_entries(const std::string& path, const std::vector<KeyTable>& tables,
                  const std::string& name, const toml::table& entries,
                  std::vector<std::string>* given) {
  const KeyTable* table = table_named(tables, name);
  for (const auto& [k, node] : entries) {
    const std::string key(k.str());
    const std::string dotted = name.empty() ? key : name + "." + key;
    const toml::table* sub = node.as_table();
    if (table_named(tables, dotted) != nullptr) {
      if (sub == nullptr) throw file_key_error(path, dotted, "must be a table");
      given->push_back(dotted);
      read_entries(path, tables, dotted, *sub, given);
      continue;
    }
    if (table == nullptr || (sub != nullptr && name.empty())) {
      std::string names;  // the tables this level holds
      for (const KeyTable& t : tables) {
        const bool here = name.empty() ? !t.name.empty() && t.name.find('.') == std::string::npos
                                       : t.name.rfind(name + ".", 0) == 0;
        if (here) names += (names.empty() ? "" : ", ") + t.name;
      }
      throw file_key_error(path, dotted, "unknown table (allowed: " + names + ")");
    }
    read_key(path, *table, key, node);
    given->push_back(dotted);
  }
}

// A required row missing from a table the file has, or from a table it must have: one not
// optional whose parent it has (the top level, "a" for "a.b").
void check_required(const std::string& path, const std::vector<KeyTable>& tables,
                    const std::vector<std::string>& given) {
  const auto is_given = [&](const std::string& k) {
    return std::find(given.begin(), given.end(), k) != given.end();
  };
  for (const KeyTable& t : tables) {
    const std::size_t dot = t.name.rfind('.');
    const bool parent = dot == std::string::npos || is_given(t.name.substr(0, dot));
    if (!(t.name.empty() || is_given(t.name)) && (t.optional || !parent)) continue;
    const auto require = [&](const auto& rows) {
      for (const auto& row : rows) {
        const std::string key = row_key(t, row.name);
        if (row.required && !is_given(key)) throw file_key_error(path, key, "is required");
      }
    };
    require(t.numbers);
    require(t.texts);
  }
}

}  // namespace

std::vector<std::string> read_key_tables(const toml::table& doc, const std::string& path,
                                         const std::vector<KeyTable>& tables) {
  std::vector<std::string> given;
  read_entries(path, tables, "", doc, &given);
  check_required(path, tables, given);
  return given;
}

}  // namespace pamsim
