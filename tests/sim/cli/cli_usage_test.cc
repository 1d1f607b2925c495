// cli_usage_test.cc: command-line usage errors exit 2 like every other input error (not
// CLI11's internal 104-109) in one line, a missing or misspelled subcommand is answered with
// the commands there are and the nearest one, and thread counts are bounded.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "sim/cli_util.h"

namespace {

using pamsim_test::line_count;
using pamsim_test::run_pamsim;

TEST(CliUsageTest, UsageErrorsExitTwoInOneLineWithTheCommandsThereAre) {
  struct Case {
    std::string args, says;
  };
  for (const Case& c : std::vector<Case>{
           {"", "commands: fit, estimate, tensile"},
           {"rnu scenarios/drop_mass.toml", "unknown command 'rnu'; commands: fit"},
           {"runn scenarios/drop_mass.toml", "did you mean run?"},
           {"validate", "commands: length-estimation, reaching"},
           {"validate reachin",
            "unknown command 'reachin'; commands: length-estimation, "
            "reaching; did you mean reaching?"},
           {"run", "run needs a scenario file, or --from DIR"},
           {"sweep scenarios/sweep_smoke.toml --bogus", "--bogus"},
           {"run scenarios/drop_mass.toml --trials x", "--trials"},
           {"run scenarios/drop_mass.toml --trials 2.5", "--trials must be a whole number"},
           {"sweep scenarios/sweep_smoke.toml --threads two", "--threads must be a whole number"},
           // thread counts are bounded: 0 means all cores
           {"run scenarios/drop_mass.toml --threads 100000", "--threads must be 1 to 1024"},
           {"sweep scenarios/sweep_smoke.toml --threads 5000 --out /tmp/pamsim_no_sweep",
            "--threads must be 1 to 1024"},
           {"tune scenarios/tune_reflex.toml --threads -3", "--threads must be 1 to 1024"},
           {"validate reaching --threads 2000", "--threads must be 1 to 1024"},
           // a negative seed is refused, not wrapped to 2^64 - 1
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

// One version everywhere: pamsim --version, CITATION.cff and the newest CHANGELOG entry; and
// the licence is there.
TEST(CliUsageTest, TheVersionIsTheSameInTheProgramTheCitationAndTheChangelog) {
  const auto version = run_pamsim("--version");
  EXPECT_EQ(version.out, std::string("pamsim ") + PAMSIM_VERSION + "\n");
  const std::string source = PAMSIM_SOURCE_DIR;
  const std::string citation = pamsim_test::read_file(source + "/CITATION.cff");
  EXPECT_NE(citation.find(std::string("\nversion: ") + PAMSIM_VERSION + "\n"), std::string::npos);
  EXPECT_NE(citation.find("doi: 10.3390/act14110560"), std::string::npos);
  const std::string changelog = pamsim_test::read_file(source + "/CHANGELOG.md");
  // the newest released section (an "## Unreleased" one above it gathers what comes next)
  auto newest = changelog.find("\n## ");
  if (newest != std::string::npos && changelog.compare(newest, 14, "\n## Unreleased") == 0) {
    newest = changelog.find("\n## ", newest + 1);
  }
  ASSERT_NE(newest, std::string::npos);
  EXPECT_EQ(changelog.compare(newest + 4, std::string(PAMSIM_VERSION).size(), PAMSIM_VERSION), 0)
      << changelog.substr(newest, 40);
  EXPECT_NE(pamsim_test::read_file(source + "/LICENSE").find("MIT License"), std::string::npos);
}

// Values echoed in messages are printed as read but shortened and escaped (a NUL must not end
// the message, nor a multi-megabyte value be printed whole), and a missing file names the key
// that points at it.
TEST(CliUsageTest, MessagesEscapeAndShortenEchoedValuesAndNameTheKeyOfAMissingFile) {
  const auto dir = pamsim_test::fresh_dir("usage_echo");
  const std::string base =
      "base = \"" + std::string(PAMSIM_SOURCE_DIR) + "/scenarios/drop_mass.toml\"\n";
  pamsim_test::write_text(dir / "nul.toml", base + "design = \"ab\\u0000cd\\u001b[31m\"\n");
  const auto nul = run_pamsim("sweep " + (dir / "nul.toml").string());
  EXPECT_EQ(nul.exit_code, 2);
  EXPECT_EQ(line_count(nul.err), 1) << nul.err;
  EXPECT_NE(nul.err.find("design is \"ab\\x00cd\\x1B[31m\""), std::string::npos) << nul.err;

  pamsim_test::write_text(dir / "big.toml",
                          base + "design = \"" + std::string(3 << 20, 'x') + "\"\n");
  const auto big = run_pamsim("sweep " + (dir / "big.toml").string());
  EXPECT_EQ(big.exit_code, 2);
  EXPECT_EQ(line_count(big.err), 1);
  EXPECT_LT(big.err.size(), 800u);
  // the word of the quoted value (its quotes and the comma after it) is cut to 240 bytes at
  // each end
  EXPECT_NE(big.err.find("...(" + std::to_string((3 << 20) + 3 - 480) + " bytes)..."),
            std::string::npos)
      << big.err;

  const auto model =
      run_pamsim("run scenarios/drop_mass.toml --set model.file=\\\"/nonexistent.xml\\\" --out " +
                 (dir / "out").string());
  EXPECT_EQ(model.exit_code, 2);
  EXPECT_EQ(model.err,
            "pamsim: scenarios/drop_mass.toml: --set model.file: /nonexistent.xml: "
            "cannot open file (No such file or directory)\n");
}

}  // namespace
