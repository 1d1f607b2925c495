// entry_keys.h: the keys of a file's arrays of tables ([[parameter]], [[recording]],
// [[axis]]...) as typed rows, one row a key: its name, unit, type, range (a number's) or names
// (a choice's), default and meaning. A reader's list of these is the one place its entries'
// keys are named, typed and described: every given key is checked against its row before the
// reader reads the entry (TableEntry::allow, config_reader.h; the sweep's axes), `pamsim keys`
// lists them (entry_key_docs), and the tests generate each row's bad values from it. What a
// row cannot say (a key of the base scenario, "below to") its reader checks and its `allowed`
// text names.
#pragma once

#include <string>
#include <vector>

#include <toml++/toml.h>

#include "base/key_table.h"  // KeyRange, KeyDoc

namespace pamsim {

// The TOML type an entry key's value must have. kAny: the reader alone checks it (a value of
// the swept key's own type, a table or a list of them).
enum class EntryType { kAny, kText, kTexts, kNumber, kInteger, kBool, kChoice, kTable };

struct EntryKey {
  std::string name;
  std::string unit;      // "Hz"; "" for none; "(the key's)" where it is another key's
  std::string allowed;   // what the type, range and names do not say ("below to"); may be ""
  std::string fallback;  // "(required)", "1.0", ...
  std::string meaning;
  EntryType type = EntryType::kAny;
  KeyRange range{};                    // kNumber, kInteger: in `unit`
  std::vector<std::string> choices{};  // kChoice
};

// Whether `key` is one of `keys`' names.
bool is_entry_key(const std::vector<EntryKey>& keys, const std::string& key);

// What is wrong with `value` as key `key`'s, by its row's type, range and names: "" if
// nothing, else "must be a string", "must be in (0, inf), got 0", "is \"x\", allowed \"a\" |
// \"b\""...; for a key `keys` lacks, "is not a key of this table (<its keys>)".
std::string entry_value_problem(const std::vector<EntryKey>& keys, const std::string& key,
                                const toml::node& value);

// The reference lines of array `array`'s entry keys: "<array>[].<name>", what each allows
// written from its type, range or names, then its `allowed` text.
std::vector<KeyDoc> entry_key_docs(const std::string& array, const std::vector<EntryKey>& keys);

}  // namespace pamsim
