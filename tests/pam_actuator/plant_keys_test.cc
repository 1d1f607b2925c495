// plant_keys_test.cc: the plant's keys as rows (avbdl_keys.h, plant_params.h): each key has
// one row; every row refuses, from a file or a scenario's change, each value outside its
// range, NaN and a value of another type, naming the key; validate_avbdl_params names a bad
// field by the same key in the file's unit, for each row and each check that joins keys.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <string>
#include <vector>

#include <toml++/toml.h>

#include "base/input_error.h"
#include "base/key_table_test_util.h"
#include "pam_actuator/avbdl_keys.h"
#include "pam_actuator/plant_params.h"

namespace pamsim {
namespace {

const std::string kAgonistPlant =
    std::string(PAMSIM_SOURCE_DIR) + "/models/pams/plant_agonist.toml";
const std::string kChangePrefix = "muscles.agonist.plant.";

TEST(PlantKeysTest, EachKeyHasOneRowAndTheReferenceListsThemAll) {
  AvbdlParams plant;
  const std::map<std::string, int> rows = row_keys(avbdl_key_tables(&plant));
  for (const auto& [key, count] : rows) EXPECT_EQ(count, 1) << key;
  std::map<std::string, int> listed;
  for (const KeyDoc& d : plant_key_docs()) ++listed[d.key];
  for (const auto& [key, count] : listed) EXPECT_EQ(count, 1) << key;
  for (const auto& [key, count] : rows) EXPECT_EQ(listed.count(key), 1u) << key;
  for (const char* own : {"name", "source", "law", "bladder.material", "bladder.relaxation_times_s",
                          "friction.breakaway_mm"}) {
    EXPECT_EQ(listed.count(own), 1u) << own;
  }
  EXPECT_EQ(listed.size(), rows.size() + 8) << "the file's own: name, source, law, material "
                                               "and the series' four lists";
}

TEST(PlantKeysTest, EveryRowRefusesItsBadValuesAsAChangedKey) {
  AvbdlParams plant;
  for (const KeyTable& table : avbdl_key_tables(&plant)) {
    for (const NumberRow& row : table.numbers) {
      const std::string key = row_key(table, row.name);
      for (const std::string& bad : bad_number_texts(row)) {
        const toml::table changes = toml::parse(key + " = " + bad);
        const InputErrorParts parts = refusal_parts(
            [&] { load_plant_params(kAgonistPlant, changes, kChangePrefix); }, key + " = " + bad);
        EXPECT_EQ(parts.key, kChangePrefix + key) << bad;
      }
    }
  }
}

TEST(PlantKeysTest, ValidateNamesEachBadFieldByItsFileKey) {
  AvbdlParams reference;
  const std::vector<KeyTable> tables = avbdl_key_tables(&reference);
  for (std::size_t t = 0; t < tables.size(); ++t) {
    for (std::size_t r = 0; r < tables[t].numbers.size(); ++r) {
      const NumberRow& row = tables[t].numbers[r];
      std::vector<double> bad = outside(row.range);
      bad.push_back(std::nan(""));
      for (double v : bad) {
        AvbdlParams p;
        *avbdl_key_tables(&p)[t].numbers[r].target = row.si(v);  // the same row of p
        const InputErrorParts parts =
            refusal_parts([&] { validate_avbdl_params(p, "plant."); }, row.name);
        EXPECT_EQ(parts.key, "plant." + row_key(tables[t], row.name)) << v;
      }
    }
  }
}

TEST(PlantKeysTest, ChecksThatJoinKeysNameTheFileKeyInItsUnit) {
  struct Case {
    const char* key;
    void (*set)(AvbdlParams&);
    const char* problem;
  };
  const Case cases[] = {
      {"bladder.C10_MPa",
       [](AvbdlParams& p) {
         p.bladder = {-2e5, 1e5, 0.0};
       },
       "must be > -bladder.C01_MPa = -0.1 MPa (a positive initial shear modulus 2 (C10 + "
       "C01)), got -0.2"},
      {"geometry.end_length_mm", [](AvbdlParams& p) { p.end_length_m = 0.07; }, nullptr},
      {"bladder.diameter_mm", [](AvbdlParams& p) { p.bladder_diameter_m = 0.003; },
       "must be 0 (the sleeve's) or in (2 wall = 4, diameter = 20] mm, got 3"},
  };
  for (const Case& c : cases) {
    AvbdlParams p;
    c.set(p);
    const InputErrorParts parts = refusal_parts([&] { validate_avbdl_params(p, ""); }, c.key);
    EXPECT_EQ(parts.key, c.key);
    if (c.problem != nullptr) {
      EXPECT_EQ(parts.problem, c.problem);
    }
  }
  AvbdlParams p;
  p.end_length_m = 0.07;  // 2 Ld above b / sqrt 3 = 127.4 mm: in mm, as the file gives it
  const InputErrorParts parts = refusal_parts([&] { validate_avbdl_params(p, ""); }, "Ld");
  EXPECT_NE(parts.problem.find(") mm (half the fully contracted length), got 70"),
            std::string::npos)
      << parts.problem;
}

}  // namespace
}  // namespace pamsim
