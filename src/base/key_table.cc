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
#include "base/key_table_text.h"

namespace pamsim {
namespace {

using namespace key_table_text;

// The field a number row fills, as a pointer to its SI value (nullptr: an unset optional)
const double* field(const NumberRow& row) {
  if (row.optional_target == nullptr) return row.target;
  return row.optional_target->has_value() ? &**row.optional_target : nullptr;
}

void read_number_row(ConfigReader& in, const std::string& key, const NumberRow& row) {
  if (!in.has(key)) {
    in.check(!row.required, key, "is required");
    if (const double* si = field(row)) in.get_double(key, from_si(row, *si));  // the default
    return;
  }
  const double v = in.get_double(key, 0.0);
  in.check(row.range.contains(v), key,
           "must be in " + row.range.text() + (row.unit.empty() ? "" : " " + row.unit) + ", got " +
               format_value(v));
  in.check(std::isfinite(row.si(v)), key,
           "is " + format_value(v) + ", beyond what a double holds in SI units");
  if (row.optional_target != nullptr) {
    *row.optional_target = row.si(v);
  } else {
    *row.target = row.si(v);
  }
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
  for (const TextRow& row : table.texts) keys.push_back(row_key(table, row.name));
  for (const ListRow& row : table.lists) keys.push_back(row_key(table, row.name));
  for (const NameListRow& row : table.name_lists) keys.push_back(row_key(table, row.name));
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

void read_key_rows(ConfigReader& in, const KeyTable& table) {
  const auto key = [&](const std::string& name) { return row_key(table, name); };
  for (const ChoiceRow& row : table.choices) {
    const std::string k = key(row.name);
    const std::string value = in.get_string(k, row.get());
    if (!in.has(k)) continue;
    in.check(allows(row, value), k, "is \"" + value + "\", allowed " + choices_text(row));
    row.set(value);
  }
  for (const BoolRow& row : table.bools) *row.target = in.get_bool(key(row.name), *row.target);
  for (const IntRow& row : table.ints) {
    const std::string k = key(row.name);
    const std::int64_t v = in.get_int(k, row.get());
    in.check(v >= row.lo && v <= row.hi, k,
             "must be in " + int_range(row) + ", got " + std::to_string(v));
    row.set(v);
  }
  for (const NumberRow& row : table.numbers) read_number_row(in, key(row.name), row);
  for (const TextRow& row : table.texts) {
    const std::string k = key(row.name);
    *row.target =
        row.input_file ? in.get_input_path(k, *row.target) : in.get_string(k, *row.target);
    in.check(!row.required || !row.target->empty(), k, "is required");
  }
  for (const ListRow& row : table.lists) {
    const std::string k = key(row.name);
    std::vector<double> shown;  // the default in the file's unit
    for (double si : *row.target) shown.push_back(si / row.to_si);
    const std::vector<double> values = in.get_double_list(k, shown);
    if (!in.has(k)) continue;
    const std::string count = list_count_problem(row, values.size());
    in.check(count.empty(), k, count);
    row.target->clear();
    for (std::size_t i = 0; i < values.size(); ++i) {
      if (!row.range.contains(values[i])) {  // "<file>: <key>[i] must be in ..., got v"
        const std::string problem = "[" + std::to_string(i) + "] " + out_of_range(row, values[i]);
        throw InputError(in.where(k) + problem, {in.name(), k, problem});
      }
      row.target->push_back(values[i] * row.to_si);
    }
  }
  for (const NameListRow& row : table.name_lists) {
    const std::string k = key(row.name);
    const std::vector<std::string> names = in.get_string_list(k, *row.target);
    if (!in.has(k)) continue;
    const std::string problem = name_list_problem(row, names);
    in.check(problem.empty(), k, problem);
    *row.target = names;
  }
}

namespace {

// `table` with only the rows whose names `keep` accepts
KeyTable rows_where(KeyTable table, const std::function<bool(const std::string&)>& keep) {
  const auto filter = [&](auto* rows) {
    rows->erase(std::remove_if(rows->begin(), rows->end(),
                               [&](const auto& row) { return !keep(row.name); }),
                rows->end());
  };
  filter(&table.numbers);
  filter(&table.choices);
  filter(&table.bools);
  filter(&table.ints);
  filter(&table.texts);
  filter(&table.lists);
  filter(&table.name_lists);
  return table;
}

}  // namespace

KeyTable rows_given(const ConfigReader& in, KeyTable table) {
  const KeyTable names{table.name, {}, {}};
  return rows_where(std::move(table),
                    [&](const std::string& row) { return in.has(row_key(names, row)); });
}

KeyTable rows_named(KeyTable table, const std::vector<std::string>& names) {
  return rows_where(std::move(table), [&](const std::string& row) {
    return std::find(names.begin(), names.end(), row) != names.end();
  });
}

KeyTable as_shorthand(KeyTable table, const std::string& table_name, const std::string& row_name,
                      const std::string& long_form) {
  assert(table.numbers.size() + table.texts.size() == 1 && "as_shorthand: one row");
  table.name = table_name;
  const auto rename = [&](auto* rows) {
    for (auto& row : *rows) {
      row.name = row_name;
      row.doc = "shorthand of " + long_form + ": " + row.doc;
      row.fallback_doc = "(none)";
      row.required = false;
    }
  };
  rename(&table.numbers);
  rename(&table.texts);
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
  for (const ListRow& row : table.lists) {
    for (double si : *row.target) {
      require_value(row.range.contains(si / row.to_si), row_key(table, row.name), list_allowed(row),
                    si / row.to_si);
    }
  }
  for (const ChoiceRow& row : table.choices) {
    const std::string key = row_key(table, row.name);
    const std::string value = row.get();
    if (!allows(row, value)) {
      const std::string problem = "must be " + choices_text(row) + ", got \"" + value + "\"";
      throw InputError(key + " " + problem, {"", key, problem});
    }
  }
  for (const NameListRow& row : table.name_lists) {
    const std::string key = row_key(table, row.name);
    const std::string problem = name_list_problem(row, *row.target);
    if (!problem.empty()) throw InputError(key + " " + problem, {"", key, problem});
  }
}

double from_si(const NumberRow& row, double si) {
  // the shortest of 15, 16 or 17 significant digits that the reader takes back to `si`
  for (int digits = 15; digits <= 16; ++digits) {
    char buf[40];
    std::snprintf(buf, sizeof(buf), "%.*g", digits, si * row.divisor / row.to_si);
    const double v = std::strtod(buf, nullptr);
    if (row.si(v) == si) return v;
  }
  return si * row.divisor / row.to_si;
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
    const std::size_t first = docs.size();
    for (const ChoiceRow& row : t.choices) {
      docs.push_back(
          {row_key(t, row.name), "", "\"" + row.get() + "\"", choices_text(row), row.doc});
    }
    for (const BoolRow& row : t.bools) {
      docs.push_back(
          {row_key(t, row.name), "", *row.target ? "true" : "false", "true | false", row.doc});
    }
    for (const IntRow& row : t.ints) {
      docs.push_back({row_key(t, row.name), "",
                      row.fallback_doc.empty() ? std::to_string(row.get()) : row.fallback_doc,
                      int_range(row), row.doc});
      docs.back().trial_only = row.trial_only;
    }
    for (const NumberRow& row : t.numbers) {
      const double* si = field(row);
      std::string fallback = si ? format_number(from_si(row, *si)) : "(unset)";
      if (row.required) fallback = "(required)";
      if (!row.fallback_doc.empty()) fallback = row.fallback_doc;
      docs.push_back({row_key(t, row.name), row.unit, fallback, row.range.text(), row.doc});
      docs.back().trial_only = row.trial_only;
    }
    for (const TextRow& row : t.texts) {
      std::string fallback = row.required                            ? "(required)"
                             : !row.fallback_doc.empty()             ? row.fallback_doc
                             : row.input_file && row.target->empty() ? "(none)"
                                                                     : "\"" + *row.target + "\"";
      docs.push_back(
          {row_key(t, row.name), "", fallback,
           row.input_file ? "a path to a file, relative to the file that gives it" : "a string",
           row.doc});
      docs.back().trial_only = row.trial_only;
    }
    for (const ListRow& row : t.lists) {
      std::string values;
      for (double si : *row.target) {
        values += (values.empty() ? "" : ", ") + format_number(si / row.to_si);
      }
      docs.push_back({row_key(t, row.name), row.unit,
                      row.fallback_doc.empty() ? "[" + values + "]" : row.fallback_doc,
                      list_allowed(row), row.doc});
    }
    for (const NameListRow& row : t.name_lists) {
      std::string names;
      for (const std::string& n : *row.target) names += (names.empty() ? "\"" : ", \"") + n + "\"";
      docs.push_back({row_key(t, row.name), "",
                      row.fallback_doc.empty() ? "[" + names + "]" : row.fallback_doc,
                      name_list_allowed(row), row.doc});
    }
    for (std::size_t k = first; k < docs.size(); ++k) {
      docs[k].trial_only = docs[k].trial_only || t.trial_only;
    }
  }
  return docs;
}

}  // namespace pamsim
