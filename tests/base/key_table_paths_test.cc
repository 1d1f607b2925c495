// key_table_paths_test.cc: a text row that is a path to a file to read (TextRow::input_file),
// by both readers (a parameter file's read_key_tables and a scenario's read_key_rows): given
// relative to the folder of the file that gives it, stored resolved, refused naming the file
// and the key when it is no file to read, and when required and left out; the reference says
// what it allows. And enum_choice_row: an enum's names as a choice key.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <toml++/toml.h>

#include "base/config_reader.h"
#include "base/enum_names.h"
#include "base/input_error.h"
#include "base/key_table.h"
#include "base/toml_file.h"

namespace pamsim {
namespace {

namespace fs = std::filesystem;

// a folder holding `sub/data.csv`, fresh for each test
fs::path folder(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("pamsim_key_table_paths_" + name);
  fs::remove_all(dir);
  fs::create_directories(dir / "sub");
  std::ofstream(dir / "sub" / "data.csv") << "t,x\n0,1\n";
  return dir;
}

void write(const fs::path& file, const std::string& text) { std::ofstream(file) << text; }

std::vector<KeyTable> data_table(std::string* data) {
  TextRow row{"data", "the data file", data};
  row.input_file = row.required = true;
  KeyTable t{"", {}, {}, {}};
  t.texts = {row};
  return {t};
}

TEST(KeyTablePathsTest, APathIsResolvedBesideItsFileByBothReaders) {
  const fs::path dir = folder("resolved");
  const std::string file = (dir / "f.toml").string();
  write(file, "data = \"sub/data.csv\"\n");
  std::string from_file, from_reader;
  read_key_tables(parse_toml_file(file), file, data_table(&from_file));
  ConfigReader in(file);
  read_key_rows(in, data_table(&from_reader).front());
  EXPECT_EQ(from_file, (dir / "sub" / "data.csv").string());
  EXPECT_EQ(from_reader, from_file);
  EXPECT_EQ(path_beside("a.toml", "b.csv"), "./b.csv");
  EXPECT_EQ(path_beside("x/a.toml", "/abs/b.csv"), "/abs/b.csv");
  EXPECT_EQ(path_beside("x/a.toml", ""), "");
}

TEST(KeyTablePathsTest, NoFileToReadAndARequiredPathLeftOutAreRefusedByTheirKey) {
  const fs::path dir = folder("refused");
  const std::string file = (dir / "f.toml").string();
  for (const char* text : {"data = \"sub/missing.csv\"\n", "data = \"sub\"\n", "data = 3\n", ""}) {
    SCOPED_TRACE(text);
    write(file, text);
    std::string data;
    for (int reader = 0; reader < 2; ++reader) {
      try {
        if (reader == 0) {
          read_key_tables(parse_toml_file(file), file, data_table(&data));
        } else {
          ConfigReader in(file);
          read_key_rows(in, data_table(&data).front());
        }
        ADD_FAILURE() << "read by reader " << reader;
      } catch (const InputError& e) {
        EXPECT_EQ(e.parts().file, file) << e.what();
        EXPECT_EQ(e.parts().key, "data") << e.what();
        EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos) << e.what();
      }
    }
  }
  std::string data;
  const std::vector<KeyDoc> docs = key_table_docs(data_table(&data));
  ASSERT_EQ(docs.size(), 1u);
  EXPECT_EQ(docs[0].fallback, "(required)");
  EXPECT_EQ(docs[0].allowed, "a path to a file, relative to the file that gives it");
}

enum class Shade { kLight, kDark };
constexpr EnumName<Shade> kShades[] = {{Shade::kLight, "light"}, {Shade::kDark, "dark"}};

TEST(KeyTablePathsTest, AnEnumsNamesAreAChoiceKey) {
  Shade shade = Shade::kLight;
  KeyTable t{"look", {}, {enum_choice_row("shade", kShades, "how dark", &shade)}};
  EXPECT_EQ(t.choices[0].allowed, (std::vector<std::string>{"light", "dark"}));
  EXPECT_EQ(t.choices[0].get(), "light");
  read_key_tables(toml::parse("[look]\nshade = \"dark\"\n"), "f.toml", {t});
  EXPECT_EQ(shade, Shade::kDark);
  EXPECT_THROW(read_key_tables(toml::parse("[look]\nshade = \"grey\"\n"), "f.toml", {t}),
               InputError);
}

}  // namespace
}  // namespace pamsim
