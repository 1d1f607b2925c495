// input_error_test.cc: an error about one key keeps its file, key and problem as fields, and
// the readers that re-throw it under another name use those fields, not the message's text.
#include "base/input_error.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include <toml++/toml.h>

#include "base/config_reader.h"
#include "base/file_changes.h"

namespace pamsim {
namespace {

TEST(InputErrorTest, AFileKeyErrorIsOneLineAndKeepsItsParts) {
  const InputError e = file_key_error("plant.toml", "geometry.length_mm", "must be > 0, got -1");
  EXPECT_STREQ(e.what(), "plant.toml: geometry.length_mm: must be > 0, got -1");
  EXPECT_EQ(e.parts().file, "plant.toml");
  EXPECT_EQ(e.parts().key, "geometry.length_mm");
  EXPECT_EQ(e.parts().problem, "must be > 0, got -1");
  EXPECT_STREQ(file_key_error("", "k", "bad").what(), "k: bad") << "no file, no leading colon";
  const InputError plain("plant.toml: cannot open file");
  EXPECT_TRUE(plain.parts().key.empty());
}

TEST(InputErrorTest, ARequiredValueNamesItsKey) {
  try {
    require_value(false, "friction.slip.weights", "summing to 1", 0.9);
    FAIL() << "no throw";
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(), "friction.slip.weights must be summing to 1, got 0.9");
    EXPECT_EQ(e.parts().key, "friction.slip.weights");
    EXPECT_TRUE(e.parts().file.empty());
  }
  EXPECT_NO_THROW(require_value(true, "k", "> 0", 1.0));
}

TEST(InputErrorTest, AConfigReadersRefusalNamesTheDocumentAndTheKey) {
  ConfigReader in("[reflex]\nv_thr_mm_s = -1\n", "scenario.toml");
  try {
    in.fail("reflex.v_thr_mm_s", "must be > 0, got -1");
    FAIL() << "no throw";
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(), "scenario.toml: reflex.v_thr_mm_s must be > 0, got -1");
    EXPECT_EQ(e.parts().file, "scenario.toml");
    EXPECT_EQ(e.parts().key, "reflex.v_thr_mm_s");
  }
}

// A changed field's error is re-thrown under the change's key from its parts; an error that
// only reads like one (no parts) or names another file or key is left as it is.
TEST(InputErrorTest, AChangedFieldsErrorIsRenamedFromItsPartsNotItsText) {
  const std::vector<std::string> changed = {"geometry.length_mm"};
  const std::string prefix = "muscles.agonist.plant.";
  try {
    rethrow_as_change(file_key_error("p.toml", "geometry.length_mm", "must be > 0, got -1"),
                      "p.toml", changed, prefix);
    FAIL() << "not re-thrown";
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(), "muscles.agonist.plant.geometry.length_mm: must be > 0, got -1");
    EXPECT_EQ(e.parts().key, "muscles.agonist.plant.geometry.length_mm");
  }
  EXPECT_NO_THROW(rethrow_as_change(InputError("p.toml: geometry.length_mm: must be > 0"), "p.toml",
                                    changed, prefix));
  EXPECT_NO_THROW(rethrow_as_change(file_key_error("q.toml", "geometry.length_mm", "x"), "p.toml",
                                    changed, prefix));
  EXPECT_NO_THROW(rethrow_as_change(file_key_error("p.toml", "geometry.diameter_mm", "x"), "p.toml",
                                    changed, prefix));
}

TEST(InputErrorTest, InFileAddsTheDocumentToAKeysErrorAndKeepsItsParts) {
  ConfigReader in("", "scenario.toml");
  try {
    in_file(in, [] {
      require_value(false, "reflex.mode", "\"follow\" or \"latch\"", 1.0);
      return 0;
    });
    FAIL() << "no throw";
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(), "scenario.toml: reflex.mode must be \"follow\" or \"latch\", got 1");
    EXPECT_EQ(e.parts().file, "scenario.toml");
    EXPECT_EQ(e.parts().key, "reflex.mode");
  }
}

}  // namespace
}  // namespace pamsim
