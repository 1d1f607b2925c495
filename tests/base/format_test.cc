// format_test.cc: messages stay one printable line (printable_message): control bytes are
// escaped, a megabyte value is cut to its ends, UTF-8 is never split, and wrapping a message
// again changes nothing; InputError keeps a NUL-bearing message whole. Numbers in files are
// the shortest text that reads back (format_shortest), and toml_text round-trips.
#include "base/format.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <random>
#include <string>

#include "base/input_error.h"
#include "base/toml_file.h"

namespace pamsim {
namespace {

TEST(FormatTest, ControlBytesAreEscapedAndTheRestKept) {
  EXPECT_EQ(printable_message(std::string("a\0b\nc\x1b[31m\x7f", 11)),
            "a\\x00b\\x0Ac\\x1B[31m\\x7F");
  EXPECT_EQ(printable_message("key \"é\" must be a number"), "key \"é\" must be a number");
}

TEST(FormatTest, ALongValueIsCutToItsEndsAndTheLineIsBounded) {
  const std::string value(3'000'000, 'x');
  const std::string m = printable_message("file: key got \"" + value + "\" (more)");
  EXPECT_LT(m.size(), 600u);
  EXPECT_EQ(m.rfind("file: key got \"xxx", 0), 0u) << m;
  EXPECT_NE(m.find("bytes)"), std::string::npos) << m;
  EXPECT_EQ(m.substr(m.size() - 8), "\" (more)") << m;
  std::string many;  // many short words: the line itself is capped
  for (int i = 0; i < 100000; ++i) many += "word ";
  EXPECT_LE(printable_message(many).size(), 2000u);
}

TEST(FormatTest, CutsKeepUtf8CharactersWhole) {
  std::string value;
  for (int i = 0; i < 500; ++i) value += "é";  // 2 bytes each
  const std::string m = printable_message(value);
  ASSERT_LT(m.size(), value.size());
  const std::size_t cut = m.find("...(");
  ASSERT_NE(cut, std::string::npos);
  EXPECT_EQ(cut % 2, 0u) << "the head ends on a character boundary";
  EXPECT_EQ((m.size() - m.find(")...") - 4) % 2, 0u) << "the tail starts on one";
}

TEST(FormatTest, IsIdempotentSoWrappedMessagesKeepTheirForm) {
  for (const std::string& value : {std::string(100000, 'y') + "\\0", std::string(300, '\0'),
                                   std::string(200, '\x1b') + std::string(1000, 'z')}) {
    const std::string once = printable_message("f: k got \"" + value + "\"");
    EXPECT_EQ(printable_message(once), once);
    EXPECT_EQ(printable_message("p: " + once).substr(3), once);
    EXPECT_EQ(once.find("\\x0..."), std::string::npos) << "a cut never splits an escape";
  }
}

TEST(FormatTest, PathsOfOrdinaryLengthAreNotCut) {
  const std::string path = "/scratch/" + std::string(300, 'd') + "/renders/sweep/points.csv";
  EXPECT_EQ(printable_message(path + ": cannot write"), path + ": cannot write");
}

TEST(FormatTest, InputErrorKeepsAMessageWithANulWhole) {
  const InputError e(std::string("s.toml: design got \"ab\0cd\"", 26));
  EXPECT_EQ(std::string(e.what()), "s.toml: design got \"ab\\x00cd\"");
}

}  // namespace
}  // namespace pamsim

namespace pamsim {
namespace {

TEST(FormatTest, NumbersInFilesAreTheShortestTextThatReadsBack) {
  EXPECT_EQ(format_shortest(0.14), "0.14");  // printf("%.17g") would say 0.14000000000000001
  EXPECT_EQ(format_shortest(0.1 + 0.2), "0.30000000000000004");
  EXPECT_EQ(format_shortest(5e-324), "5e-324");
  EXPECT_EQ(format_shortest(-36.0), "-36");
  EXPECT_EQ(format_number(-36.0), "-36.0");  // a float to TOML
  EXPECT_EQ(format_shortest(std::nan("")), "nan");
  // every double reads back exactly, over a spread of magnitudes
  std::mt19937_64 rng(7);
  std::uniform_int_distribution<std::uint64_t> bits;
  for (int i = 0; i < 10000; ++i) {
    std::uint64_t b = bits(rng);
    double v;
    std::memcpy(&v, &b, sizeof(v));
    if (!std::isfinite(v)) continue;
    EXPECT_EQ(std::strtod(format_shortest(v).c_str(), nullptr), v) << format_shortest(v);
  }
}

TEST(FormatTest, TomlTextRoundTripsAndWritesFloatsShortest) {
  const std::string source =
      "seed = 3\nname = \"x y\"\nlist = [0.1, 2.0, 1e-300]\n\n[sim]\nduration_s = 0.14\n\n"
      "[muscles.agonist]\ncommand = { kind = \"sine\", MPa = 0.6 }\n\n[[axis]]\nkey = \"a.b\"\n"
      "\n[[axis]]\nkey = \"c\"\n\n[\"odd key\"]\nflag = true\n";
  const toml::table table = parse_toml_text(source, "test");
  const std::string text = toml_text(table);
  EXPECT_EQ(parse_toml_text(text, "again"), table) << text;
  EXPECT_NE(text.find("duration_s = 0.14\n"), std::string::npos) << text;
  EXPECT_NE(text.find("list = [0.1, 2.0, 1e-300]"), std::string::npos) << text;
  EXPECT_EQ(toml_value_text(toml::value<double>(3.0)), "3.0");  // still a float
  EXPECT_EQ(toml_value_text(toml::value<std::string>("a\"b")), "\"a\\\"b\"");
}

}  // namespace
}  // namespace pamsim

namespace pamsim {
namespace {

// A value to its uncertainty's two significant digits, as a reader writes it.
TEST(FormatWithErrorTest, TheValueHasTheUncertaintysDecimals) {
  EXPECT_EQ(format_with_error(2.700591, 0.005312), "2.7006 +- 0.0053");
  EXPECT_EQ(format_with_error(123.4, 13.2), "123 +- 13");
  EXPECT_EQ(format_with_error(0.15104, 0.0013), "0.1510 +- 0.0013");
  EXPECT_EQ(format_with_error(-36.04, 0.5), "-36.04 +- 0.50");
  // no fixed decimals for a non-finite or non-positive uncertainty
  EXPECT_EQ(format_with_error(1.5, 0.0), "1.5 +- 0");
  EXPECT_EQ(format_with_error(1.5, std::nan("")), "1.5 +- nan");
}

}  // namespace
}  // namespace pamsim
