// calibration_keys_test.cc: the calibration file's keys as rows (calibration_file.h): each key
// has one row and the reference lists them; the committed files read back through what
// `pamsim calibrate` writes; every row refuses each value outside its range, NaN and a value
// of another type, naming the key; a muscle's pressure without its line is an unknown key.
#include <gtest/gtest.h>

#include <filesystem>
#include <map>
#include <regex>
#include <string>

#include "base/input_error.h"
#include "base/key_table_test_util.h"
#include "sim/scenario/calibration_file.h"
#include "sim/cli_util.h"

namespace pamsim {
namespace {

namespace fs = std::filesystem;

const std::string kModels = std::string(PAMSIM_SOURCE_DIR) + "/models/";

// `text` with key's line set to `value`
std::string with_value(const std::string& text, const std::string& key, const std::string& value) {
  return std::regex_replace(text, std::regex("(^|\n)" + key + " = [^\n]*"),
                            "$1" + key + " = " + value);
}

TEST(CalibrationKeysTest, EachKeyHasOneRowAndTheReferenceListsThemAll) {
  ArmCalibration c = load_calibration(kModels + "arm_2pam_calibration.toml");
  ASSERT_EQ(c.lines.size(), 2u);
  const std::map<std::string, int> rows = row_keys(calibration_key_tables(&c));
  for (const auto& [key, count] : rows) EXPECT_EQ(count, 1) << key;
  EXPECT_EQ(rows.size(), 8u) << "four of the file's own, two for each of the two muscles";
  std::map<std::string, int> listed;
  for (const KeyDoc& d : calibration_key_docs()) ++listed[d.key];
  for (const char* key : {"start_angle_deg", "antagonist_deformation_mm", "gravity_torque_Nm",
                          "written_by", "<actuator>_line_mm", "<actuator>_pressure_MPa"}) {
    EXPECT_EQ(listed[key], 1) << key;
  }
  EXPECT_EQ(listed.size(), 6u);
}

TEST(CalibrationKeysTest, TheCommittedFilesReadBackThroughWhatCalibrateWrites) {
  const fs::path dir = pamsim_test::fresh_dir("calibration_keys_round_trip");
  for (const char* name : {"arm_2pam_calibration.toml", "arm_2pam_plant_calibration.toml",
                           "arm_2pam_table1_calibration.toml"}) {
    SCOPED_TRACE(name);
    const ArmCalibration a = load_calibration(kModels + name);
    ASSERT_EQ(a.lines.size(), 2u);
    EXPECT_EQ(a.lines[0].actuator, "agonist") << "the file's order";
    EXPECT_EQ(a.lines[1].actuator, "antagonist");
    const fs::path copy = dir / name;
    pamsim_test::write_text(copy, calibration_to_toml(a, a.written_by));
    const ArmCalibration b = load_calibration(copy.string());
    EXPECT_NEAR(b.start_angle_rad, a.start_angle_rad, 1e-11);
    EXPECT_NEAR(b.antagonist_deformation_m, a.antagonist_deformation_m, 1e-14);
    EXPECT_NEAR(b.gravity_torque_nm, a.gravity_torque_nm, 1e-9);
    EXPECT_EQ(b.written_by, a.written_by);
    ASSERT_EQ(b.lines.size(), a.lines.size());
    for (std::size_t i = 0; i < a.lines.size(); ++i) {
      EXPECT_EQ(b.lines[i].actuator, a.lines[i].actuator);
      EXPECT_NEAR(b.lines[i].line_length_m, a.lines[i].line_length_m, 1e-14);
      EXPECT_NEAR(b.lines[i].pressure_pa, a.lines[i].pressure_pa, 1e-5);
    }
  }
}

TEST(CalibrationKeysTest, EveryRowRefusesItsBadValuesByItsKey) {
  const fs::path dir = pamsim_test::fresh_dir("calibration_keys_bad");
  const std::string good = pamsim_test::read_file(kModels + "arm_2pam_calibration.toml");
  ArmCalibration c = load_calibration(kModels + "arm_2pam_calibration.toml");
  const fs::path file = dir / "c.toml";
  for (const KeyTable& table : calibration_key_tables(&c)) {
    for (const NumberRow& row : table.numbers) {
      for (const std::string& bad : bad_number_texts(row)) {
        const std::string text = with_value(good, row.name, bad);
        ASSERT_NE(text, good) << row.name << " is not in the file";
        pamsim_test::write_text(file, text);
        const InputErrorParts parts =
            refusal_parts([&] { load_calibration(file.string()); }, row.name + " = " + bad);
        EXPECT_EQ(parts.file, file.string()) << bad;
        EXPECT_EQ(parts.key, row.name) << bad;
      }
    }
  }
  // a pressure without its muscle's line, and a required key left out
  pamsim_test::write_text(file, good + "third_pressure_MPa = 0.3\n");
  EXPECT_EQ(refusal_parts([&] { load_calibration(file.string()); }, "third").key,
            "third_pressure_MPa");
  pamsim_test::write_text(
      file, std::regex_replace(good, std::regex("(^|\n)agonist_pressure_MPa = [^\n]*"), "$1"));
  EXPECT_EQ(refusal_parts([&] { load_calibration(file.string()); }, "no pressure").key,
            "agonist_pressure_MPa");
}

}  // namespace
}  // namespace pamsim
