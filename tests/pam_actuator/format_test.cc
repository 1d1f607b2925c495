// format_test.cc: messages stay one printable line (printable_message): control bytes are
// escaped, a megabyte value is cut to its ends, UTF-8 is never split, and wrapping a message
// again changes nothing; InputError keeps a NUL-bearing message whole.
#include "pam_actuator/format.h"

#include <gtest/gtest.h>

#include <string>

#include "pam_actuator/input_error.h"

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
