// progress_test.cc: progress lines (ProgressReporter): a log gets a line per 10 % and a last
// line with the elapsed time, a terminal one bar redrawn in place, --quiet nothing.
#include "sim/cli/progress.h"

#include <gtest/gtest.h>

#include <sstream>
#include <string>

namespace pamsim {
namespace {

int lines(const std::string& s) {
  int n = 0;
  for (char c : s) n += c == '\n';
  return n;
}

TEST(ProgressTest, ALogGetsALinePerTenPercentAndQuietNothing) {
  std::ostringstream log;
  ProgressReporter p("pamsim sweep", 1000, 0, log, ProgressStyle::kLog);
  for (int done = 1; done <= 1000; ++done) p.update(done);
  p.finish(1000);
  EXPECT_EQ(lines(log.str()), 10) << log.str();
  EXPECT_NE(log.str().find("pamsim sweep: 100/1000   10.0%"), std::string::npos) << log.str();
  EXPECT_NE(log.str().find("1000/1000  100.0%"), std::string::npos) << log.str();

  std::ostringstream quiet;
  ProgressReporter q("pamsim sweep", 1000, 0, quiet, ProgressStyle::kQuiet);
  for (int done = 1; done <= 1000; ++done) q.update(done);
  q.finish(1000);
  EXPECT_EQ(quiet.str(), "");

  std::ostringstream terminal;
  ProgressReporter t("pamsim run", 5, 0, terminal, ProgressStyle::kTerminal);
  t.finish(5);
  EXPECT_EQ(terminal.str().rfind("\rpamsim run [", 0), 0u) << terminal.str();
  EXPECT_NE(terminal.str().find("elapsed"), std::string::npos) << terminal.str();
  EXPECT_EQ(lines(terminal.str()), 1);
}

}  // namespace
}  // namespace pamsim
