// key_table_names_test.cc: a list of names as a row (NameListRow), by both readers (a
// parameter file's read_key_tables and a scenario's read_key_rows): the file's names reach
// the field in its order, the default stays where the file gives none, and a name the row
// does not allow, an item that is no string or a value that is no list is refused in one
// line naming the file and the key; check_key_rows and the reference line say what it allows.
#include <gtest/gtest.h>

#include <functional>
#include <string>
#include <vector>

#include <toml++/toml.h>

#include "base/config_reader.h"
#include "base/input_error.h"
#include "base/key_table.h"

namespace pamsim {
namespace {

KeyTable sets_table(std::vector<std::string>* sets) {
  KeyTable t{"", {}, {}, {}};
  t.name_lists = {{"sets", {"drop", "reflex", "tracking"}, "the sets", sets}};
  return t;
}

InputErrorParts parts_of(const std::function<void()>& read) {
  try {
    read();
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos) << e.what();
    return e.parts();
  }
  ADD_FAILURE() << "read";
  return {};
}

TEST(KeyTableNamesTest, BothReadersKeepTheOrderAndTheDefault) {
  std::vector<std::string> sets = {"drop"};
  read_key_tables(toml::parse("sets = [\"tracking\", \"drop\"]"), "f.toml", {sets_table(&sets)});
  EXPECT_EQ(sets, (std::vector<std::string>{"tracking", "drop"}));
  sets = {"drop"};
  ConfigReader given("sets = [\"reflex\"]", "s.toml");
  read_key_rows(given, sets_table(&sets));
  EXPECT_EQ(sets, std::vector<std::string>{"reflex"});
  ConfigReader none("", "s.toml");
  read_key_rows(none, sets_table(&sets));
  EXPECT_EQ(sets, std::vector<std::string>{"reflex"}) << "no key: the field as it was";
}

TEST(KeyTableNamesTest, ABadNameAnItemOrAValueIsOneLineNamingTheFileAndTheKey) {
  std::vector<std::string> sets;
  for (const char* bad : {"[\"drop\", \"nope\"]", "[\"drop\", 1]", "\"drop\"", "3"}) {
    const std::string text = std::string("sets = ") + bad;
    const InputErrorParts file =
        parts_of([&] { read_key_tables(toml::parse(text), "f.toml", {sets_table(&sets)}); });
    EXPECT_EQ(file.file, "f.toml") << bad;
    EXPECT_EQ(file.key, "sets") << bad;
    ConfigReader in(text, "s.toml");
    const InputErrorParts scenario = parts_of([&] { read_key_rows(in, sets_table(&sets)); });
    EXPECT_EQ(scenario.file, "s.toml") << bad;
    EXPECT_EQ(scenario.key, "sets") << bad;
  }
  ConfigReader in("sets = [\"nope\"]", "s.toml");
  const InputErrorParts nope = parts_of([&] { read_key_rows(in, sets_table(&sets)); });
  EXPECT_NE(nope.problem.find("holds \"nope\", allowed \"drop\" | \"reflex\" | \"tracking\""),
            std::string::npos)
      << nope.problem;
}

TEST(KeyTableNamesTest, CheckedFieldsAndTheReferenceLine) {
  std::vector<std::string> sets = {"drop", "tracking"};
  check_key_rows(sets_table(&sets));
  const std::vector<KeyDoc> docs = key_table_docs({sets_table(&sets)});
  ASSERT_EQ(docs.size(), 1u);
  EXPECT_EQ(docs[0].key, "sets");
  EXPECT_EQ(docs[0].fallback, "[\"drop\", \"tracking\"]");
  EXPECT_EQ(docs[0].allowed, "a list of \"drop\" | \"reflex\" | \"tracking\"");
  EXPECT_EQ(key_names(sets_table(&sets)), std::vector<std::string>{"sets"});
  sets.push_back("nope");
  EXPECT_EQ(parts_of([&] { check_key_rows(sets_table(&sets)); }).key, "sets");
  KeyTable any{"", {}, {}, {}};
  any.name_lists = {{"bodies", {}, "any names", &sets}};
  check_key_rows(any);
  EXPECT_EQ(key_table_docs({any})[0].allowed, "a list of strings");
}

}  // namespace
}  // namespace pamsim
