// recording_csv_test.cc: a lab's recording as `pamsim identify` reads it: any
// sampling rate, empty cells as gaps, comments; and every malformed file refused in one line
// naming the file (and the line).
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "base/input_error.h"
#include "sim/cli_util.h"
#include "sim/io/recording_csv.h"

namespace pamsim {
namespace {

std::string write_recording(const std::string& name, const std::string& text) {
  const auto dir = pamsim_test::fresh_dir("recording_csv");
  const std::string path = (dir / name).string();
  pamsim_test::write_text(path, text);
  return path;
}

TEST(RecordingCsvTest, ReadsUnevenTimesGapsAndComments) {
  const Recording r = read_recording_csv(write_recording(
      "r.csv",
      "# made by hand\nangle_deg,time_s,force_meas_ago_N\n-36,0.0,10\n\n-35.5,0.013,\n"
      " -35 , 0.5 ,12.5\r\n"));
  ASSERT_EQ(r.channels, (std::vector<std::string>{"angle_deg", "force_meas_ago_N"}));
  EXPECT_EQ(r.time_s, (std::vector<double>{0.0, 0.013, 0.5}));
  EXPECT_EQ(r.samples[0], (std::vector<double>{-36, -35.5, -35}));
  EXPECT_EQ(r.samples[1][0], 10.0);
  EXPECT_TRUE(std::isnan(r.samples[1][1])) << "an empty cell is a gap";
  EXPECT_EQ(r.sample_count(1), 2u);
  EXPECT_EQ(r.channel("force_meas_ago_N"), 1u);
  EXPECT_EQ(r.channel("nothing"), 2u);
}

TEST(RecordingCsvTest, MalformedFilesAreOneLineNamingFileAndLine) {
  for (const auto& [text, says] : std::vector<std::pair<std::string, std::string>>{
           {"angle_deg\n1\n2\n", "no time_s column"},
           {"time_s,angle_deg,angle_deg\n0,1,1\n1,2,2\n", "angle_deg is named twice"},
           {"time_s\n0\n1\n", "no channel besides time_s"},
           {"time_s,,x\n0,1,1\n", "column 2 has no name"},
           {"time_s,angle_deg\n0,1\n1,2,3\n", "line 3: 3 cells, the header has 2"},
           {"time_s,angle_deg\n0,1\n1,nan\n",
            "line 3: angle_deg must be a finite number or empty, got \"nan\""},
           {"time_s,angle_deg\n0,1\n1,fast\n", "angle_deg must be a finite number or empty"},
           {"time_s,angle_deg\n0,1\n0,2\n", "line 3: time_s must increase strictly"},
           {"time_s,angle_deg\n0.5,1\n0.2,2\n", "time_s must increase strictly"},
           {"time_s,angle_deg\n-1,1\n0,2\n", "time_s must be >= 0"},
           {"time_s,angle_deg\n,1\n0,2\n", "time_s must be a finite number"},
           {"time_s,angle_deg\n0,1\n", "fewer than two rows"},
           {"time_s,angle_deg\n0,\n1,\n", "angle_deg has no samples"},
           {"", "empty file"}}) {
    SCOPED_TRACE(text);
    const std::string path = write_recording("bad.csv", text);
    try {
      read_recording_csv(path);
      ADD_FAILURE() << "accepted";
    } catch (const InputError& e) {
      const std::string what = e.what();
      EXPECT_EQ(what.rfind(path + ": ", 0), 0u) << what;
      EXPECT_NE(what.find(says), std::string::npos) << what;
      EXPECT_EQ(what.find('\n'), std::string::npos) << what;
    }
  }
  EXPECT_THROW(read_recording_csv("/nonexistent/r.csv"), InputError);
}

}  // namespace
}  // namespace pamsim
