// cli_usage_test.cc: command-line usage errors exit 2 like every other input error (not
// CLI11's internal 104-109) in one line, a missing or misspelled subcommand is answered with
// the commands there are and the nearest one, and thread counts are bounded.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "cli_util.h"

namespace {

using pamsim_test::line_count;
using pamsim_test::run_pamsim;

TEST(CliUsageTest, UsageErrorsExitTwoInOneLineWithTheCommandsThereAre) {
  struct Case {
    std::string args, says;
  };
  for (const Case& c : std::vector<Case>{
           {"", "commands: fit, estimate, tensile"},
           {"rnu scenarios/drop_mass.toml", "did you mean run?"},
           {"validate", "commands: length-estimation, reaching"},
           {"validate reachin", "did you mean reaching?"},
           {"run", "scenario is required"},
           {"sweep scenarios/sweep_smoke.toml --bogus", "--bogus"},
           {"run scenarios/drop_mass.toml --trials x", "--trials"},
           // thread counts are bounded (issue 14 item 3): 0 means all cores
           {"run scenarios/drop_mass.toml --threads 100000", "--threads must be 1 to 1024"},
           {"sweep scenarios/sweep_smoke.toml --threads 5000 --out /tmp/pamsim_no_sweep",
            "--threads must be 1 to 1024"},
           {"tune scenarios/tune_reflex.toml --threads -3", "--threads must be 1 to 1024"},
           {"validate reaching --threads 2000", "--threads must be 1 to 1024"},
           // a negative seed is refused, not wrapped to 2^64 - 1 (issue 14 item 11)
           {"tensile --params models/pams/table4_agonist.toml --seed -1 -o /tmp/pamsim_no.csv",
            "--seed"},
           {"validate reaching --seed -5", "--seed"}}) {
    const auto r = run_pamsim(c.args);
    EXPECT_EQ(r.exit_code, 2) << c.args;
    EXPECT_EQ(line_count(r.err), 1) << c.args << ": " << r.err;
    EXPECT_NE(r.err.find(c.says), std::string::npos) << c.args << ": " << r.err;
  }
  // help and version still succeed
  EXPECT_EQ(run_pamsim("--help").exit_code, 0);
  EXPECT_EQ(run_pamsim("--version").exit_code, 0);
}

}  // namespace
