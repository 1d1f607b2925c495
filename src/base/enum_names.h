// enum_names.h: the names an enum is written as in files, logs and on the command line, kept
// in one table per enum and read both ways: name_of for output, parse_name for input, with
// one error form for every enum ("<context> must be \"a\", \"b\" or \"c\", got \"x\"").
//   constexpr EnumName<SweepDesign> kDesigns[] = {{SweepDesign::kGrid, "grid"}, ...};
//   name_of(kDesigns, SweepDesign::kGrid)           -> "grid"
//   parse_name(kDesigns, "sobol", "sweep.toml: design") throws InputError
#pragma once

#include <cstddef>
#include <string>
#include <utility>
#include <vector>

#include "base/input_error.h"
#include "base/key_table.h"

namespace pamsim {

template <typename Enum>
struct EnumName {
  Enum value;
  const char* name;
};

// "\"a\"", "\"a\" or \"b\"", "\"a\", \"b\" or \"c\"": the choices of a table, for messages.
template <typename Enum, std::size_t N>
std::string quoted_choices(const EnumName<Enum> (&names)[N]) {
  std::string out;
  for (std::size_t i = 0; i < N; ++i) {
    if (i > 0) out += (i + 1 == N) ? " or " : ", ";
    out += std::string("\"") + names[i].name + "\"";
  }
  return out;
}

// The name of `value`; "?" for a value the table lacks (a cast integer).
template <typename Enum, std::size_t N>
const char* name_of(const EnumName<Enum> (&names)[N], Enum value) {
  for (const EnumName<Enum>& n : names) {
    if (n.value == value) return n.name;
  }
  return "?";
}

// The value named `name`; InputError "<context> must be <choices>, got \"<name>\"" otherwise.
template <typename Enum, std::size_t N>
Enum parse_name(const EnumName<Enum> (&names)[N], const std::string& name,
                const std::string& context) {
  for (const EnumName<Enum>& n : names) {
    if (name == n.name) return n.value;
  }
  throw InputError(context + " must be " + quoted_choices(names) + ", got \"" + name + "\"");
}

// The names of an enum's values, in its table's order.
template <typename Enum, std::size_t N>
std::vector<std::string> enum_name_list(const EnumName<Enum> (&names)[N]) {
  std::vector<std::string> list;
  for (const EnumName<Enum>& n : names) list.emplace_back(n.name);
  return list;
}

// A key whose value names one of an enum's values: a ChoiceRow bound to `field`, its allowed
// names the enum's one table's. The row keeps a reference to `names`, which must therefore
// have static storage (a constexpr table at namespace scope, as every enum's is).
template <typename Enum, std::size_t N>
ChoiceRow enum_choice_row(std::string key, const EnumName<Enum> (&names)[N], std::string doc,
                          Enum* field) {
  return {std::move(key), enum_name_list(names), std::move(doc),
          [&names, field](const std::string& v) { *field = parse_name(names, v, "choice"); },
          [&names, field] { return std::string(name_of(names, *field)); }};
}

}  // namespace pamsim
