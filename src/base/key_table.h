// key_table.h: a parameter file's keys as rows, one row a key: its name as the file writes
// it (the unit in the name: "dead_time_ms"), the unit, the factor from that unit to SI,
// the range it allows in that unit, its meaning, and the field it fills. A key's unit,
// range, default (the field's value before the file is read: the struct's own) and doc
// live in its row and nowhere else; the reader, the range checks, the key reference
// (KeyDoc, as `pamsim keys` prints it) and the tests' bad values all come from the rows.
#pragma once

#include <cstdint>
#include <functional>
#include <limits>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <toml++/toml.h>

namespace pamsim {

// An interval of allowed values, in the file's unit; finite values only.
struct KeyRange {
  double lo = -std::numeric_limits<double>::infinity();
  double hi = std::numeric_limits<double>::infinity();
  bool lo_open = false;
  bool hi_open = false;
  bool contains(double v) const;
  std::string text() const;  // "(0, 2]", "[200, 400]", "(0, inf)"
};

// The ranges most keys have: > 0, >= 0, and any finite value.
inline constexpr KeyRange kPositiveRange{0.0, std::numeric_limits<double>::infinity(), true, false};
inline constexpr KeyRange kNonNegativeRange{0.0, std::numeric_limits<double>::infinity(), false,
                                            false};
inline constexpr KeyRange kAnyRange{};

// A number key: the file's value times to_si is written to *target (or *optional_target, a
// field whose absence means "unset").
struct NumberRow {
  std::string name;  // "dead_time_ms"
  std::string unit;  // "ms"; "" for a pure number
  double to_si = 1.0;
  KeyRange range;
  std::string doc;
  double* target = nullptr;
  std::optional<double>* optional_target = nullptr;
  bool required = false;       // a file must give it (the field's value is no default)
  std::string fallback_doc{};  // the default as a reference shows it, where it is not the
                               // field's one value ("(Table II: 70 model, 25 fiber)")
  double divisor = 1.0;        // SI = value * to_si / divisor: degrees as units::deg_to_rad
                               // rounds them (to_si = pi, divisor = 180)

  double si(double value) const { return value * to_si / divisor; }
  bool trial_only = false;  // only the trial reads it, not the model it runs on (KeyTable's)
};

// An integer key (a count: bits, steps, a seed), in [lo, hi]; int_row binds it to a field.
struct IntRow {
  std::string name;
  std::string doc;
  std::int64_t lo = 0;
  std::int64_t hi = 0;
  std::function<void(std::int64_t)> set;  // sets the field
  std::function<std::int64_t()> get;      // the field's value now
  std::string fallback_doc{};  // the default as a reference shows it, where it is not the
                               // field's one value ("(8, more for many parameters)")
  bool trial_only = false;     // only the trial reads it, not the model (KeyTable's)
};

// An IntRow bound to an integer field of any type whose range holds [lo, hi].
template <typename Int>
IntRow int_row(std::string name, std::string doc, std::int64_t lo, std::int64_t hi, Int* field) {
  return {std::move(name),
          std::move(doc),
          lo,
          hi,
          [field](std::int64_t v) { *field = static_cast<Int>(v); },
          [field] { return static_cast<std::int64_t>(*field); }};
}

// A true/false key.
struct BoolRow {
  std::string name;
  std::string doc;
  bool* target = nullptr;
};

// A list of numbers (a series' terms), each in `range` in the file's unit, min_count to
// max_count of them; the SI values go to *target.
struct ListRow {
  std::string name;
  std::string unit;
  double to_si = 1.0;
  KeyRange range;
  std::size_t max_count = 0;
  std::string doc;
  std::vector<double>* target = nullptr;
  std::string fallback_doc{};  // the default as a reference shows it ("(the model's)")
  std::size_t min_count = 0;   // the fewest a given list may hold
};

// A free text key (a name, a source's citation), or a path to a file to read: given
// relative to the folder of the file that gives it, stored resolved, and refused unless it is
// a regular file of bounded size (toml_file.h: require_input_file).
struct TextRow {
  std::string name;
  std::string doc;
  std::string* target = nullptr;
  std::string fallback_doc{};  // the default as a reference shows it, where the field's
                               // empty value stands for another ("(the model's first joint)")
  bool input_file = false;     // a path to a file to read (above)
  bool required = false;       // a file must give it
  bool trial_only = false;     // only the trial reads it, not the model (KeyTable's)
};

// A key whose value is one of a few names.
struct ChoiceRow {
  std::string name;
  std::vector<std::string> allowed;
  std::string doc;
  std::function<void(const std::string&)> set;  // sets the field from an allowed name
  std::function<std::string()> get;             // the name the field holds now
};

// A list of names (metric sets, bodies), each one of `allowed` (empty: any string), the
// file's order kept; *target holds the default until the file gives the list.
struct NameListRow {
  std::string name;
  std::vector<std::string> allowed;
  std::string doc;
  std::vector<std::string>* target = nullptr;
  std::string fallback_doc{};  // the default as a reference shows it, where it is not the
                               // field's one value ("(drop: [...]; else ...)")
};

// One TOML table of the file.
struct KeyTable {
  std::string name;  // "regulator"; "" for the file's top-level keys
  std::vector<NumberRow> numbers;
  std::vector<ChoiceRow> choices;
  std::vector<BoolRow> bools{};
  std::vector<IntRow> ints{};
  std::vector<TextRow> texts{};
  std::vector<ListRow> lists{};
  bool optional = false;  // the file may leave the whole table out (its required rows with it)
  std::vector<NameListRow> name_lists{};
  // A scenario's keys that only the trial reads (a gain, a sensor's, the duration), not the
  // simulated model it runs on (the MJCF and the muscles' bindings): scenarios that differ only
  // in such keys share one compiled model (same_trial_model). For a row, its own flag.
  bool trial_only = false;
};

class ConfigReader;

// One key as a reference shows it (`pamsim keys`, the docs' key references).
struct KeyDoc {
  std::string key;       // dotted, with placeholders where the user names the part
  std::string unit;      // "s", "MPa", "" (none)
  std::string fallback;  // the default as TOML text ("0.001", "\"iso6358\""), or in
                         // parentheses where it is not one value ("(Table II)", "(unset)")
  std::string allowed;   // the values the reader accepts
  std::string meaning;
  bool trial_only = false;  // only the trial reads it, not its model (KeyTable::trial_only)
};

// Reads `doc` (the file at `path`) by `tables`: every table and key must have a row, a
// number must be a finite number within its range, a choice one of its names; each value
// goes to its field. The top-level keys are table ""'s, a table inside table "a" is table
// "a.b". A required row must be given when its table is in the file, and when the table's
// parent is (the top level always is) unless the table is optional. Throws InputError "<path>:
// <table>.<key>: <problem>" (file_key_error) for an unknown table or key, a wrong type, a value out
// of range or a required key missing. Returns the keys given, dotted ("geometry.length_mm").
std::vector<std::string> read_key_tables(const toml::table& doc, const std::string& path,
                                         const std::vector<KeyTable>& tables);

// One table of a larger document (a scenario's "reflex"), read by `in` (ConfigReader, which
// marks the keys read and refuses the keys nobody reads): the choices first (a choice may set
// other fields' defaults, as reflex.sensor sets Table II's), then the true/false keys, then
// the integers, then the numbers. A key the document does not give leaves its field as it is (and
// is listed among the reader's defaults); a given one must have its row's type and range. Throws
// InputError "<file>: <table>.<key> <problem>" through ConfigReader::fail.
void read_key_rows(ConfigReader& in, const KeyTable& table);

// `table` with only the rows whose keys `in` has: for optional keys whose absence means
// another source's value (the model's, the pneumatics file's), which the reader then neither
// sets nor lists among its defaults.
KeyTable rows_given(const ConfigReader& in, KeyTable table);

// `table` with only the rows named: a reader reads the rows that apply (an event's action
// decides which of its keys it has), and a key given beside the wrong ones stays unread,
// refused as unknown.
KeyTable rows_named(KeyTable table, const std::vector<std::string>& names);

// `table`, whose one row (a number or a text) is a long form's, as its shorthand: the table
// named `table_name`, the row `row_name`, its doc prefixed "shorthand of <long_form>: ",
// optional (a reader reads a shorthand only where it is given), its default shown as
// "(none)". The shorthand keeps its long form's unit, range and meaning, written once.
KeyTable as_shorthand(KeyTable table, const std::string& table_name, const std::string& row_name,
                      const std::string& long_form);

// The rows' fields as they are now, checked against the rows' ranges and choices: a
// validate() of a struct its table is bound to. Throws InputError
// "<table>.<key> must be in <range>, got <value>" (require_value).
void check_key_rows(const KeyTable& table);

// A row's key as a file writes it: "<table>.<name>", or "<name>" in the top-level table "".
std::string row_key(const KeyTable& table, const std::string& name);
// Every row's key, in the reader's order (choices, true/false keys, integers, numbers, texts,
// lists, name lists).
std::vector<std::string> key_names(const KeyTable& table);

// A field's SI value in its row's unit: the shortest decimal of 15 to 17 significant digits
// that the reader turns back into the same SI value (the file's 70 mm/s, read as 0.07 m/s,
// shows as 70 again, not 70.00000000000001; Table II's 1/300 MPa s/mm in full).
double from_si(const NumberRow& row, double si);

// Row `name`'s field in the row's unit (from_si); NaN for an unset optional. The row must
// exist (asserted).
double file_value(const KeyTable& table, const std::string& name);

// Every row as a reference line "<table>.<key>", its default being its field's value now, in
// the order the reader reads them: choices, true/false keys, integers, numbers.
std::vector<KeyDoc> key_table_docs(const std::vector<KeyTable>& tables);

}  // namespace pamsim
