// sweep_cases.cc: a sweep file's case axes (sweep.h): named bundles of scenario keys crossed
// with the other axes, as a lab's table of conditions is ("ideal source", "ITV2000 class");
// and the check that no two axes set one key.
#include <cctype>
#include <filesystem>
#include <map>
#include <optional>
#include <set>

#include "base/input_error.h"
#include "base/toml_file.h"
#include "sim/sweep/sweep_axis_file.h"

namespace pamsim::detail {
namespace {

// Reserved columns of the trials table (results_db.cc) that a case axis's name would shadow.
const std::set<std::string> kReservedNames = {"trial", "point", "status", "message", "seed"};

bool plain_name(const std::string& name) {
  if (name.empty() || std::isdigit(static_cast<unsigned char>(name[0]))) return false;
  for (const char c : name) {
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '_') return false;
  }
  return true;
}

// A case's `from = { file = "...", table = "..." }`: the keys of a table of another file (a
// bracket's end, kept where its sources are), named as inside that table; the file's path
// relative to the sweep file's.
void read_case_from(const toml::node& from, const Where& where, std::vector<std::string>* set) {
  const toml::table* t = from.as_table();
  const auto file = t ? (*t)["file"].value<std::string>() : std::nullopt;
  const auto table = t ? (*t)["table"].value<std::string>() : std::nullopt;
  where.check(file && table && t->size() == 2, "from",
              "must be { file = \"...\", table = \"...\" } (or a list of them): a table of "
              "scenario keys in a file");
  where.check(*file != "-", "from", "file must be a file (not standard input)");
  const std::filesystem::path dir = std::filesystem::path(where.file).parent_path();
  const std::string path = (dir / *file).lexically_normal().string();
  toml::table keys;
  try {
    keys = parse_toml_file(path);
  } catch (const InputError& e) {
    where.fail("from", e.what());
  }
  const toml::table* chosen = keys[*table].as_table();
  where.check(chosen != nullptr, "from", path + " has no table [" + *table + "]");
  flatten_keys(*chosen, "", Where{where.file, where.prefix + "from."}, set);
}

// One [[axis.case]]: its name (unique in the axis) and its scenario keys (from, then set).
void read_case(const toml::node& node, std::size_t c, const Where& axis, SweepAxis* out) {
  const Where where{axis.file, axis.prefix + "case[" + std::to_string(c) + "]."};
  const toml::table* t = node.as_table();
  axis.check(t != nullptr, "case", "must be [[axis.case]] tables");
  check_entry(*t, case_entry_keys(), where, "is not a case key (name, from, set)");
  const auto name = (*t)["name"].value<std::string>();
  where.check(name && !name->empty(), "name", "is required (a non-empty string)");
  for (const AxisValue& v : out->values) {
    where.check(v.text != *name, "name", "\"" + *name + "\" names another case of this axis");
  }
  std::vector<std::string> set;
  if (const toml::node* from = t->get("from")) {
    if (const toml::array* list = from->as_array()) {
      for (const toml::node& one : *list) read_case_from(one, where, &set);
    } else {
      read_case_from(*from, where, &set);
    }
  }
  if (const toml::node* s = t->get("set")) {
    flatten_keys(*s->as_table(), "", Where{axis.file, where.prefix + "set."}, &set);  // by its row
  }
  AxisValue v;
  v.kind = AxisValue::Kind::kString;
  v.text = *name;
  out->values.push_back(v);
  out->case_sets.push_back(std::move(set));
}

}  // namespace

SweepAxis read_case_axis(const toml::table& t, std::size_t index, SweepDesign design,
                         const std::string& file) {
  const Where where{file, "axis[" + std::to_string(index) + "]."};
  check_entry(t, case_axis_entry_keys(), where,
              "does not go with [[axis.case]] (a case axis has name and its cases)");
  where.check(design == SweepDesign::kGrid, "case",
              "is for grid designs; random and lhs sample ranges");
  SweepAxis axis;
  const auto name = t["name"].value<std::string>();
  where.check(name.has_value(), "name", "is required: the case axis's column, e.g. \"regulator\"");
  where.check(plain_name(*name), "name",
              "must be letters, digits and _ (a column name), got \"" + *name + "\"");
  where.check(!kReservedNames.count(*name), "name", "\"" + *name + "\" is a column pamsim keeps");
  axis.key = *name;
  const toml::array* cases = t["case"].as_array();
  where.check(cases != nullptr && !cases->empty(), "case", "must be one or more [[axis.case]]");
  for (std::size_t c = 0; c < cases->size(); ++c) read_case((*cases)[c], c, where, &axis);
  return axis;
}

void check_axes_disjoint(const std::vector<SweepAxis>& axes, const std::vector<std::string>& drawn,
                         const std::vector<std::string>& fixed, const std::string& file) {
  std::map<std::string, std::string> setter;  // scenario key -> what sets it
  const auto claim = [&](const std::string& key, const std::string& who) {
    const auto [at, fresh] = setter.emplace(key, who);
    if (!fresh && at->second != who) {
      throw InputError(file + ": " + who + " sets " + key + ", which " + at->second + " sets too");
    }
  };
  for (const std::string& assignment : fixed) claim(override_key(assignment), "[fixed]");
  for (std::size_t a = 0; a < axes.size(); ++a) {
    const std::string who = "axis[" + std::to_string(a) + "]";
    if (!axes[a].is_cases()) claim(axes[a].key, who);
    for (const auto& set : axes[a].case_sets) {
      for (const std::string& assignment : set) claim(override_key(assignment), who);
    }
  }
  for (const std::string& key : drawn) claim(key, "randomize");
}

}  // namespace pamsim::detail
