// enum_names_test.cc: an enum's name table read both ways, and the one error form that every
// enum's parser gives (checked here against messages written out by hand).
#include "base/enum_names.h"

#include <gtest/gtest.h>

namespace pamsim {
namespace {

enum class Colour { kRed, kGreen, kBlue };
constexpr EnumName<Colour> kColours[] = {
    {Colour::kRed, "red"}, {Colour::kGreen, "green"}, {Colour::kBlue, "blue"}};
enum class Single { kOnly, kUnnamed };
constexpr EnumName<Single> kSingles[] = {{Single::kOnly, "only"}};

std::string message_of(const std::string& name) {
  try {
    parse_name(kColours, name, "file.toml: colour");
  } catch (const InputError& e) {
    return e.what();
  }
  return "no throw";
}

TEST(EnumNamesTest, EveryValueRoundTripsThroughItsName) {
  for (const EnumName<Colour>& n : kColours) {
    EXPECT_EQ(parse_name(kColours, name_of(kColours, n.value), "x"), n.value);
  }
  EXPECT_STREQ(name_of(kColours, Colour::kGreen), "green");
}

TEST(EnumNamesTest, AValueMissingFromTheTableIsNamedWithAQuestionMark) {
  EXPECT_STREQ(name_of(kSingles, Single::kUnnamed), "?");
}

TEST(EnumNamesTest, AnUnknownNameListsTheChoicesInOrder) {
  EXPECT_EQ(message_of("Red"),
            "file.toml: colour must be \"red\", \"green\" or \"blue\", got \"Red\"");
  EXPECT_EQ(message_of(""), "file.toml: colour must be \"red\", \"green\" or \"blue\", got \"\"");
}

TEST(EnumNamesTest, ChoicesReadAsASentenceForOneTwoAndThreeNames) {
  constexpr EnumName<Colour> two[] = {{Colour::kRed, "red"}, {Colour::kBlue, "blue"}};
  EXPECT_EQ(quoted_choices(kSingles), "\"only\"");
  EXPECT_EQ(quoted_choices(two), "\"red\" or \"blue\"");
  EXPECT_EQ(quoted_choices(kColours), "\"red\", \"green\" or \"blue\"");
}

}  // namespace
}  // namespace pamsim
