// key_table_test.cc: the key-table rows (base/key_table.h) on a table made here: a whole
// document read by read_key_tables (a number to its SI field, a choice, an integer, a
// true/false key; each refused in one line naming the file and the key for a wrong type, a
// value outside its range, an unknown key or table), ranges written as intervals, the file's
// value given back from SI without a trailing digit, check_key_rows on the fields as they
// are, and the reference lines in the reader's order; a file's top-level keys, nested
// tables, texts and lists, and the required rows of a table it must or may give.
#include <gtest/gtest.h>

#include <limits>
#include <string>
#include <vector>

#include <toml++/toml.h>

#include "base/config_reader.h"
#include "base/input_error.h"
#include "base/key_table.h"

namespace pamsim {
namespace {

struct Fields {
  double delay_s = 0.02;
  int bits = 12;
  bool on = false;
  std::string mode = "fast";
};

KeyTable table(Fields* f) {
  KeyTable t{"loop", {}, {}, {}};
  t.numbers = {{"delay_ms", "ms", 1e-3, {0.0, 1000.0, false, true}, "the delay", &f->delay_s}};
  t.choices = {{"mode",
                {"fast", "slow"},
                "the mode",
                [f](const std::string& v) { f->mode = v; },
                [f] { return f->mode; }}};
  t.bools = {{"on", "switched on", &f->on}};
  t.ints = {int_row("bits", "resolution", 4, 24, &f->bits)};
  return t;
}

// the refusal's parts of reading `text` as file "f.toml"
InputErrorParts refusal(const std::string& text) {
  Fields f;
  try {
    read_key_tables(toml::parse(text), "f.toml", {table(&f)});
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos) << e.what();
    return e.parts();
  }
  ADD_FAILURE() << "read: " << text;
  return {};
}

TEST(KeyTableTest, ADocumentReachesItsFieldsInSi) {
  Fields f;
  read_key_tables(toml::parse("[loop]\ndelay_ms = 70\nmode = \"slow\"\non = true\nbits = 16\n"),
                  "f.toml", {table(&f)});
  EXPECT_EQ(f.delay_s, 70 * 1e-3);
  EXPECT_EQ(f.mode, "slow");
  EXPECT_TRUE(f.on);
  EXPECT_EQ(f.bits, 16);
}

TEST(KeyTableTest, EveryBadValueIsOneLineNamingTheFileAndTheKey) {
  struct Case {
    const char* text;
    const char* key;
    const char* says;
  };
  for (const Case& c :
       {Case{"[loop]\ndelay_ms = 1000\n", "loop.delay_ms", "must be in [0, 1000) ms, got 1000"},
        Case{"[loop]\ndelay_ms = \"x\"\n", "loop.delay_ms", "must be a number"},
        Case{"[loop]\nmode = \"medium\"\n", "loop.mode", "unknown value \"medium\""},
        Case{"[loop]\nmode = 1\n", "loop.mode", "must be a string"},
        Case{"[loop]\non = 1\n", "loop.on", "must be true or false"},
        Case{"[loop]\nbits = 2.5\n", "loop.bits", "must be an integer"},
        Case{"[loop]\nbits = 25\n", "loop.bits", "out of range, allowed [4, 24]"},
        Case{"[loop]\nbit = 12\n", "loop.bit", "unknown key (allowed: delay_ms, mode, on, bits)"},
        Case{"[lop]\nbits = 12\n", "lop", "unknown table (allowed: loop)"},
        Case{"loop = 3\n", "loop", "must be a table"}}) {
    const InputErrorParts parts = refusal(c.text);
    EXPECT_EQ(parts.file, "f.toml") << c.text;
    EXPECT_EQ(parts.key, c.key) << c.text;
    EXPECT_NE(parts.problem.find(c.says), std::string::npos) << parts.problem;
  }
}

TEST(KeyTableTest, RangesAndFileValuesReadAsWritten) {
  const double inf = std::numeric_limits<double>::infinity();
  EXPECT_EQ((KeyRange{0.0, inf, true, false}).text(), "(0, inf)");
  EXPECT_EQ((KeyRange{-1.0, 1.0, false, true}).text(), "[-1, 1)");
  EXPECT_FALSE((KeyRange{0.0, 1.0, true, false}).contains(0.0));
  EXPECT_FALSE((KeyRange{}).contains(std::numeric_limits<double>::quiet_NaN()));
  Fields f;
  const KeyTable t = table(&f);
  f.delay_s = 70 * 1e-3;  // 0.07000000000000001 in SI
  EXPECT_EQ(file_value(t, "delay_ms"), 70.0);
  f.delay_s = 1e-3 / 3.0;
  EXPECT_EQ(from_si(t.numbers[0], f.delay_s) * 1e-3, f.delay_s);
}

TEST(KeyTableTest, CheckedFieldsAndReferenceLines) {
  Fields f;
  const KeyTable t = table(&f);
  EXPECT_NO_THROW(check_key_rows(t));
  f.bits = 3;
  EXPECT_THROW(check_key_rows(t), InputError);
  f.bits = 12;
  f.delay_s = 2.0;  // 2000 ms
  try {
    check_key_rows(t);
    ADD_FAILURE() << "no throw";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), "loop.delay_ms must be in [0, 1000), got 2000");
  }
  f.delay_s = 0.02;
  const std::vector<KeyDoc> docs = key_table_docs({t});
  ASSERT_EQ(docs.size(), 4u);
  EXPECT_EQ(docs[0].key, "loop.mode");  // the reader's order: choices, bools, ints, numbers
  EXPECT_EQ(docs[0].fallback, "\"fast\"");
  EXPECT_EQ(docs[1].allowed, "true | false");
  EXPECT_EQ(docs[2].allowed, "[4, 24]");
  EXPECT_EQ(docs[3].key, "loop.delay_ms");
  EXPECT_EQ(docs[3].fallback, "20.0");  // as TOML writes it
  EXPECT_EQ(docs[3].unit, "ms");
}

}  // namespace
}  // namespace pamsim

namespace pamsim {
namespace {

// A file with top-level keys (table ""), a text, a list, a nested table and tables that must
// or may be given (the layout of a plant or muscle parameter file).
struct Nested {
  std::string name;
  std::vector<double> times_s;
  double length_m = 0.0, force_n = 0.0, gain = 1.0;
};

std::vector<KeyTable> nested_tables(Nested* n) {
  constexpr double kInf = std::numeric_limits<double>::infinity();
  KeyTable top{"", {}, {}};
  top.texts = {{"name", "its name", &n->name}};
  KeyTable geometry{"geometry", {}, {}};
  geometry.numbers = {
      {"length_mm", "mm", 1e-3, {0.0, kInf, true}, "L", &n->length_m, nullptr, true}};
  geometry.lists = {{"times_ms", "ms", 1e-3, {0.0, kInf, true}, 2, "the times", &n->times_s}};
  KeyTable stroke{"geometry.stroke", {}, {}};
  stroke.numbers = {{"F0_N", "N", 1.0, {0.0, kInf}, "F0", &n->force_n, nullptr, true}};
  KeyTable extra{"extra", {}, {}};
  extra.optional = true;
  extra.numbers = {{"gain", "", 1.0, {0.0, 10.0}, "g", &n->gain, nullptr, true}};
  return {top, geometry, stroke, extra};
}

InputErrorParts nested_refusal(const std::string& text) {
  Nested n;
  try {
    read_key_tables(toml::parse(text), "f.toml", nested_tables(&n));
  } catch (const InputError& e) {
    return e.parts();
  }
  ADD_FAILURE() << "read: " << text;
  return {};
}

TEST(KeyTableTest, TopLevelKeysNestedTablesTextsAndListsReachTheirFields) {
  Nested n;
  const std::vector<std::string> given = read_key_tables(
      toml::parse("name = \"a\"\n[geometry]\nlength_mm = 180\ntimes_ms = [10, 100]\n"
                  "stroke = { F0_N = 0.5 }\n"),
      "f.toml", nested_tables(&n));
  EXPECT_EQ(n.name, "a");
  EXPECT_EQ(n.length_m, 180 * 1e-3);
  EXPECT_EQ(n.times_s, (std::vector<double>{10 * 1e-3, 100 * 1e-3}));
  EXPECT_EQ(n.force_n, 0.5);
  EXPECT_EQ(n.gain, 1.0) << "an optional table left out keeps its defaults";
  EXPECT_EQ(given, (std::vector<std::string>{"geometry", "geometry.length_mm", "geometry.stroke",
                                             "geometry.stroke.F0_N", "geometry.times_ms",
                                             "name"}))  // toml++ keeps a table's keys sorted
      << "every key given, and the tables";
}

TEST(KeyTableTest, RequiredRowsOfATableThatMustBeGivenAndBadTextsAndListsAreNamed) {
  struct Case {
    const char* text;
    const char* key;
    const char* says;
  };
  for (const Case& c :
       {Case{"name = \"a\"\n", "geometry.length_mm", "is required"},
        Case{"[geometry]\nlength_mm = 1\n", "geometry.stroke.F0_N", "is required"},
        Case{"[geometry]\nlength_mm = 1\nstroke = {F0_N = 1}\n[extra]\n", "extra.gain",
             "is required"},
        Case{"name = 3\n", "name", "must be a string"},
        Case{"colour = 3\n", "colour", "unknown key (allowed: name)"},
        Case{"[colour]\nx = 3\n", "colour", "unknown table (allowed: geometry, extra)"},
        Case{"[geometry]\ntimes_ms = [1, 2, 3]\n", "geometry.times_ms",
             "must list up to 2 values, got 3"},
        Case{"[geometry]\ntimes_ms = [1, -2]\n", "geometry.times_ms",
             "[1] must be in (0, inf) ms, got -2"},
        Case{"[geometry]\ntimes_ms = 1\n", "geometry.times_ms", "must be a list of numbers"},
        Case{"[geometry]\nlength_mm = nan\n", "geometry.length_mm", "must be finite"},
        Case{"[geometry]\nstroke = 1\n", "geometry.stroke", "must be a table"}}) {
    const InputErrorParts parts = nested_refusal(c.text);
    EXPECT_EQ(parts.key, c.key) << c.text;
    EXPECT_NE(parts.problem.find(c.says), std::string::npos) << c.text << ": " << parts.problem;
  }
}

// A shorthand is its long form's row renamed: the same unit, factor and range, read into the
// same field, its doc saying what it shortens, optional where the long form was required.
TEST(KeyTableTest, AShorthandIsTheLongFormsRowRenamed) {
  double pressure_pa = 0.0;
  NumberRow row{"MPa", "MPa", 1e6, kNonNegativeRange, "the commanded pressure", &pressure_pa};
  row.required = true;
  const KeyTable shorthand = as_shorthand(KeyTable{"muscles.agonist.command", {row}, {}},
                                          "pressure", "agonist_MPa", "a constant command");
  ASSERT_EQ(shorthand.numbers.size(), 1u);
  EXPECT_EQ(row_key(shorthand, shorthand.numbers[0].name), "pressure.agonist_MPa");
  EXPECT_EQ(shorthand.numbers[0].doc, "shorthand of a constant command: the commanded pressure");
  EXPECT_FALSE(shorthand.numbers[0].required);
  ConfigReader in("pressure = { agonist_MPa = 0.25 }", "s.toml");
  read_key_rows(in, shorthand);
  EXPECT_DOUBLE_EQ(pressure_pa, 0.25e6);
  ConfigReader bad("pressure = { agonist_MPa = -1 }", "s.toml");
  EXPECT_THROW(read_key_rows(bad, shorthand), InputError) << "the long form's range";
}

}  // namespace
}  // namespace pamsim
